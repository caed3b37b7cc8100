// Shared by the point-in-volume tests: the probe points of a cell volume, and Freedoom maps as
// Worlds (the Debian package freedoom's phase 1 WAD; tests skip when it is not installed).
#pragma once

#include <lintel/doom_import.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/world.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace lintel::testing {

inline const std::string kFreedoomWad = "/usr/share/games/doom/freedoom1.wad";

// The worlds the point-in-volume tests probe besides Freedoom: the committed cottage, grid16 and
// ring64, and a generated random scene (labelled by name). A scene that fails to load is a test
// failure and is left out.
inline std::vector<std::pair<std::string, World>> committed_and_random_worlds() {
  std::vector<std::pair<std::string, World>> out;
  for (const char* name : {"cottage", "grid16", "ring64"}) {
    const std::string path = std::string(LINTEL_SOURCE_DIR) + "/scenes/" + name + ".gltf";
    World world;
    const Status s = load_world(path, world);
    EXPECT_TRUE(s.ok()) << path << ": " << s.message();
    if (s.ok()) out.emplace_back(name, std::move(world));
  }
  World random;
  const Status s = build_world(generate_random({}), "random", random);
  EXPECT_TRUE(s.ok()) << s.message();
  if (s.ok()) out.emplace_back("random", std::move(random));
  return out;
}

// `map` of kFreedoomWad imported (default options) and built into `out`.
inline Status import_freedoom_map(const std::string& map, World& out) {
  SceneDesc scene;
  if (Status s = import_doom(kFreedoomWad, map, {}, scene); !s) return s;
  return build_world(scene, map, out);
}

// Cell-space probes of `cell`'s volume: first `random_count` points at random in its box widened
// 10 % (drawn from `rng`), then, per face while there are fewer than random_count + surface_budget
// points, a vertex, (with `edge_midpoints`) an edge midpoint, the centroid, and points a hair
// (1e-4 of the box diagonal) in front of and behind the centroid.
inline std::vector<glm::dvec3> volume_probe_points(const Cell& cell, uint32_t random_count, size_t surface_budget,
                                                   bool edge_midpoints, std::mt19937_64& rng) {
  const glm::dvec3 lo(cell.volume_box_cell.min), hi(cell.volume_box_cell.max);
  const glm::dvec3 pad = 0.1 * (hi - lo);
  std::vector<glm::dvec3> points;
  for (uint32_t k = 0; k < random_count; ++k) {
    glm::dvec3 p;
    for (int a = 0; a < 3; ++a) p[a] = std::uniform_real_distribution<double>(lo[a] - pad[a], hi[a] + pad[a])(rng);
    points.push_back(p);
  }
  const auto& t = cell.volume_triangles_cell;
  for (size_t i = 0; i + 2 < t.size() && points.size() < random_count + surface_budget; i += 3) {
    const glm::dvec3 a(t[i]), b(t[i + 1]), c(t[i + 2]);
    const glm::dvec3 centroid = (a + b + c) / 3.0;
    glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::length(n) == 0.0) continue;
    n = glm::normalize(n) * (1e-4 * glm::length(hi - lo));
    points.push_back(a);
    if (edge_midpoints) points.push_back((a + b) / 2.0);
    points.insert(points.end(), {centroid, centroid + n, centroid - n});
  }
  return points;
}

}  // namespace lintel::testing
