// Hand-built test Worlds (see test_worlds.h). Every derived field is computed here from the
// layout geometry and the cell frames, the way a loader would.
#include "test_worlds.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel::testing {
namespace {

constexpr float kPi = 3.14159265358979f;

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

float uniform(uint64_t& state, float lo, float hi) {
  return lo + (hi - lo) * float(double(splitmix64(state) >> 11) * (1.0 / 9007199254740992.0));
}

glm::vec3 transform_point(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

// A 1.2 x 0.8 x 0.8 m table (extent baked into the mesh, identity-free placement) per room,
// 0.9 m off the room centre, turned 25 degrees.
template <typename Centre>
void furnish(WorldBuilder& b, uint32_t cells, Centre centre) {
  const uint32_t mesh = b.add_box_mesh({-0.6f, 0.0f, -0.4f}, {0.6f, 0.8f, 0.4f});
  for (uint32_t c = 0; c < cells; ++c) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centre(c) + glm::vec3(0.7f, 0.0f, 0.9f));
    b.add_instance(c, mesh, glm::rotate(m, glm::radians(25.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
  }
}

}  // namespace

glm::mat4 default_layout_to_world() {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(2.3f, -0.7f, 1.9f));
  return glm::rotate(m, glm::radians(37.0f), glm::normalize(glm::vec3(0.1f, 1.0f, 0.05f)));
}

glm::mat4 layout_to_world_centred_at(const glm::vec3& layout_point) {
  const glm::mat4 m = default_layout_to_world();
  return glm::translate(glm::mat4(1.0f), -glm::vec3(m * glm::vec4(layout_point, 1.0f))) * m;
}

std::vector<glm::vec3> box_triangles(const glm::vec3& mn, const glm::vec3& mx) {
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? mx.x : mn.x, (i & 2) ? mx.y : mn.y, (i & 4) ? mx.z : mn.z};
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<glm::vec3> out;
  for (const auto& q : kQuads)
    for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(c[q[k]]);
  return out;
}

WorldBuilder::WorldBuilder(const glm::mat4& layout_to_world, const WorldOptions& options)
    : layout_to_world_(layout_to_world), options_(options), rng_(options.frame_seed) {
  world_.source = "test_worlds";
}

glm::mat4 WorldBuilder::random_frame(const glm::vec3& origin_layout) {
  glm::mat4 frame = glm::translate(layout_to_world_, origin_layout);
  if (options_.identity_frames) return frame;
  // Angles kept away from multiples of 90 degrees; non-uniform scale.
  const float angle = uniform(rng_, 11.0f, 79.0f) + 90.0f * float(splitmix64(rng_) % 4);
  const glm::vec3 axis = glm::normalize(glm::vec3(uniform(rng_, -1, 1), uniform(rng_, 0.2f, 1), uniform(rng_, -1, 1)));
  frame = glm::rotate(frame, glm::radians(angle), axis);
  return glm::scale(frame, glm::vec3(uniform(rng_, 0.6f, 1.7f), uniform(rng_, 0.6f, 1.7f), uniform(rng_, 0.6f, 1.7f)));
}

uint32_t WorldBuilder::add_cell(const std::string& name, const std::vector<glm::vec3>& triangles_layout,
                                const glm::vec3& frame_origin_layout) {
  assert(triangles_layout.size() % 3 == 0 && !triangles_layout.empty());
  Cell cell;
  cell.name = name;
  cell.node = static_cast<int>(world_.cells.size());
  cell.cell_to_world = random_frame(frame_origin_layout);
  cell.world_to_cell = glm::inverse(cell.cell_to_world);
  const glm::mat4 layout_to_cell = cell.world_to_cell * layout_to_world_;
  for (const glm::vec3& p : triangles_layout) {
    cell.volume_triangles_cell.push_back(transform_point(layout_to_cell, p));
    cell.volume_box_cell.extend(cell.volume_triangles_cell.back());
  }
  world_.cells.push_back(std::move(cell));
  return static_cast<uint32_t>(world_.cells.size() - 1);
}

uint32_t WorldBuilder::add_box_cell(const std::string& name, const glm::vec3& min_layout, const glm::vec3& max_layout) {
  return add_cell(name, box_triangles(min_layout, max_layout), 0.5f * (min_layout + max_layout));
}

uint32_t WorldBuilder::add_portal(uint32_t from, uint32_t to, const std::vector<glm::vec3>& polygon_layout,
                                  const glm::vec3& from_side_layout, bool two_way) {
  assert(polygon_layout.size() >= 3 && from < world_.cells.size() && to < world_.cells.size());
  Portal portal;
  portal.name = "portal_" + world_.cells[from].name + "_" + world_.cells[to].name;
  portal.node = static_cast<int>(world_.portals.size());
  portal.from = from;
  portal.to = to;
  portal.two_way = two_way && !options_.one_way;
  std::vector<glm::vec3> poly;
  for (const glm::vec3& p : polygon_layout) poly.push_back(transform_point(layout_to_world_, p));
  // Newell normal of the given order, then orient from -> to and make the stored winding agree
  // (right-hand rule gives normal_world) unless the test asks for the opposite winding.
  glm::dvec3 newell(0.0);
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    newell += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  glm::dvec3 centroid(0.0);
  for (const glm::vec3& p : poly) centroid += glm::dvec3(p);
  centroid /= double(poly.size());
  glm::dvec3 normal = glm::normalize(newell);
  const glm::dvec3 from_side(transform_point(layout_to_world_, from_side_layout));
  const bool toward_from = glm::dot(normal, from_side - centroid) > 0.0;
  if (toward_from) normal = -normal;
  const bool winding_matches_normal = !toward_from;
  if (winding_matches_normal == options_.reverse_portal_winding) std::reverse(poly.begin(), poly.end());
  portal.polygon_world = poly;
  portal.normal_world = glm::vec3(normal);
  portal.plane_d_world = float(glm::dot(normal, centroid));
  portal.centroid_world = glm::vec3(centroid);
  for (const glm::vec3& p : poly) {
    portal.polygon_from_cell.push_back(transform_point(world_.cells[from].world_to_cell, p));
    portal.polygon_to_cell.push_back(transform_point(world_.cells[to].world_to_cell, p));
  }
  world_.portals.push_back(std::move(portal));
  return static_cast<uint32_t>(world_.portals.size() - 1);
}

uint32_t WorldBuilder::add_box_mesh(const glm::vec3& min_mesh, const glm::vec3& max_mesh) {
  Mesh mesh;
  mesh.name = "box_" + std::to_string(world_.meshes.size());
  mesh.gltf_index = static_cast<int>(world_.meshes.size());
  const std::vector<glm::vec3> tris = box_triangles(min_mesh, max_mesh);
  for (size_t i = 0; i < tris.size(); ++i) {
    mesh.positions.push_back(tris[i]);
    mesh.indices.push_back(static_cast<uint32_t>(i));
    mesh.bounds_mesh.extend(tris[i]);
  }
  for (size_t i = 0; i < tris.size(); i += 3) {
    const glm::vec3 n = glm::normalize(glm::cross(tris[i + 1] - tris[i], tris[i + 2] - tris[i]));
    for (int k = 0; k < 3; ++k) mesh.normals.push_back(n);
  }
  world_.meshes.push_back(std::move(mesh));
  return static_cast<uint32_t>(world_.meshes.size() - 1);
}

uint32_t WorldBuilder::add_instance(uint32_t cell, uint32_t mesh, const glm::mat4& mesh_to_layout) {
  Instance inst;
  inst.name = "instance_" + std::to_string(world_.instances.size());
  inst.node = static_cast<int>(1000 + world_.instances.size());
  inst.cell = cell;
  inst.mesh = mesh;
  inst.mesh_to_world = layout_to_world_ * mesh_to_layout;
  inst.bounds_world = transform_aabb(inst.mesh_to_world, world_.meshes[mesh].bounds_mesh);
  world_.instances.push_back(std::move(inst));
  return static_cast<uint32_t>(world_.instances.size() - 1);
}

World WorldBuilder::finish() {
  World world = world_;
  world.groups.clear();
  for (uint32_t m = 0; m < world.meshes.size(); ++m) world.groups.push_back({m, {}});
  for (Instance& inst : world.instances) inst.group = inst.mesh;
  const Status derived = finalize_world(world);  // links, lists, bounds, revision
  assert(derived.ok());
  (void)derived;
  return world;
}

glm::vec3 WorldBuilder::to_world(const glm::vec3& p_layout) const {
  return transform_point(layout_to_world_, p_layout);
}

glm::vec3 TestWorld::to_world(const glm::vec3& p_layout) const { return transform_point(layout_to_world, p_layout); }
glm::vec3 TestWorld::dir_to_world(const glm::vec3& d_layout) const { return glm::mat3(layout_to_world) * d_layout; }

View TestWorld::view(const glm::vec3& eye_layout, const glm::vec3& target_layout, float fov_y_deg) const {
  View v;
  v.eye_world = to_world(eye_layout);
  v.target_world = to_world(target_layout);
  v.up_world = dir_to_world({0.0f, 1.0f, 0.0f});
  v.fov_y_deg = fov_y_deg;
  return v;
}

TestWorld make_chain(uint32_t rooms, const WorldOptions& options) {
  WorldBuilder b(options.layout_to_world, options);
  for (uint32_t i = 0; i < rooms; ++i)
    b.add_box_cell("room" + std::to_string(i), {4.0f * i, 0.0f, -2.0f}, {4.0f * i + 4.0f, 3.0f, 2.0f});
  for (uint32_t i = 0; i + 1 < rooms; ++i) {
    const float x = 4.0f * (i + 1), hw = options.door_half_width;
    b.add_portal(i, i + 1, {{x, 0.0f, -hw}, {x, 0.0f, hw}, {x, 2.2f, hw}, {x, 2.2f, -hw}}, {x - 1.0f, 1.0f, 0.0f},
                 true);
  }
  if (options.furnish) furnish(b, rooms, [](uint32_t i) { return glm::vec3(4.0f * i + 2.0f, 0.0f, 0.0f); });
  return {b.finish(), b.layout_to_world()};
}

TestWorld make_grid(uint32_t w, uint32_t h, const WorldOptions& options) {
  WorldBuilder b(options.layout_to_world, options);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
      b.add_box_cell("room" + std::to_string(i) + "_" + std::to_string(j), {4.0f * i, 0.0f, 4.0f * j},
                     {4.0f * i + 4.0f, 3.0f, 4.0f * j + 4.0f});
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const uint32_t c = j * w + i;
      const float cx = 4.0f * i + 2.0f, cz = 4.0f * j + 2.0f, hw = options.door_half_width;
      if (i + 1 < w) {
        const float x = 4.0f * (i + 1);
        b.add_portal(c, c + 1, {{x, 0, cz - hw}, {x, 0, cz + hw}, {x, 2.2f, cz + hw}, {x, 2.2f, cz - hw}}, {cx, 1, cz},
                     true);
      }
      if (j + 1 < h) {
        const float z = 4.0f * (j + 1);
        b.add_portal(c, c + w, {{cx - hw, 0, z}, {cx + hw, 0, z}, {cx + hw, 2.2f, z}, {cx - hw, 2.2f, z}}, {cx, 1, cz},
                     true);
      }
    }
  if (options.furnish)
    furnish(b, w * h, [w](uint32_t c) { return glm::vec3(4.0f * (c % w) + 2.0f, 0.0f, 4.0f * (c / w) + 2.0f); });
  return {b.finish(), b.layout_to_world()};
}

float ring_inner_radius(uint32_t n) { return std::max(3.0f, 4.0f * float(n) / (2.0f * kPi)); }

TestWorld make_ring(uint32_t n, const WorldOptions& options) {
  assert(n >= 2);
  WorldBuilder b(options.layout_to_world, options);
  const float r0 = ring_inner_radius(n), r1 = r0 + 4.0f, height = 3.0f;
  const float sector = 2.0f * kPi / float(n);
  const uint32_t segments = std::max(1u, uint32_t(std::ceil(sector / glm::radians(10.0f))));
  auto at = [](float r, float a, float y) { return glm::vec3(r * std::cos(a), y, r * std::sin(a)); };
  for (uint32_t i = 0; i < n; ++i) {
    const float a0 = sector * float(i);
    std::vector<glm::vec3> tris;
    auto quad = [&](glm::vec3 p, glm::vec3 q, glm::vec3 r, glm::vec3 s) {
      for (const glm::vec3& v : {p, q, r, p, r, s}) tris.push_back(v);
    };
    for (uint32_t k = 0; k < segments; ++k) {
      const float s0 = a0 + sector * float(k) / float(segments), s1 = a0 + sector * float(k + 1) / float(segments);
      quad(at(r0, s0, 0), at(r1, s0, 0), at(r1, s1, 0), at(r0, s1, 0));                      // floor
      quad(at(r0, s0, height), at(r0, s1, height), at(r1, s1, height), at(r1, s0, height));  // ceiling
      quad(at(r1, s0, 0), at(r1, s0, height), at(r1, s1, height), at(r1, s1, 0));            // outer wall
      quad(at(r0, s0, 0), at(r0, s1, 0), at(r0, s1, height), at(r0, s0, height));            // inner wall
    }
    const float a1 = a0 + sector;
    quad(at(r0, a0, 0), at(r0, a0, height), at(r1, a0, height), at(r1, a0, 0));  // radial ends
    quad(at(r0, a1, 0), at(r1, a1, 0), at(r1, a1, height), at(r0, a1, height));
    b.add_cell("sector" + std::to_string(i), tris, at(0.5f * (r0 + r1), a0 + 0.5f * sector, 1.5f));
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t next = (i + 1) % n;
    const float a = sector * float(i + 1);
    const glm::vec3 from_side = at(0.5f * (r0 + r1), a - 0.5f * sector, 1.0f);
    b.add_portal(i, next, {at(r0 + 0.5f, a, 0), at(r0 + 3.5f, a, 0), at(r0 + 3.5f, a, 2.2f), at(r0 + 0.5f, a, 2.2f)},
                 from_side, true);
  }
  return {b.finish(), b.layout_to_world()};
}

TestWorld make_cycle_stack(uint32_t n, const WorldOptions& options) {
  assert(n >= 1);
  WorldBuilder b(options.layout_to_world, options);
  b.add_box_cell("start", {-2.0f, -2.0f, -1.0f}, {2.0f, 2.0f, 2.0f});
  // Cycle windows grow with distance (half size 0.75 |z|) so that each covers the first window's
  // view (half size 0.5 at 1 m): going round the cycle clips nothing away.
  const float side = 0.75f * float(n + 3) + 1.0f;
  for (uint32_t i = 1; i <= n; ++i) {
    // Slab between windows i and i + 1; cell 1 also owns the space past the last window.
    const float z_near = -float(i), z_far = -float(i + 1);
    std::vector<glm::vec3> tris = box_triangles({-side, -side, z_far}, {side, side, z_near});
    if (i == 1) {
      const std::vector<glm::vec3> tail = box_triangles({-side, -side, -float(n + 3)}, {side, side, -float(n + 1)});
      tris.insert(tris.end(), tail.begin(), tail.end());
    }
    b.add_cell("cycle" + std::to_string(i), tris, {0.0f, 0.0f, 0.5f * (z_near + z_far)});
  }
  auto window = [](float half, float z) {
    return std::vector<glm::vec3>{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  };
  b.add_portal(0, 1, window(0.5f, -1.0f), {0, 0, 0}, false);
  for (uint32_t i = 1; i <= n; ++i) {
    const uint32_t next = i == n ? 1 : i + 1;
    const float z = -float(i + 1);
    b.add_portal(i, next, window(0.75f * float(i + 1), z), {0, 0, z + 0.5f}, false);
  }
  return {b.finish(), b.layout_to_world()};
}

}  // namespace lintel::testing
