// Closedness of a cell volume mesh: a volume must bound the interior, so every edge must be
// shared by triangles (an edge used once is a hole).
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lintel::scene_read {

// Number of edges used by exactly one triangle of `triangles` (3 vertices per triangle).
// Vertices are matched by exact position, so split normals or UV seams do not open the mesh;
// degenerate triangles are ignored.
size_t count_open_edges(const std::vector<glm::vec3>& triangles);

}  // namespace lintel::scene_read
