// The consistency checks behind the loader fuzz targets. Each returns the first breach in words,
// so that a failing case says what broke rather than only that something did.
#include "world_invariants.h"

#include <cmath>

namespace lintel::fuzz {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string check_meshes(const World& w) {
  for (size_t m = 0; m < w.meshes.size(); ++m) {
    const Mesh& mesh = w.meshes[m];
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
      return "mesh " + std::to_string(m) + " has partial or no triangles";
    if (mesh.normals.size() != mesh.positions.size())
      return "mesh " + std::to_string(m) + " normals/positions mismatch";
    for (uint32_t i : mesh.indices)
      if (i >= mesh.positions.size()) return "mesh " + std::to_string(m) + " index out of range";
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size())
      return "mesh " + std::to_string(m) + " colors/positions mismatch";
    for (const glm::vec4& c : mesh.colors)
      if (!(c.r >= 0.0f && c.r <= 1.0f && c.g >= 0.0f && c.g <= 1.0f && c.b >= 0.0f && c.b <= 1.0f && c.a >= 0.0f &&
            c.a <= 1.0f))
        return "mesh " + std::to_string(m) + " vertex colour outside [0, 1]";
    if (uint8_t(mesh.alpha_mode) > 2 || !(mesh.alpha_cutoff >= 0.0f && std::isfinite(mesh.alpha_cutoff)))
      return "mesh " + std::to_string(m) + " alpha mode outside its enum, or cutoff negative or not finite";
    if (!finite(mesh.emissive) || mesh.emissive.x < 0.0f || mesh.emissive.y < 0.0f || mesh.emissive.z < 0.0f)
      return "mesh " + std::to_string(m) + " emission negative or not finite";
    if (mesh.emissive_texture >= int(w.textures.size()) || mesh.emissive_texture < -1 ||
        (mesh.emissive_texture >= 0 && mesh.uvs.size() != mesh.positions.size()))
      return "mesh " + std::to_string(m) + " emissive texture out of range or without uvs";
    for (const glm::vec3& p : mesh.positions)
      if (!finite(p) || !mesh.bounds_mesh.contains(p)) return "mesh " + std::to_string(m) + " position outside bounds";
  }
  return {};
}

std::string check_cells(const World& w) {
  for (size_t c = 0; c < w.cells.size(); ++c) {
    const Cell& cell = w.cells[c];
    const std::string name = "cell " + std::to_string(c);
    if (cell.shell_mesh >= int(w.meshes.size())) return name + " shell_mesh out of range";
    if (cell.volume_box_cell.empty()) return name + " has an empty volume box";
    if (cell.volume_triangles_cell.size() % 3 != 0) return name + " volume is not whole triangles";
    for (const PortalLink& l : cell.links)
      if (l.portal >= w.portals.size() || l.neighbour >= w.cells.size()) return name + " link out of range";
    for (uint32_t i : cell.instances)
      if (i >= w.instances.size() || w.instances[i].cell != c) return name + " instance list is wrong";
    for (uint32_t i : cell.lights)
      if (i >= w.lights.size() || w.lights[i].cell != c) return name + " light list is wrong";
    if (w.find_cell(cell.name) != int(c)) return name + " name is not unique";
  }
  return {};
}

std::string check_portals(const World& w) {
  for (size_t p = 0; p < w.portals.size(); ++p) {
    const Portal& portal = w.portals[p];
    const std::string name = "portal " + std::to_string(p);
    if (portal.from >= w.cells.size() || portal.to >= w.cells.size() || portal.from == portal.to)
      return name + " cells are wrong";
    const size_t n = portal.polygon_world.size();
    if (n < 3 || n > kMaxPortalVertices) return name + " has " + std::to_string(n) + " vertices";
    if (portal.polygon_from_cell.size() != n || portal.polygon_to_cell.size() != n) return name + " space sizes differ";
    if (std::fabs(glm::length(portal.normal_world) - 1.0f) > 1e-3f) return name + " normal is not unit";
    for (size_t i = 0; i < n; ++i)
      if (!finite(portal.polygon_world[i]) || !finite(portal.polygon_from_cell[i]) ||
          !finite(portal.polygon_to_cell[i]))
        return name + " has a non-finite vertex";
  }
  return {};
}

std::string check_instances_and_groups(const World& w) {
  std::vector<int> seen(w.instances.size(), 0);
  for (size_t g = 0; g < w.groups.size(); ++g) {
    const DrawGroup& group = w.groups[g];
    if (group.mesh >= w.meshes.size() || group.instances.empty()) return "group " + std::to_string(g) + " is wrong";
    for (size_t k = 0; k < group.instances.size(); ++k) {
      const uint32_t i = group.instances[k];
      if (i >= w.instances.size() || w.instances[i].group != g || w.instances[i].mesh != group.mesh)
        return "group " + std::to_string(g) + " lists a wrong instance";
      if (k > 0 && group.instances[k - 1] >= i) return "group " + std::to_string(g) + " is not ascending";
      ++seen[i];
    }
  }
  for (size_t i = 0; i < w.instances.size(); ++i) {
    if (seen[i] != 1) return "instance " + std::to_string(i) + " is in " + std::to_string(seen[i]) + " groups";
    if (w.instances[i].cell >= w.cells.size()) return "instance " + std::to_string(i) + " cell out of range";
  }
  for (size_t l = 0; l < w.lights.size(); ++l)
    if (w.lights[l].cell >= w.cells.size() || std::fabs(glm::length(w.lights[l].direction_world) - 1.0f) > 1e-3f)
      return "light " + std::to_string(l) + " is wrong";
  return {};
}

std::string check_timelines(const World& w) {
  for (const Timeline& t : w.timelines) {
    if (t.keys.empty() || !(t.fps > 0.0) || !(t.fov_y_deg > 0.0 && t.fov_y_deg < 180.0))
      return "timeline '" + t.name + "' breaks its preconditions";
    for (size_t k = 1; k < t.keys.size(); ++k)
      if (!(t.keys[k].t > t.keys[k - 1].t)) return "timeline '" + t.name + "' keys do not increase";
  }
  return {};
}

}  // namespace

std::string world_invariant_violation(const World& world) {
  for (auto check : {check_meshes, check_cells, check_portals, check_instances_and_groups, check_timelines})
    if (std::string why = check(world); !why.empty()) return why;
  return {};
}

std::string error_message_violation(const std::string& message, const std::string& label) {
  if (message.empty()) return "empty error message";
  if (message.find('\n') != std::string::npos || message.find('\r') != std::string::npos)
    return "error message spans lines: " + message;
  if (message.rfind(label + ": ", 0) != 0) return "error message does not start with the label: " + message;
  if (message.size() <= label.size() + 2) return "error message has no fault: " + message;
  return {};
}

}  // namespace lintel::fuzz
