// Open-edge count: corners numbered by exact position, then undirected edges as pairs of those
// numbers, counted; both in hash tables rather than sorts, whose comparisons mispredict (a
// volume's few hundred corners stay in cache either way).
#include "read/closed_mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace lintel::scene_read {
namespace {

using Key = std::array<float, 3>;
using Edge = std::pair<Key, Key>;

Key key_of(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// Edges keyed on the positions themselves, sorted (finite positions: a NaN breaks the order).
size_t by_position(const std::vector<glm::vec3>& triangles) {
  std::vector<Edge> edges;
  edges.reserve(triangles.size());
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Key k[3] = {key_of(triangles[t]), key_of(triangles[t + 1]), key_of(triangles[t + 2])};
    if (k[0] == k[1] || k[1] == k[2] || k[0] == k[2]) continue;
    for (int e = 0; e < 3; ++e) {
      Key a = k[e], b = k[(e + 1) % 3];
      if (b < a) std::swap(a, b);
      edges.emplace_back(a, b);
    }
  }
  std::sort(edges.begin(), edges.end());
  size_t open = 0;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++open;
    i = j;
  }
  return open;
}

// For positions without a NaN, `==` is equality of the bits once -0 is made +0.
uint32_t bits_of(float v) { return std::bit_cast<uint32_t>(v + 0.0f); }

// Open-addressing slots for `n` keys, at most half full.
size_t slots_for(size_t n) { return std::bit_ceil(std::max<size_t>(16, 2 * n)); }

uint64_t mix(uint64_t h) {  // the 64-bit finalizer of MurmurHash3
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  return h ^ (h >> 33);
}

}  // namespace

size_t count_open_edges_by_position(const std::vector<glm::vec3>& triangles) { return by_position(triangles); }

size_t count_open_edges(const std::vector<glm::vec3>& triangles) {
  const size_t corners = triangles.size() / 3 * 3;
  if (corners >= UINT32_MAX) return by_position(triangles);  // corner numbers are 32 bits
  // The same count as by position, each position hashed once instead of compared once per edge
  // comparison of a sort: a corner's vertex is the first corner with its position (`==`: the bits
  // once -0 is +0; a NaN position equals none, so its corner is a vertex of its own).
  auto key = [&](size_t i) {
    return std::array<uint32_t, 3>{bits_of(triangles[i].x), bits_of(triangles[i].y), bits_of(triangles[i].z)};
  };
  const size_t vertex_mask = slots_for(corners) - 1;
  std::vector<uint32_t> first_corner(vertex_mask + 1, UINT32_MAX);
  std::vector<uint32_t> vertex(corners);
  for (size_t i = 0; i < corners; ++i) {
    if (std::isnan(triangles[i].x) || std::isnan(triangles[i].y) || std::isnan(triangles[i].z)) {
      vertex[i] = uint32_t(i);
      continue;
    }
    const std::array<uint32_t, 3> k = key(i);
    for (size_t slot = mix((uint64_t(k[0]) << 32 | k[1]) ^ mix(k[2])) & vertex_mask;; slot = (slot + 1) & vertex_mask) {
      if (first_corner[slot] == UINT32_MAX) first_corner[slot] = uint32_t(i);
      if (key(first_corner[slot]) != k) continue;
      vertex[i] = first_corner[slot];
      break;
    }
  }
  // Undirected edges between vertices, counted; an edge used once is open.
  const size_t edge_mask = slots_for(corners) - 1;
  std::vector<uint64_t> edge_key(edge_mask + 1, UINT64_MAX);  // no edge joins a vertex to itself
  std::vector<uint32_t> uses(edge_mask + 1, 0);
  for (size_t t = 0; t < corners; t += 3) {
    const uint32_t v[3] = {vertex[t], vertex[t + 1], vertex[t + 2]};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;  // degenerate
    for (int e = 0; e < 3; ++e) {
      const uint64_t edge = uint64_t(std::min(v[e], v[(e + 1) % 3])) << 32 | std::max(v[e], v[(e + 1) % 3]);
      size_t slot = mix(edge) & edge_mask;
      while (edge_key[slot] != edge && edge_key[slot] != UINT64_MAX) slot = (slot + 1) & edge_mask;
      edge_key[slot] = edge;
      ++uses[slot];
    }
  }
  return size_t(std::count(uses.begin(), uses.end(), 1u));
}

}  // namespace lintel::scene_read
