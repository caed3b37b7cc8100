// A conservative CPU depth buffer and its max pyramid: the occlusion half of the accuracy
// benchmark's `portal+hiz` method (docs/accuracy.md, "portal+hiz"). Learned from Greene, Kass and
// Miller, "Hierarchical Z-buffer visibility" (SIGGRAPH 1993), and from niagara's two-phase
// occlusion culling (Kapoulkine); the coverage rule is Lintel's own, so that the ground truth's
// rays can never see what the pyramid rejects.
//
// The buffer covers NDC [-1, 1]^2 with size x size texels. A texel holds an upper bound of the view
// depth of the nearest occluder surface over its WHOLE closed footprint (widened by a margin for
// float error), or +infinity when the occluders do not provably cover all of it:
// * Coverage, per occluder mesh: the footprint contains no projected *contour* segment of the
//   mesh and its centre lies inside one of the mesh's projected triangles. Contour segments are
//   every edge that does not have exactly two triangles projecting to opposite sides of it
//   (boundary, silhouette, non-manifold and degenerate edges, edges of triangles cut by the near
//   plane) plus the near-plane cuts. The projected mesh is a union of triangles whose boundary
//   lies on those segments, so a connected footprint that meets none of them and has one point
//   inside lies wholly inside. Edges are matched by position (float world vertices compared
//   exactly), so faces that meet at a corner with different normals still share their edge.
// * Depth, per mesh: the largest, over the triangles touching the footprint, of that triangle's
//   deepest point over the footprint (its plane at the footprint's shallowest corner direction,
//   or its deepest vertex where the plane turns away). Every point of the footprint is covered by
//   one of those triangles, so the nearest surface there is no deeper. Meshes combine by min.
// * Union of meshes: a footprint that no mesh's contour meets and whose centre some mesh covers
//   takes the largest depth of every triangle touching it, of any mesh. Contours a mesh shares
//   with another only up to float error — a shell's rim at a portal whose other side's shell is
//   drawn too — are left out of the union's contours: the two reveals meet there within the
//   ground truth's rim radius, whose rays are not judged (ray_ground_truth.h); the union's bound
//   is raised by `rim_pad_m` for rays that stop just before the rim.
// A box is occluded when its nearest corner lies deeper than every level-0 texel that its screen
// outline (the convex hull of its projected corners, widened by the margin) touches: the test
// starts at the finest pyramid level where its rect spans at most 4 x 4 texels (niagara's 2 x 2,
// widened) and descends only into texels that are not already in front of the box (Greene et
// al.'s hierarchical test). Triangles are occluders wherever they are: no assumption about cells,
// portals or which object an occluder belongs to.
#pragma once

#include <lintel/aabb.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

// One mesh as an occluder: world-space vertices computed exactly as the ground truth's Embree
// meshes are (float mesh_to_world times the float vertex), triangles, and edges matched by
// position. Built once per World.
struct OccluderMesh {
  static constexpr uint32_t kNone = 0xffffffffu;
  struct Edge {
    uint32_t a = 0, b = 0;                  // vertex indices (ends of the edge)
    uint32_t tri[2] = {kNone, kNone};       // the two triangles sharing it; tri[1] == kNone: a contour edge always
    uint32_t opposite[2] = {kNone, kNone};  // each triangle's vertex off the edge
  };
  std::vector<glm::vec3> positions_world;  // welded: one per distinct float position
  std::vector<uint32_t> indices;           // 3 per triangle, into positions_world
  std::vector<Edge> edges;                 // every distinct edge once
  // Per edge: the portal whose rim holds it (a boundary edge of a shell within half the ground
  // truth's rim radius of a portal edge; mark_portal_rims), else kNone.
  std::vector<uint32_t> rim_portal;
  Aabb bounds_world;  // of positions_world (the triangles' own bounds)
};

// Precondition: indices index mesh.positions. Triangles with two equal corners are dropped.
OccluderMesh make_occluder_mesh(const Mesh& mesh, const glm::mat4& mesh_to_world);

// Fills mesh.rim_portal for the shell of `cell`: boundary edges whose ends both lie inside the box
// of half-width rim_radius_m[p] / 2 around an edge of a plain (not linked) portal p of that cell.
void mark_portal_rims(const World& world, uint32_t cell, const std::vector<double>& rim_radius_m, OccluderMesh& mesh);

class OcclusionBuffer {
 public:
  // Starts a frame for `view` (validate_view must hold) at size x size texels, size a power of two
  // in [1, 4096]: every texel +infinity. Allocates only when the size grows.
  // rim_pad_m: added to the union's bound (see above), the largest rim radius in the world.
  void begin(const View& view, uint32_t size, double rim_pad_m = 0.0);
  // Draws one occluder (see the header comment). Any mesh, any number of times. sealed_portals
  // (one per World portal, or empty): 1 where both cells' shells are drawn this frame, so that
  // this mesh's rim edges on that portal are no contour of the union.
  void add_mesh(const OccluderMesh& mesh, std::span<const uint8_t> sealed_portals = {});
  // Builds the max pyramid over the drawn texels; box_occluded() reads it.
  void build_pyramid();
  // Whether no ray of the view (NDC inside [-1, 1]^2, starting at the near plane) can reach
  // `box_world` before an occluder drawn this frame. False for empty boxes, boxes reaching the
  // near plane, boxes off screen and boxes whose outline touches an uncovered level-0 texel.
  bool box_occluded(const Aabb& box_world) const;

  uint32_t size() const { return size_; }
  // Level 0 texel (x right, y up from the bottom row); +infinity when not covered.
  float depth(uint32_t x, uint32_t y) const { return levels_[0][size_t(y) * size_ + x]; }
  // Counters of the last frame, for tests and the benchmark's notes.
  uint64_t triangles_drawn() const { return triangles_drawn_; }
  uint64_t covered_texels() const;

 private:
  struct Projected {
    glm::dvec3 v;  // view space: x right, y up, z = depth along the view direction
    glm::dvec2 ndc;
    bool in_front;  // depth >= the clip depth
  };
  void mark_contour(const glm::dvec3& a, const glm::dvec3& b, uint8_t bit);
  void mark_segment_ndc(const glm::dvec2& a, const glm::dvec2& b, double margin, uint8_t bit);
  void draw_polygon(const glm::dvec3* v, int count);
  void touch_rect(int x0, int y0, int x1, int y1);
  double margin_at(double depth) const;

  // Camera (double, the ground truth's basis) and clip depth.
  glm::dvec3 eye_{0.0}, forward_{0.0}, right_{0.0}, up_{0.0};
  double tx_ = 1.0, ty_ = 1.0, clip_depth_ = 0.05, scale_m_ = 1.0;
  uint32_t size_ = 0;
  double texel_ = 2.0;
  std::vector<std::vector<float>> levels_;  // [0] = size^2 ... [last] = 1
  // Per-mesh scratch over the mesh's touched texel rect.
  std::vector<float> mesh_depth_;
  std::vector<uint8_t> mesh_flags_;   // bit 0: centre covered, bit 1: contour, bit 2: sealed rim
  std::vector<float> union_depth_;    // per texel: deepest touching triangle of any mesh
  std::vector<uint8_t> union_flags_;  // bit 0: centre covered by some mesh, bit 1: a contour of some mesh
  double rim_pad_m_ = 0.0;
  int rx0_ = 0, ry0_ = 0, rx1_ = -1, ry1_ = -1;
  std::vector<Projected> projected_;
  std::vector<uint8_t> tri_ok_;  // per triangle of the mesh being drawn: wholly in front, not edge-on
  uint64_t triangles_drawn_ = 0;
};

}  // namespace lintel
