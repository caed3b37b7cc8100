// KHR_lights_punctual lights on nodes below cells: type, colour, intensity, range and cone
// angles checked against the extension's rules; position and direction (the node's -Z) in world.
#include "read/world_assemble.h"

#include <tiny_gltf.h>

#include <cmath>

namespace lintel::scene_read {
namespace {

bool finite_float(double v) { return std::isfinite(v) && std::fabs(v) <= 3.4e38; }

Status read_light(const AssemblyState& s, size_t index, Light& out) {
  const tinygltf::Light& l = s.model.lights[index];
  const std::string element = describe("light", index, l.name);
  if (l.name.find('\0') != std::string::npos) return s.ctx.fail(element, "name contains a NUL byte (\\u0000)");
  if (l.type == "point")
    out.type = Light::Type::Point;
  else if (l.type == "spot")
    out.type = Light::Type::Spot;
  else if (l.type == "directional")
    out.type = Light::Type::Directional;
  else
    return s.ctx.fail(element, "unknown KHR_lights_punctual type '" + l.type + "'");
  if (!l.color.empty()) {
    if (l.color.size() != 3) return s.ctx.fail(element, "color must have 3 numbers");
    for (int i = 0; i < 3; ++i) {
      if (!finite_float(l.color[size_t(i)]) || l.color[size_t(i)] < 0.0)
        return s.ctx.fail(element, "color components must be finite and >= 0");
      out.color[i] = float(l.color[size_t(i)]);
    }
  }
  if (!finite_float(l.intensity) || l.intensity < 0.0) return s.ctx.fail(element, "intensity must be finite and >= 0");
  if (!finite_float(l.range) || l.range < 0.0) return s.ctx.fail(element, "range must be finite and >= 0");
  out.intensity = float(l.intensity);
  out.range = float(l.range);
  if (out.type == Light::Type::Spot) {
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2 + 1e-6))
      return s.ctx.fail(element, "spot cone angles must satisfy 0 <= inner < outer <= pi/2");
    out.inner_cone_rad = float(inner);
    out.outer_cone_rad = float(outer);
  }
  out.name = l.name;
  return {};
}

}  // namespace

Status assemble_lights(AssemblyState& s, World& world) {
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    const NodeRecord& node = s.nodes[n];
    if (!s.graph.in_scene[n] || node.light < 0) continue;
    int cell = s.cell_of_node[n];
    if (cell < 0 && s.graph.cell_ancestor[n] >= 0) cell = s.cell_of_node[size_t(s.graph.cell_ancestor[n])];
    if (cell < 0) {
      s.ctx.warn(node.element, "light outside any cell (ignored)");
      continue;
    }
    Light light;
    if (Status st = read_light(s, size_t(node.light), light); !st) return st;
    if (!node.name.empty()) light.name = node.name;  // a light may be shared; its node tells them apart
    light.node = int(n);
    light.cell = uint32_t(cell);
    const glm::dmat4& m = s.graph.world[n];
    light.position_world = glm::vec3(m[3]);
    const glm::dvec3 direction = glm::dmat3(m) * glm::dvec3(0.0, 0.0, -1.0);
    light.direction_world = glm::vec3(glm::normalize(direction));
    world.lights.push_back(std::move(light));  // Cell::lights: finalize_world()
  }
  return {};
}

}  // namespace lintel::scene_read
