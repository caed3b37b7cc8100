// `lintel cull <scene> --eye … --target … [--gpu|--cpu] [--json]`: one frame end to end — viewer
// cell, portal visibility, then the instance cull on the GPU pass (default) or by the CPU
// reference — printed per draw group as the indirect command it draws with.
#include "cli_common.h"
#include "visibility_args.h"

#include <lintel/tools/cull_query.h>

#include <cstdio>

namespace lintel::cli {
namespace {

struct CullArgs {
  std::string scene, eye, target, up = "0,1,0", device;
  bool cpu = false, gpu = false, json = false, validation = false;
  VisibilityArgs vis;
  LoadOptions load;
};

int run_cull(const CullArgs& a) {
  gpu::CullQueryOptions options;
  if (Status s = parse_vec3(a.eye, "--eye", options.view.eye_world); !s) return fail(s);
  if (Status s = parse_vec3(a.target, "--target", options.view.target_world); !s) return fail(s);
  if (Status s = parse_vec3(a.up, "--up", options.view.up_world); !s) return fail(s);
  options.view.fov_y_deg = a.vis.fov_y_deg;
  options.view.aspect = a.vis.aspect;
  options.view.near_m = a.vis.near_m;
  options.visibility = a.vis.options;
  options.use_gpu = !a.cpu;
  options.device = a.device;
  options.validation = a.validation;
  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, a.json); !s) return fail(s);
  gpu::CullQueryResult result;
  if (Status s = gpu::cull_query(world, options, result); !s) return fail(s);

  if (a.json) {
    nlohmann::json groups = nlohmann::json::array();
    for (const gpu::GroupDraw& g : result.groups)
      groups.push_back({{"group", g.group},
                        {"mesh", g.mesh_name},
                        {"command",
                         {{"indexCount", g.command.index_count},
                          {"instanceCount", g.command.instance_count},
                          {"firstIndex", g.command.first_index},
                          {"vertexOffset", g.command.vertex_offset},
                          {"firstInstance", g.command.first_instance}}},
                        {"instances", g.instances}});
    nlohmann::json cells = nlohmann::json::array();
    for (uint32_t c : result.visible_cells) cells.push_back(world.cells[c].name);
    nlohmann::json linked = nlohmann::json::array();
    for (const gpu::LinkedViewDraw& v : result.linked_views) {
      nlohmann::json view_cells = nlohmann::json::array(), instances = nlohmann::json::array();
      for (uint32_t c : v.cells) view_cells.push_back(world.cells[c].name);
      for (uint32_t i : v.instances) instances.push_back(world.instances[i].name);
      linked.push_back({{"transform", v.transform},
                        {"portal", world.portals[v.portal].name},
                        {"depth", v.depth},
                        {"mirrored", v.mirrored},
                        {"cells", view_cells},
                        {"instances", instances}});
    }
    nlohmann::json out = {{"method", result.method},
                          {"device", result.device},
                          {"viewer_cell", world.cells[result.start_cell].name},
                          {"visible_cells", cells},
                          {"visible_instances", result.visible_instances},
                          {"groups", groups},
                          {"linked_views", linked},
                          {"unresolved_links", result.unresolved_links},
                          {"stats", stats_json(result.stats)}};
    std::printf("%s\n", out.dump(2).c_str());
    return kExitOk;
  }
  std::printf("%s cull%s%s: viewer cell %s, %zu visible cells, %u of %zu instances drawn\n", result.method.c_str(),
              result.device.empty() ? "" : " on ", result.device.c_str(),
              printable(world.cells[result.start_cell].name).c_str(), result.visible_cells.size(),
              result.visible_instances, world.instances.size());
  std::printf("  %-5s %-20s %9s %9s %10s %9s %9s\n", "group", "mesh", "indices", "instances", "firstIndex", "vtxOffset",
              "firstInst");
  for (const gpu::GroupDraw& g : result.groups)
    std::printf("  %-5u %-20s %9u %9u %10u %9d %9u\n", g.group, printable(g.mesh_name).c_str(), g.command.index_count,
                g.command.instance_count, g.command.first_index, g.command.vertex_offset, g.command.first_instance);
  if (!result.linked_views.empty() || result.unresolved_links > 0)
    std::printf("through mirrors and teleports (CPU cull, drawn with the view's transform): %zu views, %u unresolved\n",
                result.linked_views.size(), result.unresolved_links);
  for (const gpu::LinkedViewDraw& v : result.linked_views)
    std::printf("  view %-3u %-8s %-20s depth %u: %zu cells, %zu instances\n", v.transform,
                v.mirrored ? "mirrored" : "", printable(world.portals[v.portal].name).c_str(), v.depth, v.cells.size(),
                v.instances.size());
  return kExitOk;
}

}  // namespace

void add_cull_command(CLI::App& app, Command& run) {
  auto* cmd = app.add_subcommand("cull", "Cull one frame's instances on the GPU (or CPU) and print the indirect draws");
  auto a = std::make_shared<CullArgs>();
  cmd->add_option("scene", a->scene, "Scene file (.gltf or .glb)")->required();
  add_load_options(cmd, a->load);
  cmd->add_option("--eye", a->eye, "Eye position X,Y,Z (meters, world space)")->required();
  cmd->add_option("--target", a->target, "Point looked at X,Y,Z")->required();
  cmd->add_option("--up", a->up, "Up direction X,Y,Z")->capture_default_str();
  auto* gpu_flag = cmd->add_flag("--gpu", a->gpu, "Cull with the Vulkan compute pass (default)");
  cmd->add_flag("--cpu", a->cpu, "Cull with the CPU reference instead")->excludes(gpu_flag);
  cmd->add_option("--device", a->device,
                  "Vulkan device: index or name substring (default: LINTEL_VK_DEVICE, then the first GPU)")
      ->envname("LINTEL_VK_DEVICE");
  cmd->add_flag("--validation", a->validation, "Run under the Khronos validation layers; any message is an error");
  cmd->add_flag("--json", a->json, "Print JSON");
  add_visibility_options(cmd, a->vis, /*camera_shape=*/true);
  cmd->callback([&run, a] { run = [a] { return run_cull(*a); }; });
}

}  // namespace lintel::cli
