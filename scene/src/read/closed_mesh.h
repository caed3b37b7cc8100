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

// The same count by sorting the edges' positions (finite positions only): what count_open_edges
// falls back to past 2^32 corners, and its reference in the tests.
size_t count_open_edges_by_position(const std::vector<glm::vec3>& triangles);

}  // namespace lintel::scene_read
