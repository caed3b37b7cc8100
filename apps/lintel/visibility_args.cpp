// Shared visibility options and the JSON form of a VisibleSet.
#include "visibility_args.h"

#include "cli_common.h"

namespace lintel::cli {

void add_visibility_options(CLI::App* cmd, VisibilityArgs& args, bool camera_shape) {
  if (camera_shape) {
    cmd->add_option("--fov", args.fov_y_deg, "Vertical field of view in degrees")
        ->capture_default_str()
        ->check(finite_range(1e-3, 179.0));
    cmd->add_option("--aspect", args.aspect, "Width / height")->capture_default_str()->check(finite_range(1e-4, 1e4));
  }
  cmd->add_option("--near", args.near_m, "Near plane distance in meters")
      ->capture_default_str()
      ->check(finite_range(1e-6, 1e3));
  cmd->add_option("--snap", args.options.snap_lattice_cells,
                  "Snap lattice cells per NDC axis (power of two, 2..2097152)")
      ->capture_default_str();
  cmd->add_option("--cap", args.options.reprocess_cap, "Re-process cap K per cell before its region becomes a rect")
      ->capture_default_str();
  cmd->add_option("--max-polygons", args.options.max_region_polygons,
                  "Convex polygons per region before it becomes a rect")
      ->capture_default_str();
}

nlohmann::json stats_json(const VisibilityStats& s) {
  return {{"pops", s.pops},
          {"pop_bound", s.pop_bound},
          {"reenqueues", s.reenqueues},
          {"cap_hits", s.cap_hits},
          {"polygon_overflows", s.polygon_overflows},
          {"snapped_duplicates_skipped", s.snapped_duplicates_skipped},
          {"near_plane_clips", s.near_plane_clips},
          {"doorway_passes", s.doorway_passes},
          {"portals_tested", s.portals_tested},
          {"polygons_added", s.polygons_added},
          {"windows_merged", s.windows_merged},
          {"instances_tested", s.instances_tested},
          {"linked_portals_followed", s.linked_portals_followed},
          {"link_limit_hits", s.link_limit_hits}};
}

nlohmann::json visible_set_json(const World& world, const VisibleSet& visible, bool with_regions) {
  using nlohmann::json;
  json cells = json::array();
  for (const VisibleCell& c : visible.cells) {
    json entry = {{"cell", world.cells[c.cell].name},
                  {"index", c.cell},
                  {"reached_from", world.cells[c.reached_from].name},
                  {"pops", c.pops},
                  {"collapsed_to_rect", c.collapsed_to_rect},
                  {"rect_ndc", {c.rect_ndc.min.x, c.rect_ndc.min.y, c.rect_ndc.max.x, c.rect_ndc.max.y}},
                  {"polygons", c.polygon_count}};
    if (with_regions) {
      json polys = json::array();
      const ClipRegionView region = visible.region(c);
      for (size_t p = 0; p < region.polygons.size(); ++p) {
        json poly = json::array();
        for (const glm::vec2& v : region.polygon(p)) poly.push_back({v.x, v.y});
        polys.push_back(poly);
      }
      entry["region_ndc"] = polys;
    }
    cells.push_back(entry);
  }
  json instances = json::array();
  for (uint32_t i : visible.instances)
    instances.push_back(world.instances[i].name.empty() ? json(i) : json(world.instances[i].name));
  json out = {{"start_cell", world.cells[visible.start_cell].name},
              {"visible_cells", cells},
              {"visible_instances", instances},
              {"visible_instance_count", visible.instances.size()},
              {"stats", stats_json(visible.stats)}};
  if (visible.linked_cells.empty() && visible.unresolved.empty()) return out;  // worlds without links: as before
  // Cells drawn with a link transform (teleports, mirrors): docs/visibility.md, "Linked portals".
  json linked = json::array();
  for (const VisibleCell& c : visible.linked_cells) {
    const ViewTransform& t = visible.transforms[c.transform];
    json m = json::array();
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) m.push_back(t.seen_from_world[col][row]);
    linked.push_back({{"cell", world.cells[c.cell].name},
                      {"transform", c.transform},
                      {"through_portal", world.portals[t.portal].name},
                      {"link_depth", t.depth},
                      {"mirrored", t.mirrored},
                      {"seen_from_world", m},
                      {"rect_ndc", {c.rect_ndc.min.x, c.rect_ndc.min.y, c.rect_ndc.max.x, c.rect_ndc.max.y}},
                      {"polygons", c.polygon_count}});
  }
  json unresolved = json::array();
  for (const UnresolvedLink& u : visible.unresolved)
    unresolved.push_back({{"cell", world.cells[u.cell].name},
                          {"transform", u.transform},
                          {"portal", world.portals[u.portal].name},
                          {"rect_ndc", {u.rect_ndc.min.x, u.rect_ndc.min.y, u.rect_ndc.max.x, u.rect_ndc.max.y}}});
  out["linked_cells"] = linked;
  out["linked_cell_count"] = visible.linked_cells.size();
  out["linked_instance_count"] = visible.linked_instances.size();
  out["unresolved_links"] = unresolved;
  return out;
}

}  // namespace lintel::cli
