// Node fields and local transforms. Rotation quaternions are normalized (writers round them);
// only a zero quaternion, which has no rotation to recover, is an error.
#include "read/node_read.h"

#include "read/json_fields.h"
#include "read/load_limits.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

Status read_matrix(const LoadContext& ctx, const std::string& element, const json& value, glm::dmat4& out) {
  float m[16];
  if (std::string why = read_float_array(value, 16, m); !why.empty()) return ctx.fail(element, "matrix " + why);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out[c][r] = m[c * 4 + r];  // glTF matrices are column-major
  // Exporters round; a last row off by more than this is a projective matrix, not a node transform.
  if (std::fabs(out[0][3]) > 1e-6 || std::fabs(out[1][3]) > 1e-6 || std::fabs(out[2][3]) > 1e-6 ||
      std::fabs(out[3][3] - 1.0) > 1e-6)
    return ctx.fail(element, "matrix is not affine (its last row must be 0 0 0 1)");
  out[0][3] = out[1][3] = out[2][3] = 0.0;
  out[3][3] = 1.0;
  // A negative determinant (a mirror) is valid glTF: instances take it (world_assemble.cpp), cells not.
  const double det = glm::determinant(glm::dmat3(out));
  if (!(std::fabs(det) > 0.0))
    return ctx.fail(element, "matrix has determinant " + number_text(det) + " (a zero scale collapses an axis)");
  return {};
}

Status read_trs(const LoadContext& ctx, const std::string& element, const json& node, glm::dmat4& out) {
  glm::vec3 t(0.0f), s(1.0f);
  float q[4] = {0, 0, 0, 1};
  if (const json* v = member(node, "translation"))
    if (std::string why = read_vec3(*v, t); !why.empty()) return ctx.fail(element, "translation " + why);
  if (const json* v = member(node, "rotation"))
    if (std::string why = read_float_array(*v, 4, q); !why.empty()) return ctx.fail(element, "rotation " + why);
  if (const json* v = member(node, "scale"))
    if (std::string why = read_vec3(*v, s); !why.empty()) return ctx.fail(element, "scale " + why);
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(s[i]) > 0.0f))  // negative (a mirror) is valid glTF; zero collapses an axis
      return ctx.fail(element, "scale [" + number_text(s.x) + ", " + number_text(s.y) + ", " + number_text(s.z) +
                                   "] has a zero component (it collapses an axis)");
  glm::dquat rotation(q[3], q[0], q[1], q[2]);  // glTF stores x, y, z, w
  const double length = glm::length(rotation);
  if (!(length > 1e-6)) return ctx.fail(element, "rotation quaternion has zero length");
  rotation /= length;
  out = glm::translate(glm::dmat4(1.0), glm::dvec3(t)) * glm::mat4_cast(rotation) *
        glm::scale(glm::dmat4(1.0), glm::dvec3(s));
  return {};
}

Status read_light_reference(const LoadContext& ctx, const std::string& element, const json& node, size_t light_count,
                            int& out) {
  out = -1;
  const json* extensions = member(node, "extensions");
  const json* punctual = extensions ? member(*extensions, "KHR_lights_punctual") : nullptr;
  if (!punctual) return {};
  const json* light = member(*punctual, "light");
  if (!light) return ctx.fail(element, "extensions.KHR_lights_punctual has no 'light'");
  size_t index = 0;
  if (std::string why = read_index(*light, light_count, index); !why.empty())
    return ctx.fail(element, "KHR_lights_punctual light " + why);
  out = static_cast<int>(index);
  return {};
}

Status read_node(const LoadContext& ctx, const json& node, size_t index, size_t node_count, size_t mesh_count,
                 size_t light_count, NodeRecord& out) {
  if (const json* name = member(node, "name"))
    if (std::string why = read_string(*name, out.name); !why.empty())
      return ctx.fail("node " + std::to_string(index), "name " + why);
  out.element = describe("node", index, out.name);
  if (const json* mesh = member(node, "mesh")) {
    size_t m = 0;
    if (std::string why = read_index(*mesh, mesh_count, m); !why.empty()) return ctx.fail(out.element, "mesh " + why);
    out.mesh = static_cast<int>(m);
  }
  if (const json* children = member(node, "children")) {
    if (!children->is_array()) return ctx.fail(out.element, "children must be an array, got " + json_kind(*children));
    for (const json& child : *children) {
      size_t c = 0;
      if (std::string why = read_index(child, node_count, c); !why.empty())
        return ctx.fail(out.element, "child " + why);
      out.children.push_back(static_cast<uint32_t>(c));
    }
  }
  const json* matrix = member(node, "matrix");
  if (matrix && (member(node, "translation") || member(node, "rotation") || member(node, "scale")))
    return ctx.fail(out.element, "has both 'matrix' and translation/rotation/scale (glTF allows one or the other)");
  if (Status s =
          matrix ? read_matrix(ctx, out.element, *matrix, out.local) : read_trs(ctx, out.element, node, out.local);
      !s)
    return s;
  if (Status s = read_light_reference(ctx, out.element, node, light_count, out.light); !s) return s;
  return read_node_tag(ctx, out.element, node, out.tag);
}

}  // namespace

Status read_nodes(const LoadContext& ctx, const json& doc, size_t mesh_count, size_t light_count,
                  std::vector<NodeRecord>& out) {
  out.clear();
  const json* nodes = member(doc, "nodes");
  if (!nodes) return {};
  if (!nodes->is_array()) return ctx.fail("nodes", "must be an array, got " + json_kind(*nodes));
  if (nodes->size() > kMaxNodes)
    return ctx.fail("nodes", std::to_string(nodes->size()) + " nodes, over the limit of " + std::to_string(kMaxNodes));
  out.resize(nodes->size());
  for (size_t i = 0; i < nodes->size(); ++i) {
    const json& node = (*nodes)[i];
    if (!node.is_object()) return ctx.fail("node " + std::to_string(i), "must be an object, got " + json_kind(node));
    if (Status s = read_node(ctx, node, i, nodes->size(), mesh_count, light_count, out[i]); !s) return s;
  }
  return {};
}

Status read_scene_choice(const LoadContext& ctx, const json& doc, size_t node_count, SceneChoice& out) {
  out = {};
  const json* scenes = member(doc, "scenes");
  if (!scenes) return {};
  if (!scenes->is_array()) return ctx.fail("scenes", "must be an array, got " + json_kind(*scenes));
  if (scenes->empty()) return {};
  size_t chosen = 0;
  if (const json* scene = member(doc, "scene"))
    if (std::string why = read_index(*scene, scenes->size(), chosen); !why.empty())
      return ctx.fail("scene", "the default scene " + why);
  out.scene = &(*scenes)[chosen];
  std::string name;
  if (const json* n = member(*out.scene, "name")) read_string(*n, name);  // a bad name only loses the label
  out.element = describe("scene", chosen, name);
  if (!out.scene->is_object()) return ctx.fail(out.element, "must be an object, got " + json_kind(*out.scene));
  if (const json* roots = member(*out.scene, "nodes")) {
    if (!roots->is_array()) return ctx.fail(out.element, "nodes must be an array, got " + json_kind(*roots));
    for (const json& root : *roots) {
      size_t r = 0;
      if (std::string why = read_index(root, node_count, r); !why.empty())
        return ctx.fail(out.element, "root node " + why);
      out.roots.push_back(static_cast<uint32_t>(r));
    }
  }
  return {};
}

}  // namespace lintel::scene_read
