// Bounds-checked reading of glTF accessors: every element is proven to lie inside its buffer view
// and buffer before a byte is read, component types are checked against what the attribute
// allows, and float data must be finite. Faults name the accessor and what it was read for.
#pragma once

#include "read/load_context.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

// Vertex attributes (positions, normals, uvs) and indices read so far over all meshes, against
// kMaxTotalVertices/kMaxTotalIndices.
struct ReadBudget {
  size_t vertices = 0;
  size_t indices = 0;
};

// Reads a VEC3 FLOAT accessor (POSITION, NORMAL). `role` says what it is for in messages
// ("POSITION of mesh 2 'Chair' primitive 0"). Appends to `out`.
Status read_vec3_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                          ReadBudget& budget, std::vector<glm::vec3>& out);

// Reads a VEC2 FLOAT accessor (TEXCOORD_0), finite, against the same vertex budget. Appends to
// `out`.
Status read_vec2_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                          ReadBudget& budget, std::vector<glm::vec2>& out);

// Reads a COLOR_n accessor: VEC3 or VEC4 of FLOAT or of normalized UNSIGNED_BYTE/SHORT, finite,
// against the vertex budget; VEC3 gets alpha 1, values are clamped to [0, 1]. Appends to `out`.
Status read_color_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                           ReadBudget& budget, std::vector<glm::vec4>& out);

// Reads a SCALAR UNSIGNED_BYTE/SHORT/INT index accessor, each index < vertex_count. Appends
// index + base to `out`.
Status read_index_accessor(const LoadContext& ctx, const tinygltf::Model& model, int accessor, const std::string& role,
                           size_t vertex_count, uint32_t base, ReadBudget& budget, std::vector<uint32_t>& out);

}  // namespace lintel::scene_read
