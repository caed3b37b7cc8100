// Regression for the lessons' drift hang: "a client's portal flood re-enqueued a cell whenever its
// view grew; ... exact-match dedup never matched, the region grew forever: a frozen game. Its unit
// tests used identity transforms and chains, never cycles."
#include "test_worlds.h"
#include "visibility_builder_testing.h"

#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <chrono>

namespace lintel {
namespace {

using testing::make_cycle_stack;
using testing::TestWorld;

// Property: on a ring of cells with non-identity frames whose flood goes round a cycle of portals
// (all facing the eye, each covering the last), the traversal
//  * with snapping and the cap disabled (the test-only switch: float precision, widened an ulp
//    outward for conservative storage, exact dedup) widens the region on every lap, never stops on
//    its own, exceeds the pop bound and is stopped by the hard limit at 100x the bound, reporting it;
//  * with the same options and the switch off (lattice + cap) terminates within the bound, having
//    gone round the cycle at most a few times, with every cell of the ring visible; so do the
//    defaults and the finest lattice.
TEST(DriftHang, UnboundedModeExceedsTheBoundAndDefaultsTerminate) {
  for (uint32_t ring : {2u, 5u}) {
    const TestWorld t = make_cycle_stack(ring);
    ASSERT_NE(t.world.cells[1].cell_to_world, t.world.cells[2].cell_to_world);
    const uint32_t cells = static_cast<uint32_t>(t.world.cells.size());
    const View view = t.view({0.04f, -0.03f, 0.5f}, {0.1f, 0.07f, -5.0f});
    VisibilityBuilder builder;

    VisibleSet defaults;
    ASSERT_TRUE(builder.build(t.world, view, 0, {}, defaults).ok());
    EXPECT_LE(defaults.stats.pops, pop_bound(cells, {}));
    EXPECT_EQ(defaults.cells.size(), cells);

    // A coarser lattice than the default keeps the hard limit (100 x the bound) quick to reach.
    VisibilityOptions bounded;
    bounded.snap_lattice_cells = 64;
    VisibleSet v;
    const Status ok = builder.build(t.world, view, 0, bounded, v);
    ASSERT_TRUE(ok.ok()) << ok.message();
    EXPECT_FALSE(v.stats.bound_exceeded);
    EXPECT_LE(v.stats.pops, pop_bound(cells, bounded));
    EXPECT_LE(v.stats.pops, 4u * cells) << "the lattice should recognise the second lap";
    EXPECT_EQ(v.cells.size(), cells);

    // The finest lattice (2^21 cells, 9.5e-7 NDC) recognises the second lap just as well: the
    // snap tolerance (1e-12 NDC there) still exceeds the clipper's rounding noise.
    VisibilityOptions finest;
    finest.snap_lattice_cells = kMaxSnapLatticeCells;
    VisibleSet f;
    ASSERT_TRUE(builder.build(t.world, view, 0, finest, f).ok());
    EXPECT_FALSE(f.stats.bound_exceeded);
    EXPECT_LE(f.stats.pops, 4u * cells) << "the finest lattice should recognise the second lap";
    EXPECT_EQ(f.cells.size(), cells);

    const VisibilityOptions& unbounded = bounded;  // same options, snap and cap switched off below
    VisibilityBuilderTesting::disable_snap_and_cap(builder, true);
    VisibleSet u;
    const auto t0 = std::chrono::steady_clock::now();
    const Status stopped = builder.build(t.world, view, 0, unbounded, u);
    VisibilityBuilderTesting::disable_snap_and_cap(builder, false);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_FALSE(stopped.ok());
    EXPECT_TRUE(u.stats.bound_exceeded);
    EXPECT_GT(u.stats.pops, pop_bound(cells, unbounded));
    EXPECT_EQ(u.stats.pops, kUnboundedSafetyFactor * pop_bound(cells, unbounded));
    EXPECT_GT(u.stats.reenqueues, pop_bound(cells, unbounded));
    EXPECT_EQ(u.cells.size(), cells);
    std::printf("ring %u: bounded %llu pops, unbounded stopped at %llu pops in %.2f s: %s\n", ring,
                (unsigned long long)v.stats.pops, (unsigned long long)u.stats.pops, seconds, stopped.message().c_str());
  }
}

}  // namespace
}  // namespace lintel
