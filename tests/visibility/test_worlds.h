// Hand-built Worlds for the visibility tests: box rooms in chains and grids, annular rings, and a
// cyclic stack of portals. Every World field is filled consistently, and every cell has a
// NON-IDENTITY frame (rotations that are not multiples of 90 degrees, non-uniform scales), because
// the drift bug in the lessons hid behind identity transforms. Geometry is written in a "layout"
// space (meters, +Y up); layout_to_world places it in the world with a rotation and translation.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::testing {

// Layout -> world: a rotation of 37 degrees about a tilted axis plus a translation.
glm::mat4 default_layout_to_world();

struct WorldOptions {
  glm::mat4 layout_to_world = default_layout_to_world();
  uint64_t frame_seed = 1;              // pseudo-random cell frames
  bool identity_frames = false;         // cell_to_world = layout_to_world (still not the identity)
  bool reverse_portal_winding = false;  // store portal polygons clockwise around normal_world
  bool one_way = false;                 // portals are one-way (from -> to only)
  float door_half_width = 0.6f;         // chains and grids: doors are 2 x this wide (at most 1.9 m)
  bool furnish = false;                 // chains and grids: a table instance in every room
};

// default_layout_to_world() followed by a shift that puts `layout_point` at the world origin:
// float world coordinates then resolve offsets of 1e-7 m around that point.
glm::mat4 layout_to_world_centred_at(const glm::vec3& layout_point);

class WorldBuilder {
 public:
  WorldBuilder(const glm::mat4& layout_to_world, const WorldOptions& options);

  // A cell whose volume is a closed triangle mesh (layout space, 3 vertices per triangle), with its
  // frame origin at `frame_origin_layout`.
  uint32_t add_cell(const std::string& name, const std::vector<glm::vec3>& triangles_layout,
                    const glm::vec3& frame_origin_layout);
  uint32_t add_box_cell(const std::string& name, const glm::vec3& min_layout, const glm::vec3& max_layout);
  // A portal: convex planar polygon in layout space (any winding), normal oriented away from
  // `from_side_layout` (a point on the `from` side).
  uint32_t add_portal(uint32_t from, uint32_t to, const std::vector<glm::vec3>& polygon_layout,
                      const glm::vec3& from_side_layout, bool two_way);
  // A box mesh whose real extent is [min_mesh, max_mesh] (not a unit box).
  uint32_t add_box_mesh(const glm::vec3& min_mesh, const glm::vec3& max_mesh);
  uint32_t add_instance(uint32_t cell, uint32_t mesh, const glm::mat4& mesh_to_layout);

  World finish();

  glm::vec3 to_world(const glm::vec3& p_layout) const;
  const glm::mat4& layout_to_world() const { return layout_to_world_; }
  const WorldOptions& options() const { return options_; }

 private:
  glm::mat4 random_frame(const glm::vec3& origin_layout);

  glm::mat4 layout_to_world_;
  WorldOptions options_;
  uint64_t rng_;
  World world_;
};

struct TestWorld {
  World world;
  glm::mat4 layout_to_world{1.0f};
  glm::vec3 to_world(const glm::vec3& p_layout) const;
  glm::vec3 dir_to_world(const glm::vec3& d_layout) const;
  // A view from eye to target given in layout space, up = layout +Y.
  View view(const glm::vec3& eye_layout, const glm::vec3& target_layout, float fov_y_deg = 70.0f) const;
};

// Rooms 4 x 3 x 4 m along layout +X: room i spans x in [4i, 4i + 4], y in [0, 3], z in [-2, 2];
// the door between i and i + 1 is the rect x = 4(i + 1), y in [0, 2.2], z in [-0.6, 0.6].
TestWorld make_chain(uint32_t rooms, const WorldOptions& options = {});

// w x h rooms of 4 x 3 x 4 m: room (i, j) = cell j * w + i spans x in [4i, 4i + 4], z in [4j, 4j + 4];
// doors 1.2 m wide, 2.2 m high in the middle of each shared wall.
TestWorld make_grid(uint32_t w, uint32_t h, const WorldOptions& options = {});

// n >= 2 annular sectors around the layout Y axis, inner radius ring_inner_radius(n), 4 m deep,
// 3 m high; cell i spans angles [i, i + 1) * 2 pi / n; the door between i and i + 1 (mod n) lies in
// the radial plane at angle (i + 1) * 2 pi / n, radii inner + [0.5, 3.5], y in [0, 2.2].
TestWorld make_ring(uint32_t n, const WorldOptions& options = {});
float ring_inner_radius(uint32_t n);

// The drift ring: cell 0 ("start", around the layout origin) looks down -Z through a 1 x 1 m
// window at z = -1 into cell 1; cells 1..n form a cycle 1 -> 2 -> ... -> n -> 1 through large
// one-way windows (half size 0.75 |z|) at z = -2, -3, ..., -(n + 1), all facing the eye and
// covering the first window on screen, so the flood can go round the cycle for ever unless dedup
// recognises what it has seen.
// (Cell 1 is U-shaped: it holds the space right after the first window and after the last.)
TestWorld make_cycle_stack(uint32_t n, const WorldOptions& options = {});

// Triangles of an axis-aligned box (outward winding).
std::vector<glm::vec3> box_triangles(const glm::vec3& min, const glm::vec3& max);

}  // namespace lintel::testing
