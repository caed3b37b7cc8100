// Area-weighted vertex normals for meshes whose file gives no NORMAL attribute.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lintel::scene_read {

// Sets normals[first .. first + count) from the triangles in `indices` that use those vertices:
// each vertex gets the normalized sum of its triangles' unnormalized cross products (so larger
// triangles weigh more, and slivers cannot tip the result). A vertex on no triangle of non-zero
// area gets +Y. `normals` must already have positions.size() entries.
void compute_vertex_normals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                            size_t first_index, size_t first, size_t count, std::vector<glm::vec3>& normals);

}  // namespace lintel::scene_read
