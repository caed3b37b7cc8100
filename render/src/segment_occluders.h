// Whether a straight segment between two points inside a cell crosses any of the cell's
// triangles: the GI's visibility between a probe and a surfel (gi_layout.cpp). A small bounding
// volume hierarchy over the triangles, built once per cell; both sides of a triangle block (a
// single-sided wall is still solid for light), and the first surface hit says whether the start
// point looks at a front or a back face (a probe buried in a wall or outside its room sees the
// backs of the room's faces).
//
// Most of a room's triangles lie on its boundary planes -- a plane that has all of the cell's
// geometry on one side (the walls, floor and ceiling of a convex room, of a Doom sector's convex
// piece). A segment whose two ends both lie strictly on that side cannot cross such a plane, so
// the query skips those triangles and tests only the rest (furniture, the inner corners of an L):
// probe-to-surfel segments inside a room almost always qualify, and the boundary triangles were
// most of the work of a level's load. Same answers as testing every triangle.
//
// A cut-out triangle (glTF alphaMode MASK: foliage, fences, grates) blocks only where its coverage
// is at least its cutoff, as the camera, the shadow maps and the path tracer see it: a segment
// through an uncovered point passes.
#pragma once

#include "base_color.h"

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::render {

class SegmentOccluders {
 public:
  struct Triangle {
    glm::vec3 a, b, c;
    glm::vec3 normal;  // the front face's unit normal
    int32_t cut = -1;  // index into the cut-outs given to the constructor, or -1: solid everywhere
  };
  // Where a cut-out triangle has surface: base colour alpha x COLOR_0 alpha (per corner,
  // interpolated) x the base colour texture's alpha at the point's uv (level 0, its sampler) at
  // least the cutoff (Mesh::alpha_cutoff).
  struct CutOut {
    glm::vec2 uv_a{0.0f}, uv_b{0.0f}, uv_c{0.0f};
    float alpha_a = 1.0f, alpha_b = 1.0f, alpha_c = 1.0f;
    const TextureMips* texture = nullptr;  // must outlive the occluders; null: no texture
    TextureSampler sampler;
    float cutoff = 0.5f;
    // u, v: the barycentric weights of b and c.
    bool covered(float u, float v) const;
  };
  explicit SegmentOccluders(const std::vector<Triangle>& triangles, std::vector<CutOut> cut_outs = {});

  enum class Hit { None, Front, Back };
  // The first triangle the segment from `from` to `to` crosses strictly between its ends (ends
  // excluded by a relative margin), and which of its faces looks at `from`.
  Hit first_hit(const glm::vec3& from, const glm::vec3& to) const;
  // Whether any triangle crosses the segment strictly between its ends (stops at the first found).
  bool blocked(const glm::vec3& from, const glm::vec3& to) const;
  // Whether p lies well inside every boundary plane. The overloads below take the answer for both
  // ends, for callers that cast many segments from one point to a fixed set of ends (the result
  // is the same; only the plane tests are not repeated).
  bool inside_boundary(const glm::vec3& p) const;
  Hit first_hit(const glm::vec3& from, const glm::vec3& to, bool ends_inside_boundary) const;
  bool blocked(const glm::vec3& from, const glm::vec3& to, bool ends_inside_boundary) const;

  // Boundary planes found (tests and measurements).
  size_t boundary_plane_count() const { return planes_.size(); }

 private:
  // A median-split BVH over some of the triangles.
  class Bvh {
   public:
    explicit Bvh(std::vector<Triangle> triangles);
    // Nearest crossing in (margin, best) of from + t (to - from) where the triangle has surface
    // (`cuts`: the cut-outs its triangles' `cut` index), or null (`best` lowered to its t); with
    // `any`, the first found.
    const Triangle* cross(const glm::vec3& from, const glm::vec3& to, bool any, float& best,
                          const std::vector<CutOut>& cuts) const;

   private:
    struct Node {
      glm::vec3 min, max;
      uint32_t first = 0, count = 0;  // a leaf's triangles; count 0: children at first, first + 1
    };
    void build(uint32_t node, uint32_t begin, uint32_t end);
    std::vector<Triangle> triangles_;
    std::vector<Node> nodes_;
  };
  // xyz: unit normal towards the side where all the geometry lies, w: offset (dot(n, x) = w on it).
  struct Plane {
    glm::vec3 n;
    float d;
  };
  static std::vector<Plane> find_boundary_planes(const std::vector<Triangle>& triangles, float margin,
                                                 std::vector<int>& plane_of);
  const Triangle* cross(const glm::vec3& from, const glm::vec3& to, bool any, bool ends_inside) const;

  std::vector<Plane> planes_;
  std::vector<CutOut> cuts_;
  float margin_ = 0.0f;
  Bvh interior_, boundary_;  // the triangles off and on the boundary planes
};

}  // namespace lintel::render
