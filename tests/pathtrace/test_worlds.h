// Hand-built worlds for the path tracer's tests: each is small enough that the expected image
// follows from a formula. Only what the path tracer reads is filled in (meshes, cells, instances,
// lights); portals and volumes are not needed because portals add no geometry.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace lintel::pathtrace_test {

inline Mesh finish_mesh(Mesh m, const glm::vec3& albedo) {
  for (const glm::vec3& p : m.positions) m.bounds_mesh.extend(p);
  m.base_color = glm::vec4(albedo, 1.0f);
  // These analytic meshes are wound without regard to which side is seen (the sphere is viewed
  // from inside, the floor from above and below), and the expected values treat both sides as
  // surface: glTF's doubleSided. Single-sided culling has its own tests (render_sidedness_test).
  m.double_sided = true;
  return m;
}

// The square [-half, half]^2 of the plane y = 0.
inline Mesh floor_mesh(float half, const glm::vec3& albedo) {
  Mesh m;
  m.name = "floor";
  m.positions = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
  m.indices = {0, 2, 1, 0, 3, 2};
  return finish_mesh(m, albedo);
}

// A closed box [lo, hi] of 12 triangles sharing 8 vertices (watertight: no crack on its edges).
inline Mesh box_mesh(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& albedo) {
  Mesh m;
  m.name = "box";
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return finish_mesh(m, albedo);
}

// A closed latitude-longitude sphere about the origin (poles shared, so it is watertight).
inline Mesh sphere_mesh(float radius, uint32_t segments, uint32_t rings, const glm::vec3& albedo) {
  Mesh m;
  m.name = "sphere";
  const float pi = 3.14159265358979f;
  m.positions.push_back({0, radius, 0});
  for (uint32_t r = 1; r < rings; ++r) {
    const float theta = pi * float(r) / float(rings);
    for (uint32_t s = 0; s < segments; ++s) {
      const float phi = 2.0f * pi * float(s) / float(segments);
      m.positions.push_back(
          radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  }
  m.positions.push_back({0, -radius, 0});
  const uint32_t bottom = uint32_t(m.positions.size() - 1);
  const auto ring_vertex = [segments](uint32_t r, uint32_t s) { return 1 + (r - 1) * segments + s % segments; };
  for (uint32_t s = 0; s < segments; ++s) {
    m.indices.insert(m.indices.end(), {0, ring_vertex(1, s + 1), ring_vertex(1, s)});
    m.indices.insert(m.indices.end(), {bottom, ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1)});
    for (uint32_t r = 1; r + 1 < rings; ++r) {
      const uint32_t a = ring_vertex(r, s), b = ring_vertex(r, s + 1);
      const uint32_t c = ring_vertex(r + 1, s), d = ring_vertex(r + 1, s + 1);
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  }
  return finish_mesh(m, albedo);
}

// One cell whose shell is `shell`, placed by cell_to_world.
inline uint32_t add_cell(World& w, Mesh shell, const glm::mat4& cell_to_world = glm::mat4(1.0f)) {
  Cell c;
  c.name = "cell" + std::to_string(w.cells.size());
  c.shell_mesh = int(w.meshes.size());
  c.cell_to_world = cell_to_world;
  c.world_to_cell = glm::inverse(cell_to_world);
  w.meshes.push_back(std::move(shell));
  w.cells.push_back(std::move(c));
  return uint32_t(w.cells.size() - 1);
}

inline Light point_light(const glm::vec3& position, float intensity, float range = 0.0f) {
  Light l;
  l.name = "point";
  l.type = Light::Type::Point;
  l.intensity = intensity;
  l.range = range;
  l.position_world = position;
  return l;
}

}  // namespace lintel::pathtrace_test
