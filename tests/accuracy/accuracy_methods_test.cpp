// The CI-sized accuracy check (docs/accuracy.md): a few scenes and views, every conservative
// method scored against the Embree ground truth. A false negative is never accepted; the
// over-inclusion order exact <= polygon <= rect <= frustum is the expected cost of each
// simplification (false positives accepted by design, measured here).
#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/exact_oracle.h>
#include <lintel/ndc_snap.h>
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
    m.push_back(make_polygon_method(kMaxSnapLatticeCells, 16));  // the finest snap, 9.5e-7 NDC
    m.push_back(make_rect_method());
    m.push_back(make_frustum_method());
    m.push_back(make_none_method());
    // Portal visibility plus two-phase occlusion, at rest and with a camera cut on every view.
    m.push_back(make_portal_hiz_method(64, HizHistory::Still));
    m.push_back(make_portal_hiz_method(64, HizHistory::Cut));
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
  // Every setting of every conservative method, both polygon lattices included.
  for (const MethodScore& s : all) {
    EXPECT_GT(s.views, 60u);
    EXPECT_EQ(s.cell_false_negatives, 0u) << s.method << " " << s.settings;
    EXPECT_EQ(s.instance_false_negatives, 0u) << s.method << " " << s.settings;
  }
  const double exact = find(all, "exact").over_inclusion(), polygon = find(all, "polygon").over_inclusion();
  const double rect = find(all, "rect").over_inclusion(), frustum = find(all, "frustum").over_inclusion();
  EXPECT_GE(exact, 1.0);
  EXPECT_LE(exact, polygon);
  EXPECT_LE(polygon, rect);
  EXPECT_LE(rect, frustum);
  // Occlusion only ever removes instances from the polygon method's set (same builder settings);
  // at rest it removes some.
  const double hiz = find(all, "portal+hiz").over_inclusion();
  EXPECT_LT(hiz, polygon);
  EXPECT_GE(hiz, 1.0);
  // The finest snap still contains the exact regions, so it draws at least what exact draws.
  const auto finest = std::find_if(all.begin(), all.end(), [](const MethodScore& s) {
    return s.settings == "lattice=" + std::to_string(kMaxSnapLatticeCells) + " cap=16";
  });
  ASSERT_NE(finest, all.end());
  EXPECT_LE(exact, finest->over_inclusion());
  EXPECT_GE(finest->area_ratio(), 1.0 - 1e-3);
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
      ASSERT_TRUE(run_and_measure(*exact, scene.world, v.view, v.start_cell, exact_result).ok());
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

// Regression: in scenes/cottage.gltf the portals between the enclosing `outside` cell and the
// rooms used to be stored facing the wrong way (the loader oriented a portal by the two cells'
// volume-box centres, and the centre of a cell that surrounds the house lies inside the house),
// so every portal method, the exact oracle included, culled the outside from inside. The loader
// now orients portals by probing either side (docs/accuracy.md); this keeps it fixed.
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
