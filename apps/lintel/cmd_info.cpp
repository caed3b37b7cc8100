// `lintel info <scene> [--json]`: what a scene holds — cells with their portals and volumes, draw
// groups, lights, timelines, the portal graph's cycle count — and the loader's warnings.
#include "cli_common.h"

#include <lintel/version.h>

#include <nlohmann/json.hpp>

#include <cstdio>

namespace lintel::cli {
namespace {

bool is_identity(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(m[c][r] - (c == r ? 1.0f : 0.0f)) > 1e-6f) return false;
  return true;
}

const char* light_type_name(Light::Type t) {
  switch (t) {
    case Light::Type::Point:
      return "point";
    case Light::Type::Spot:
      return "spot";
    case Light::Type::Directional:
      return "directional";
  }
  return "?";
}

nlohmann::json vec_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json box_json(const Aabb& b) { return {{"min", vec_json(b.min)}, {"max", vec_json(b.max)}}; }

nlohmann::json world_json(const World& world, const std::vector<std::string>& warnings) {
  using nlohmann::json;
  json cells = json::array();
  for (const Cell& c : world.cells) {
    json links = json::array();
    for (const PortalLink& l : c.links)
      links.push_back({{"portal", l.portal},
                       {"name", world.portals[l.portal].name},
                       {"to", world.cells[l.neighbour].name},
                       {"two_way", world.portals[l.portal].two_way}});
    json m = json::array();
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) m.push_back(c.cell_to_world[col][row]);
    cells.push_back({{"name", c.name},
                     {"node", c.node},
                     {"cell_to_world", m},
                     {"identity_transform", is_identity(c.cell_to_world)},
                     {"shell_mesh", c.shell_mesh},
                     {"volume", c.volume_triangles_cell.empty() ? "shell_bounds" : "mesh"},
                     {"volume_box_cell", box_json(c.volume_box_cell)},
                     {"portals", links},
                     {"instances", c.instances.size()},
                     {"lights", c.lights.size()}});
  }
  json portals = json::array();
  for (const Portal& p : world.portals)
    portals.push_back({{"name", p.name},
                       {"node", p.node},
                       {"from", world.cells[p.from].name},
                       {"to", world.cells[p.to].name},
                       {"two_way", p.two_way},
                       {"vertices", p.polygon_world.size()},
                       {"normal_world", vec_json(p.normal_world)},
                       {"centroid_world", vec_json(p.centroid_world)}});
  json groups = json::array();
  for (size_t g = 0; g < world.groups.size(); ++g) {
    const DrawGroup& grp = world.groups[g];
    const Mesh& mesh = world.meshes[grp.mesh];
    groups.push_back({{"group", g},
                      {"mesh", mesh.name},
                      {"mesh_index", mesh.gltf_index},
                      {"instances", grp.instances.size()},
                      {"triangles", mesh.indices.size() / 3},
                      {"bounds_mesh", box_json(mesh.bounds_mesh)}});
  }
  json lights = json::array();
  for (const Light& l : world.lights)
    lights.push_back({{"name", l.name},
                      {"type", light_type_name(l.type)},
                      {"cell", world.cells[l.cell].name},
                      {"intensity", l.intensity},
                      {"color", vec_json(l.color)},
                      {"position_world", vec_json(l.position_world)}});
  json timelines = json::array();
  for (const Timeline& t : world.timelines)
    timelines.push_back({{"name", t.name},
                         {"fps", t.fps},
                         {"fov_y_deg", t.fov_y_deg},
                         {"aspect", t.aspect},
                         {"keys", t.keys.size()},
                         {"duration_s", t.keys.back().t - t.keys.front().t}});
  return {{"file", world.source},
          {"lintel_version", LINTEL_VERSION_STRING},
          {"format_version", world.version},
          {"counts",
           {{"cells", world.cells.size()},
            {"portals", world.portals.size()},
            {"meshes", world.meshes.size()},
            {"instances", world.instances.size()},
            {"draw_groups", world.groups.size()},
            {"lights", world.lights.size()},
            {"timelines", world.timelines.size()}}},
          {"portal_graph_cycles", world.portal_graph_cycles()},
          {"cells", cells},
          {"portals", portals},
          {"draw_groups", groups},
          {"lights", lights},
          {"timelines", timelines},
          {"warnings", warnings}};
}

void print_text(const World& world, const std::vector<std::string>& warnings) {
  std::printf("%s (scene format %d)\n", printable(world.source).c_str(), world.version);
  std::printf("  %zu cells, %zu portals, %zu instances in %zu draw groups, %zu lights, %zu timelines\n",
              world.cells.size(), world.portals.size(), world.instances.size(), world.groups.size(),
              world.lights.size(), world.timelines.size());
  std::printf("  portal graph: %zu independent cycles\n", world.portal_graph_cycles());
  std::printf("\ncells:\n");
  for (const Cell& c : world.cells) {
    std::printf("  %-14s %2zu portals, %3zu instances, %zu lights, volume: %s%s\n", printable(c.name).c_str(),
                c.links.size(), c.instances.size(), c.lights.size(),
                c.volume_triangles_cell.empty() ? "shell bounds" : "mesh",
                is_identity(c.cell_to_world) ? ", identity transform" : "");
    for (const PortalLink& l : c.links) {
      const Portal& p = world.portals[l.portal];
      std::printf("      -> %-14s via %s%s\n", printable(world.cells[l.neighbour].name).c_str(),
                  printable(p.name).c_str(), p.two_way ? "" : " (one-way)");
    }
  }
  std::printf("\ndraw groups:\n");
  for (size_t g = 0; g < world.groups.size(); ++g) {
    const Mesh& mesh = world.meshes[world.groups[g].mesh];
    std::printf("  %2zu %-18s %3zu instances, %5zu triangles\n", g, printable(mesh.name).c_str(),
                world.groups[g].instances.size(), mesh.indices.size() / 3);
  }
  if (!world.lights.empty()) {
    std::printf("\nlights:\n");
    for (const Light& l : world.lights)
      std::printf("  %-14s %-11s in %s, intensity %g\n", printable(l.name).c_str(), light_type_name(l.type),
                  printable(world.cells[l.cell].name).c_str(), l.intensity);
  }
  if (!world.timelines.empty()) {
    std::printf("\ntimelines:\n");
    for (const Timeline& t : world.timelines)
      std::printf("  %-14s %zu keys, %.1f s at %g fps\n", printable(t.name).c_str(), t.keys.size(),
                  t.keys.back().t - t.keys.front().t, t.fps);
  }
  if (!warnings.empty()) {
    std::printf("\nwarnings:\n");
    for (const std::string& w : warnings) std::printf("  %s\n", printable(w).c_str());
  }
}

}  // namespace

void add_info_command(CLI::App& app, Command& run) {
  auto* cmd = app.add_subcommand("info", "Summarize a scene: cells, portals, volumes, draw groups, lights, timelines");
  auto path = std::make_shared<std::string>();
  auto json_out = std::make_shared<bool>(false);
  auto load = std::make_shared<LoadOptions>();
  cmd->add_option("scene", *path, "Scene file (.gltf or .glb)")->required();
  cmd->add_flag("--json", *json_out, "Print JSON (for programs) instead of text");
  add_load_options(cmd, *load);
  cmd->callback([&run, path, json_out, load] {
    run = [path, json_out, load] {
      World world;
      std::vector<std::string> warnings;
      if (Status s = load_scene(*path, *load, world, &warnings, /*quiet=*/true); !s) return fail(s);
      if (*json_out)
        std::printf("%s\n", world_json(world, warnings).dump(2).c_str());
      else
        print_text(world, warnings);
      return kExitOk;
    };
  });
}

}  // namespace lintel::cli
