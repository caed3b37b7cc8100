// `lintel vis <scene> --eye X,Y,Z --target X,Y,Z`: one visibility query — the viewer cell, the
// visible cells with their clip regions, the visible instances and the traversal's counters.
#include "cli_common.h"
#include "visibility_args.h"

#include <lintel/viewer_tracker.h>

#include <cstdio>
#include <string>
#include <vector>

namespace lintel::cli {
namespace {

struct VisArgs {
  std::string scene, eye, target, up = "0,1,0", cell;
  std::vector<std::string> closed;  // portals to close (doors), on top of the file's `open` states
  bool json = false;
  VisibilityArgs vis;
  LoadOptions load;
};

int run_vis(const VisArgs& a) {
  View view;
  if (Status s = parse_vec3(a.eye, "--eye", view.eye_world); !s) return fail(s);
  if (Status s = parse_vec3(a.target, "--target", view.target_world); !s) return fail(s);
  if (Status s = parse_vec3(a.up, "--up", view.up_world); !s) return fail(s);
  view.fov_y_deg = a.vis.fov_y_deg;
  view.aspect = a.vis.aspect;
  view.near_m = a.vis.near_m;
  if (Status s = validate_view(view); !s) return fail(s);
  if (Status s = validate_options(a.vis.options); !s) return fail(s);

  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, a.json); !s) return fail(s);
  for (const std::string& name : a.closed) {
    const int portal = world.find_portal(name);
    if (portal < 0) return fail(a.scene + ": --close '" + printable(name) + "': no portal of that name");
    world.set_portal_open(uint32_t(portal), false);
  }
  uint32_t start = 0;
  const char* how = "given";
  if (!a.cell.empty()) {
    const int found = world.find_cell(a.cell);
    if (found < 0) return fail(a.scene + ": --cell '" + a.cell + "': no cell of that name");
    start = static_cast<uint32_t>(found);
  } else {
    ViewerTracker tracker;
    if (Status s = tracker.reset(world, view.eye_world); !s) return fail(s);
    start = tracker.cell();
    how = transition_reason_name(tracker.transitions().back().reason);
  }
  VisibilityBuilder builder;
  VisibleSet visible;
  if (Status s = builder.build(world, view, start, a.vis.options, visible); !s) return fail(s);

  if (a.json) {
    nlohmann::json out = visible_set_json(world, visible, /*with_regions=*/true);
    out["viewer_cell"] = world.cells[start].name;
    out["viewer_cell_found_by"] = how;
    std::printf("%s\n", out.dump(2).c_str());
    return kExitOk;
  }
  std::printf("viewer cell: %s (%s)\n", printable(world.cells[start].name).c_str(), how);
  std::printf("visible cells: %zu of %zu\n", visible.cells.size(), world.cells.size());
  for (const VisibleCell& c : visible.cells)
    std::printf("  %-16s rect [%+.3f %+.3f]..[%+.3f %+.3f]  %u polygon%s%s, via %s\n",
                printable(world.cells[c.cell].name).c_str(), c.rect_ndc.min.x, c.rect_ndc.min.y, c.rect_ndc.max.x,
                c.rect_ndc.max.y, c.polygon_count, c.polygon_count == 1 ? "" : "s",
                c.collapsed_to_rect ? " (collapsed to rect)" : "", printable(world.cells[c.reached_from].name).c_str());
  std::printf("visible instances: %zu of %zu\n", visible.instances.size(), world.instances.size());
  if (!visible.linked_cells.empty() || !visible.unresolved.empty()) {
    std::printf("linked cells: %zu (drawn with a link transform), %zu linked instances, %zu unresolved links\n",
                visible.linked_cells.size(), visible.linked_instances.size(), visible.unresolved.size());
    for (const VisibleCell& c : visible.linked_cells) {
      const ViewTransform& t = visible.transforms[c.transform];
      std::printf("  %-16s transform %u (depth %u%s, through %s) rect [%+.3f %+.3f]..[%+.3f %+.3f]\n",
                  printable(world.cells[c.cell].name).c_str(), c.transform, t.depth, t.mirrored ? ", mirrored" : "",
                  printable(world.portals[t.portal].name).c_str(), c.rect_ndc.min.x, c.rect_ndc.min.y, c.rect_ndc.max.x,
                  c.rect_ndc.max.y);
    }
  }
  const VisibilityStats& s = visible.stats;
  std::printf(
      "stats: %llu pops (bound %llu), %llu re-enqueues, %llu cap hits, %llu duplicates skipped, "
      "%llu near-plane clips, %llu doorway passes\n",
      (unsigned long long)s.pops, (unsigned long long)s.pop_bound, (unsigned long long)s.reenqueues,
      (unsigned long long)s.cap_hits, (unsigned long long)s.snapped_duplicates_skipped,
      (unsigned long long)s.near_plane_clips, (unsigned long long)s.doorway_passes);
  return kExitOk;
}

}  // namespace

void add_vis_command(CLI::App& app, Command& run) {
  auto* cmd = app.add_subcommand("vis", "Which cells and instances are visible from one camera, with clip regions");
  auto a = std::make_shared<VisArgs>();
  cmd->add_option("scene", a->scene, "Scene file (.gltf or .glb)")->required();
  add_load_options(cmd, a->load);
  cmd->add_option("--eye", a->eye, "Eye position X,Y,Z (meters, world space)")->required();
  cmd->add_option("--target", a->target, "Point looked at X,Y,Z")->required();
  cmd->add_option("--up", a->up, "Up direction X,Y,Z")->capture_default_str();
  cmd->add_option("--cell", a->cell, "Viewer cell name (default: the cell whose volume contains the eye)");
  cmd->add_flag("--json", a->json, "Print JSON (regions as NDC polygons, y up)");
  cmd->add_option("--close", a->closed, "Close this portal (a door), both directions; repeatable");
  add_visibility_options(cmd, a->vis, /*camera_shape=*/true);
  cmd->callback([&run, a] { run = [a] { return run_vis(*a); }; });
}

}  // namespace lintel::cli
