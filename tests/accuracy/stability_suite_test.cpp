// The stability suite at CI size: Lintel's polygon method, the rect method and the exact oracle
// stay conservative and within their bounds on every hard case (eyes on portal planes, grazing
// views, huge coordinates, long chains, rings up to 256 cells...). The planes method is expected
// to fail the 64-cell chain (Godot's depth cap of 16): the suite must report that, not hide it.
#include <lintel/exact_oracle.h>
#include <lintel/stability_suite.h>

#include <gtest/gtest.h>

namespace lintel {
namespace {

TEST(StabilitySuite, ConservativeMethodsSurviveEveryCase) {
  StabilityOptions options;
  options.views_per_case = 6;
  options.resolution = 96;
  options.progress = false;
  const MethodFactory factory = [] {
    std::vector<std::unique_ptr<CullMethod>> m;
    m.push_back(make_exact_method());
    m.push_back(make_polygon_method(1024, 16));
    m.push_back(make_rect_method());
    m.push_back(make_planes_method(16));
    return m;
  };
  StabilityResult result;
  ASSERT_TRUE(run_stability_suite(factory, options, result).ok());
  bool planes_failed_on_chain = false;
  for (const MethodScore& s : result.scores) {
    if (s.method == "planes") {
      if (s.scene == "chain of 64" && s.bound_hits > 0) planes_failed_on_chain = true;
      continue;
    }
    EXPECT_EQ(s.bound_hits, 0u) << s.scene << " " << s.method;
    EXPECT_EQ(s.cell_false_negatives, 0u) << s.scene << " " << s.method;
    EXPECT_EQ(s.instance_false_negatives, 0u) << s.scene << " " << s.method;
  }
  EXPECT_TRUE(planes_failed_on_chain);
}

}  // namespace
}  // namespace lintel
