// Open-edge count by sorting undirected edges keyed on exact vertex positions.
#include "read/closed_mesh.h"

#include <algorithm>
#include <array>
#include <tuple>

namespace lintel::scene_read {
namespace {

using Key = std::array<float, 3>;
using Edge = std::pair<Key, Key>;

Key key_of(const glm::vec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

size_t count_open_edges(const std::vector<glm::vec3>& triangles) {
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
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++open;
    i = j;
  }
  return open;
}

}  // namespace lintel::scene_read
