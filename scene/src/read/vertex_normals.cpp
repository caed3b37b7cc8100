// Area-weighted vertex normals (the cross product's length is twice the triangle's area, so
// summing unnormalized cross products weights by area without computing it).
#include "read/vertex_normals.h"

#include <cmath>

namespace lintel::scene_read {

void compute_vertex_normals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                            size_t first_index, size_t first, size_t count, std::vector<glm::vec3>& normals) {
  std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
  for (size_t t = first_index; t + 2 < indices.size(); t += 3) {
    const uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
    const glm::dvec3 a(positions[i0]), b(positions[i1]), c(positions[i2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    for (uint32_t i : {i0, i1, i2})
      if (i >= first && i < first + count) sum[i - first] += n;
  }
  for (size_t v = 0; v < count; ++v) {
    const double length = glm::length(sum[v]);
    normals[first + v] = length > 0.0 && std::isfinite(length) ? glm::vec3(sum[v] / length) : glm::vec3(0, 1, 0);
  }
}

}  // namespace lintel::scene_read
