// `import doom` with convex cells (DoomImportOptions::convex_cells, `--sectors convex`) on Freedoom
// phase 1: non-convex sectors become several convex cells joined by always-open portals. Checks the
// split's geometry against the whole-sector import, the portals between the parts, the things'
// cells, the walks and the ray cast. Skipped (with the reason) when the WAD is not installed.
#include "timeline_walk.h"

#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/bench_views.h>
#include <lintel/cell_locate.h>
#include <lintel/reference/cull_method.h>
#include <lintel/doom_import.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lintel {
namespace {

const char* const kWad = "/usr/share/games/doom/freedoom1.wad";

#define REQUIRE_WAD() \
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)"

bool load_map(const std::string& map, bool convex, bool doors_open, World& world, DoomImportStats* stats = nullptr) {
  DoomImportOptions options;
  options.convex_cells = convex;
  options.doors_open = doors_open;
  SceneDesc scene;
  const Status imported = import_doom(kWad, map, options, scene, stats);
  EXPECT_TRUE(imported.ok()) << imported.message();
  if (!imported) return false;
  const Status loaded = build_world(scene, map, world);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.ok();
}

// "sector_12" and "sector_12_3" -> 12.
long sector_of(const std::string& cell_name) {
  return std::strtol(cell_name.c_str() + std::string("sector_").size(), nullptr, 10);
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// The floor of a cell seen from above (world x, -z): area of its volume's downward faces, and the
// area of the convex hull of its volume's corners.
struct Footprint {
  double area = 0.0, hull = 0.0;
};

Footprint footprint(const World& world, uint32_t c) {
  const Cell& cell = world.cells[c];
  Footprint out;
  std::vector<glm::dvec2> points;
  const auto& t = cell.volume_triangles_cell;
  for (size_t i = 0; i + 2 < t.size(); i += 3) {
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = glm::dvec3(cell.cell_to_world * glm::vec4(t[i + size_t(k)], 1.0f));
      points.emplace_back(p[k].x, -p[k].z);
    }
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (n.y < 0.0 && std::fabs(n.y) > 0.99 * glm::length(n)) out.area += 0.5 * glm::length(n);
  }
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> hull(2 * points.size() + 1);
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = 0; i + 2 < k; ++i) out.hull += 0.5 * cross2(hull[i + 1] - hull[0], hull[i + 2] - hull[0]);
  return out;
}

// Property: on every map of episode 1, each cell of a split sector is convex within the
// importer's tolerance (the hull of its floor exceeds the floor's area by at most
// DoomImportOptions::convex_hull_excess, plus float rounding), except cells whose pieces were
// kept together so that no cut runs close to a thing (fewer than one in five split cells); the
// cells of each sector cover the floor of that sector's one cell in the whole-sector import: the
// same area to within what the importer allows between a sector's exact outline and its BSP
// pieces (1 % plus 64 square map units); the split leaves no sector without a cell and no cell
// without its sector, a sector that is split really has several cells, and no thing is lost to a
// cut (the same instances as the whole-sector import). (That the pieces tile the outline exactly is
// levels_sector_partition_test's property.)
TEST(ConvexCells, SplitCellsAreConvexAndCoverTheirSector) {
  REQUIRE_WAD();
  const double unit2 = std::pow(1.0 / 32.0, 2);  // one square map unit in m^2
  for (int m = 1; m <= 9; ++m) {
    const std::string map = "E1M" + std::to_string(m);
    SCOPED_TRACE(map);
    World whole, split;
    DoomImportStats stats;
    ASSERT_TRUE(load_map(map, false, true, whole));
    ASSERT_TRUE(load_map(map, true, true, split, &stats));
    EXPECT_GT(stats.split_sectors, 0u);
    EXPECT_GT(split.cells.size(), whole.cells.size());
    EXPECT_EQ(split.instances.size(), whole.instances.size());
    std::map<long, double> whole_area, split_area;
    std::map<long, int> parts;
    size_t split_cells = 0, joined_around_things = 0;
    for (uint32_t c = 0; c < whole.cells.size(); ++c)
      whole_area[sector_of(whole.cells[c].name)] += footprint(whole, c).area;
    for (uint32_t c = 0; c < split.cells.size(); ++c) {
      const long s = sector_of(split.cells[c].name);
      const Footprint f = footprint(split, c);
      split_area[s] += f.area;
      ++parts[s];
      if (split.cells[c].name.find('_', 7) != std::string::npos) {
        ++split_cells;
        // Above the tolerance: pieces kept together so that no cut runs close to a thing (the
        // thing may stand in the next cell).
        joined_around_things += f.hull > f.area * (1.0 + DoomImportOptions{}.convex_hull_excess) + 1e-3 * unit2;
      }
    }
    EXPECT_LT(joined_around_things * 5, split_cells) << joined_around_things << " of " << split_cells;
    ASSERT_EQ(whole_area.size(), split_area.size());
    uint32_t split_sectors = 0;
    for (const auto& [s, area] : whole_area) {
      ASSERT_TRUE(split_area.count(s)) << "sector " << s;
      EXPECT_NEAR(split_area[s], area, 0.01 * area + 64.0 * unit2 + 1e-6) << "sector " << s;
      split_sectors += parts[s] > 1;
    }
    EXPECT_EQ(split_sectors, stats.split_sectors);
  }
}

// Property: every portal between two cells of one sector ("sector_N_cut_K") joins two cells of
// sector N, is two-way and open both ways, also when the map is imported with its doors closed,
// and is never closable (so `optimize` may merge across it, but no timeline event names it);
// every other portal is a whole line's ("line_N": a line lies on one cell of each side, so no line
// is cut).
TEST(ConvexCells, PortalsBetweenPartsAreOpenAndNeverClosable) {
  REQUIRE_WAD();
  for (const char* map : {"E1M1", "E1M5", "E1M9"}) {
    SCOPED_TRACE(map);
    World world;
    DoomImportStats stats;
    ASSERT_TRUE(load_map(map, true, false, world, &stats));
    // Closable as `optimize` reads it (docs/levels.md): closed either way, one-way, or named by an event.
    std::vector<bool> closable(world.portals.size(), false);
    for (uint32_t p = 0; p < world.portals.size(); ++p)
      closable[p] = !world.portals[p].two_way || !world.portals[p].open_from_to || !world.portals[p].open_to_from;
    for (const Timeline& timeline : world.timelines)
      for (const TimelineEvent& event : timeline.events)
        if (const int p = world.find_portal(event.portal); p >= 0) closable[size_t(p)] = true;
    uint32_t inner = 0, closed_lines = 0;
    for (uint32_t p = 0; p < world.portals.size(); ++p) {
      const Portal& portal = world.portals[p];
      if (portal.name.find("_cut_") != std::string::npos) {
        ++inner;
        EXPECT_EQ(sector_of(world.cells[portal.from].name), sector_of(world.cells[portal.to].name)) << portal.name;
        EXPECT_EQ(portal.name.rfind("sector_" + std::to_string(sector_of(world.cells[portal.from].name)) + "_cut_", 0),
                  0u)
            << portal.name;
        EXPECT_TRUE(portal.two_way && portal.open_from_to && portal.open_to_from) << portal.name;
        EXPECT_FALSE(closable[p]) << portal.name;
      } else {
        EXPECT_EQ(portal.name.rfind("line_", 0), 0u) << portal.name;
        EXPECT_EQ(portal.name.find_first_not_of("0123456789", 5), std::string::npos) << portal.name;
        closed_lines += !portal.open_from_to;
      }
    }
    EXPECT_EQ(inner, stats.inner_portals);
    EXPECT_GT(inner, 0u);
    EXPECT_GT(closed_lines, 0u);  // the doors are closed, the parts are not
  }
}

// Property: every thing stands in the cell it is listed in (the instance's base, a little above
// the floor, lies in that cell's volume): a thing of a split sector belongs to the part under it.
TEST(ConvexCells, ThingsBelongToThePartUnderThem) {
  REQUIRE_WAD();
  for (const char* map : {"E1M1", "E1M5"}) {
    SCOPED_TRACE(map);
    World world;
    ASSERT_TRUE(load_map(map, true, true, world));
    size_t checked = 0;
    for (const Instance& instance : world.instances) {
      const glm::vec3 base = glm::vec3(instance.mesh_to_world[3]) + glm::vec3(0.0f, 0.05f, 0.0f);
      EXPECT_TRUE(cell_volume_contains(world, instance.cell, glm::dvec3(base))) << world.cells[instance.cell].name;
      ++checked;
    }
    EXPECT_GT(checked, 10u);
  }
}

// Property: as for the whole-sector import (freedoom_levels_test), the doorway walk of every map
// of episode 1 has no flap and crosses portals, and on 120 views of each of five maps (E1M1, E1M2, E1M8,
// E3M1: false negatives of the BSP-piece split; E4M1: the loosest map whole) every cell and
// instance some ground-truth ray hits is drawn (no false negative; over-inclusion accepted).
TEST(ConvexCells, WalksWithoutFlapsAndNoFalseNegatives) {
  REQUIRE_WAD();
  for (int m = 1; m <= 9; ++m) {
    const std::string map = "E1M" + std::to_string(m);
    SCOPED_TRACE(map);
    World world;
    ASSERT_TRUE(load_map(map, true, true, world));
    test::WalkCounts walk;
    test::walk_first_timeline(world, walk);
    if (HasFatalFailure()) return;
    EXPECT_EQ(walk.flaps, 0u);
    EXPECT_GE(walk.crossings, 1u);
  }
  for (const char* map : {"E1M1", "E1M2", "E1M8", "E3M1", "E4M1"}) {
    SCOPED_TRACE(map);
    AccuracyScene scene;
    scene.label = map;
    ASSERT_TRUE(load_map(map, true, true, scene.world));
    RayGroundTruth rays;
    ASSERT_TRUE(rays.build(scene.world).ok());
    std::vector<BenchView> views = make_bench_views(scene.world, rays, 120, 1);
    for (BenchView& v : views)
      if (!cell_volume_contains(scene.world, v.start_cell, glm::dvec3(v.view.eye_world)))
        v.start_cell = locate_cell(scene.world, glm::dvec3(v.view.eye_world)).cell;
    std::vector<std::unique_ptr<CullMethod>> methods;
    methods.push_back(make_polygon_method(kDefaultSnapLatticeCells, 16));
    std::vector<MethodScore> scores;
    ASSERT_TRUE(score_scene(scene, rays, views, methods, 128, scores).ok());
    EXPECT_EQ(scores.at(0).cell_false_negatives, 0u)
        << (scores[0].false_negative_examples.empty() ? "" : scores[0].false_negative_examples[0]);
    EXPECT_EQ(scores[0].instance_false_negatives, 0u);
    EXPECT_GT(scores[0].true_cells, 0u);
  }
}

}  // namespace
}  // namespace lintel
