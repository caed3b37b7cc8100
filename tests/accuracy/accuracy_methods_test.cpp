// The CI-sized accuracy check (docs/accuracy.md): a few scenes and views, every conservative
// method scored against the Embree ground truth. A false negative is never accepted; the
// over-inclusion order exact <= polygon <= rect <= frustum is the expected cost of each
// simplification (false positives accepted by design, measured here).
#include <lintel/accuracy_bench.h>
#include <lintel/exact_oracle.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace lintel {
namespace {

std::vector<AccuracyScene> ci_scenes() {
  std::vector<AccuracyScene> scenes(4);
  for (uint64_t seed : {1u, 2u}) {
    RandomOptions o;
    o.seed = seed;
    o.cells = 12;
    AccuracyScene& s = scenes[seed - 1];
    s.label = "random-" + std::to_string(seed);
    EXPECT_TRUE(build_world(generate_random(o), s.label, s.world).ok());
  }
  RingOptions ring;
  ring.cells = 8;
  scenes[2].label = "ring8";
  EXPECT_TRUE(build_world(generate_ring(ring), "ring8", scenes[2].world).ok());
  GridOptions grid;
  grid.jitter = true;
  scenes[3].label = "grid4-jitter";
  EXPECT_TRUE(build_world(generate_grid(grid), "grid4-jitter", scenes[3].world).ok());
  return scenes;
}

MethodFactory ci_methods() {
  return [] {
    std::vector<std::unique_ptr<CullMethod>> m;
    m.push_back(make_exact_method());
    m.push_back(make_polygon_method(1024, 16));
    m.push_back(make_rect_method());
    m.push_back(make_frustum_method());
    m.push_back(make_none_method());
    return m;
  };
}

const MethodScore& find(const std::vector<MethodScore>& scores, const std::string& method) {
  const auto it = std::find_if(scores.begin(), scores.end(), [&](const MethodScore& s) { return s.method == method; });
  EXPECT_NE(it, scores.end()) << method;
  return *it;
}

TEST(AccuracyCiSubset, ConservativeMethodsHaveNoFalseNegativesAndOrderHolds) {
  const std::vector<AccuracyScene> scenes = ci_scenes();
  AccuracyBenchOptions options;
  options.views_per_scene = 24;
  options.resolution = 128;
  options.progress = false;
  AccuracyBenchResult result;
  const MethodFactory factory = ci_methods();
  ASSERT_TRUE(run_accuracy_bench(scenes, factory, options, result).ok());
  const std::vector<MethodScore> all = merge_scores(result.scores);
  for (const char* m : {"exact", "polygon", "rect", "frustum", "none"}) {
    const MethodScore& s = find(all, m);
    EXPECT_GT(s.views, 60u);
    EXPECT_EQ(s.cell_false_negatives, 0u) << m;
    EXPECT_EQ(s.instance_false_negatives, 0u) << m;
  }
  const double exact = find(all, "exact").over_inclusion(), polygon = find(all, "polygon").over_inclusion();
  const double rect = find(all, "rect").over_inclusion(), frustum = find(all, "frustum").over_inclusion();
  EXPECT_GE(exact, 1.0);
  EXPECT_LE(exact, polygon);
  EXPECT_LE(polygon, rect);
  EXPECT_LE(rect, frustum);
  // Region areas: the exact one is the smallest; polygon adds at most the snap margin and caps.
  EXPECT_GE(find(all, "polygon").area_ratio(), 1.0 - 1e-3);
  EXPECT_GE(find(all, "rect").area_ratio(), find(all, "polygon").area_ratio() - 1e-3);
}

// Every vertex of every exact region lies in Lintel's region of the same cell (up to the slice
// and float tolerance): polygon regions contain the exact ones, i.e. agree with them up to snapping.
TEST(AccuracyCiSubset, PolygonRegionsContainExactRegions) {
  const std::vector<AccuracyScene> scenes = ci_scenes();
  VisibilityBuilder builder;
  VisibleSet visible;
  MethodResult exact_result;
  for (const AccuracyScene& scene : scenes) {
    RayGroundTruth rays;
    ASSERT_TRUE(rays.build(scene.world).ok());
    const std::vector<BenchView> views = make_bench_views(scene.world, rays, 16, 7);
    auto exact = make_exact_method();
    for (const BenchView& v : views) {
      ASSERT_TRUE(exact->run(scene.world, v.view, v.start_cell, exact_result).ok());
      ASSERT_TRUE(builder.build(scene.world, v.view, v.start_cell, {}, visible).ok());
      const auto& regions = exact_regions_of(*exact);
      for (uint32_t c = 0; c < regions.size(); ++c) {
        if (regions[c].empty()) continue;
        const VisibleCell* vc = visible.find(c);
        ASSERT_NE(vc, nullptr) << scene.label << ": cell " << c << " exact-visible but culled";
        const ClipRegionView region = visible.region(*vc);
        for (const auto& poly : regions[c])
          for (const glm::dvec2& p : poly)
            EXPECT_TRUE(region.contains(p, 1e-5)) << scene.label << ": cell " << c << " vertex " << p.x << "," << p.y;
      }
    }
  }
}

// KNOWN BUG, disabled until fixed: in scenes/cottage.gltf the portals between the enclosing
// `outside` cell and the rooms are stored facing the wrong way. The loader orients a portal by
// the two cells' volume-box centres (docs/scene-format.md, "Orientation"); the centre of a cell
// that surrounds the house lies inside the house, so e.g. living_west_window's normal points into
// the living room. Every portal method, the exact oracle included, then treats the windows and
// doors as seen from behind and culls the outside from inside (and the rooms from outside),
// which the rays see. Enable this test once the loader orients such portals correctly.
TEST(AccuracyCiSubset, CottageHasNoFalseNegatives) {
  std::vector<AccuracyScene> scenes(1);
  scenes[0].label = "cottage";
  ASSERT_TRUE(load_world(std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf", scenes[0].world).ok());
  AccuracyBenchOptions options;
  options.views_per_scene = 40;
  options.resolution = 128;
  options.progress = false;
  AccuracyBenchResult result;
  ASSERT_TRUE(run_accuracy_bench(scenes, ci_methods(), options, result).ok());
  for (const MethodScore& s : result.scores) {
    EXPECT_EQ(s.cell_false_negatives, 0u) << s.method;
    EXPECT_EQ(s.instance_false_negatives, 0u) << s.method;
  }
}

}  // namespace
}  // namespace lintel
