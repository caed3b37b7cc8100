// The builder's fast paths (per-build projection cache, skipped clip passes, the column snap)
// against its steps as first written (VisibilityBuilderTesting::use_reference_paths): the same
// VisibleSet, field for field (cells, regions' vertices, instances, linked entries, statistics),
// on generated scenes and, when the WAD is installed, on two Freedoom maps. Both builders merge a
// pop's pending polygons into clip windows (pending_merge.h) unless a case turns it off in both:
// the merge is part of what the build computes, the fast paths must not change it either way.
#include <lintel/cell_locate.h>
#include <lintel/doom_import.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include "visibility_builder_testing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace lintel {
namespace {

struct Query {
  View view;
  uint32_t start_cell = 0;
};

// The world's first timeline frame by frame (every `step`-th frame), tracked as a game would.
void add_timeline_queries(const World& world, size_t step, std::vector<Query>& out) {
  if (world.timelines.empty()) return;
  const Timeline& timeline = world.timelines[0];
  ViewerTracker tracker;
  for (size_t f = 0; f < timeline_frame_count(timeline); ++f) {
    const View view = timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    if (f % step == 0) out.push_back({view, tracker.cell()});
  }
}

// Eyes near the timeline's path (up to 1.5 m off it) looking anywhere, with fields of view and
// aspects of every kind, rooted where locate_cell puts them; and a few rooted in a random cell
// whatever the eye (the builder must agree with itself on any input, not only sensible ones).
void add_random_queries(const World& world, uint32_t seed, size_t count, std::vector<Query>& out) {
  std::vector<Query> path;
  add_timeline_queries(world, 1, path);
  ASSERT_FALSE(path.empty());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (size_t i = 0; i < count; ++i) {
    Query q = path[size_t(rng()) % path.size()];
    q.view.eye_world += glm::vec3(float(1.5 * u(rng)), float(0.5 * u(rng)), float(1.5 * u(rng)));
    glm::dvec3 dir(u(rng), 0.6 * u(rng), u(rng));
    if (glm::length(dir) < 1e-3) dir = glm::dvec3(1.0, 0.0, 0.0);
    q.view.target_world = q.view.eye_world + glm::vec3(glm::normalize(dir));
    q.view.up_world = glm::vec3(0.0f, 1.0f, 0.0f);
    q.view.fov_y_deg = float(30.0 + 45.0 * (u(rng) + 1.0));
    q.view.aspect = float(1.5 + u(rng));
    q.start_cell = i % 10 == 9 ? uint32_t(rng()) % uint32_t(world.cells.size())
                               : locate_cell(world, glm::dvec3(q.view.eye_world)).cell;
    out.push_back(q);
  }
}

// Property: for every query and every options set, the fast build and the reference build give
// equal VisibleSets (operator==: every field, every vertex, every counter). Returns how many
// builds collapsed a region (cap or polygon limit) and how many merged windows, so callers can
// check those paths ran too.
struct PathsRun {
  size_t collapsed = 0, merged = 0;
};
PathsRun expect_same_builds(const World& world, const std::vector<Query>& queries,
                            const std::vector<VisibilityOptions>& options_sets, bool merge_windows = true) {
  VisibilityBuilder fast, reference;
  VisibilityBuilderTesting::use_reference_paths(reference, true);
  VisibilityBuilderTesting::merge_pending_windows(fast, merge_windows);
  VisibilityBuilderTesting::merge_pending_windows(reference, merge_windows);
  VisibleSet a, b;
  PathsRun run;
  size_t mismatches = 0;
  for (const VisibilityOptions& options : options_sets)
    for (size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      const Status sa = fast.build(world, q.view, q.start_cell, options, a);
      const Status sb = reference.build(world, q.view, q.start_cell, options, b);
      EXPECT_EQ(sa.ok(), sb.ok());
      if (a == b) {
        run.collapsed += a.stats.cap_hits + a.stats.polygon_overflows > 0;
        run.merged += a.stats.windows_merged > 0;
        continue;
      }
      if (++mismatches <= 3)
        ADD_FAILURE() << "query " << i << " (lattice " << options.snap_lattice_cells << ", cap "
                      << options.reprocess_cap << ", polygons " << options.max_region_polygons
                      << "): the fast build differs from the reference (" << a.cells.size() << " against "
                      << b.cells.size() << " cells, " << a.stats.polygons_added << " against " << b.stats.polygons_added
                      << " polygons added)";
    }
  EXPECT_EQ(mismatches, 0u);
  return run;
}

std::vector<VisibilityOptions> option_sets() {
  std::vector<VisibilityOptions> sets(4);
  sets[1].snap_lattice_cells = 64;        // coarse: more dedup
  sets[2].snap_lattice_cells = 1u << 21;  // finest: more distinct polygons, more cap hits
  sets[3].reprocess_cap = 1;              // the fallbacks early and often
  sets[3].max_region_polygons = 2;
  return sets;
}

World load(const SceneDesc& scene, const std::string& label) {
  World world;
  const Status s = build_world(scene, label, world);
  EXPECT_TRUE(s.ok()) << s.message();
  return world;
}

TEST(BuildEquivalence, GeneratedScenesMatchTheReferencePaths) {
  struct Case {
    std::string label;
    SceneDesc scene;
  };
  std::vector<Case> cases;
  cases.push_back({"grid 12x12 jittered", generate_grid({12, 12, true, 3})});
  GridOptions wide;
  wide.width = wide.height = 10;
  wide.door_width_m = 3.4;  // wide doors: many cells, many polygons per region
  cases.push_back({"grid 10x10 wide doors", generate_grid(wide)});
  cases.push_back({"ring 64", generate_ring({64, 2})});
  cases.push_back({"cottage", generate_cottage({1})});
  for (uint64_t seed : {1u, 2u, 3u}) {
    RandomOptions random;
    random.cells = 60;
    random.seed = seed;
    cases.push_back({"random 60 seed " + std::to_string(seed), generate_random(random)});
  }
  cases.push_back({"teleport ring", generate_teleport({6})});  // linked views: the uncached path
  cases.push_back({"mirrors", generate_mirror({})});
  size_t collapsed = 0, merged = 0, queries_total = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    const World world = load(c.scene, c.label);
    if (HasFailure()) return;
    std::vector<Query> queries;
    add_timeline_queries(world, 7, queries);
    add_random_queries(world, 5, 150, queries);
    if (HasFailure()) return;
    queries_total += queries.size();
    const PathsRun run = expect_same_builds(world, queries, option_sets());
    collapsed += run.collapsed;
    merged += run.merged;
    EXPECT_EQ(expect_same_builds(world, queries, {VisibilityOptions{}}, false).merged, 0u);  // one window each
  }
  EXPECT_GT(queries_total, 1000u);
  EXPECT_GT(collapsed, 50u);  // the cap and the polygon limit were exercised, not only plain adds
  EXPECT_GT(merged, 100u);    // and builds that merged pending polygons into one window
}

// Property: a builder that keeps the last build's lens (view_to_clip, near extent, clip depth:
// portal_traversal.cpp's Lens) gives, for every query, the VisibleSet a fresh builder gives, when
// the lens changes between builds (fov, aspect, near and far drawn anew), stays the same for a
// run of builds, or changes one field only.
TEST(BuildEquivalence, KeptLensGivesAFreshBuildersAnswer) {
  const World world = load(generate_grid({8, 8, true, 4}), "grid 8x8");
  if (HasFailure()) return;
  std::vector<Query> queries;
  add_random_queries(world, 11, 240, queries);
  if (HasFailure()) return;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t i = 0; i < queries.size(); ++i) {
    View& v = queries[i].view;
    if (i % 8 < 3 && i > 0) {  // runs of builds with the previous query's lens
      const View& before = queries[i - 1].view;
      v.fov_y_deg = before.fov_y_deg, v.aspect = before.aspect, v.near_m = before.near_m, v.far_m = before.far_m;
    } else if (i % 8 == 3) {  // one field apart from the previous query's lens
      const View& before = queries[i - 1].view;
      v.fov_y_deg = before.fov_y_deg, v.aspect = before.aspect, v.far_m = before.far_m;
      v.near_m = before.near_m * 1.5f;
    } else {
      v.near_m = 0.01f + 0.3f * u(rng);
      v.far_m = v.near_m + 5.0f + 500.0f * u(rng);
    }
  }
  VisibilityBuilder kept;
  VisibleSet a, b;
  size_t mismatches = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    VisibilityBuilder fresh;
    const Query& q = queries[i];
    ASSERT_TRUE(kept.build(world, q.view, q.start_cell, {}, a).ok());
    ASSERT_TRUE(fresh.build(world, q.view, q.start_cell, {}, b).ok());
    if (!(a == b) && ++mismatches <= 3) ADD_FAILURE() << "query " << i << ": the kept lens changed the answer";
  }
  EXPECT_EQ(mismatches, 0u);
}

const char* const kWad = "/usr/share/games/doom/freedoom1.wad";

TEST(BuildEquivalence, FreedoomMapsMatchTheReferencePaths) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  for (const char* map : {"E1M1", "E1M8"}) {
    SCOPED_TRACE(map);
    SceneDesc scene;
    DoomImportOptions import_options;
    import_options.convex_cells = true;  // the CLI's default
    ASSERT_TRUE(import_doom(kWad, map, import_options, scene).ok());
    const World world = load(scene, map);
    if (HasFailure()) return;
    std::vector<Query> queries;
    add_timeline_queries(world, 3, queries);
    add_random_queries(world, 9, 200, queries);
    if (HasFailure()) return;
    expect_same_builds(world, queries, {VisibilityOptions{}});
  }
}

}  // namespace
}  // namespace lintel
