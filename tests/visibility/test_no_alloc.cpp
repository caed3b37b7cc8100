// No heap allocation per frame after warm-up: the builder, the output VisibleSet and the tracker
// reuse their memory. This executable replaces the global operator new to count allocations (its
// own executable: the replacement affects nothing else).
#include "test_worlds.h"

#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <random>

namespace {
// The replaced operator new has to count somewhere global; only this test executable has it.
long g_allocations = 0;
bool g_counting = false;
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace lintel {
namespace {

struct Frame {
  View view;
  glm::vec3 eye;
  uint32_t cell;
};

TEST(NoAlloc, BuildsAndTrackerUpdatesDoNotAllocateAfterWarmUp) {
  testing::WorldOptions o;
  o.furnish = true;
  o.door_half_width = 1.5f;
  const testing::TestWorld t = testing::make_grid(6, 6, o);
  // A walk through the grid with turning views: the eye crosses doors, regions grow and collapse.
  std::vector<glm::vec3> eyes;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  glm::vec3 p(2.0f, 1.5f, 2.0f);
  for (int i = 0; i < 200; ++i) {
    p += glm::vec3(0.1f + 0.02f * u(rng), 0.0f, 0.1f * std::sin(0.05f * float(i)));
    eyes.push_back(t.to_world(p));
  }
  VisibilityBuilder builder;
  VisibleSet out;
  ViewerTracker tracker;
  VisibilityOptions options;
  options.max_region_polygons = 3;  // exercise the polygon limit too
  options.reprocess_cap = 2;

  auto run_walk = [&](uint64_t& cells_seen) {
    EXPECT_TRUE(tracker.update(t.world, eyes.front()).ok());
    for (size_t i = 0; i < eyes.size(); ++i) {
      EXPECT_TRUE(tracker.update(t.world, eyes[i]).ok());
      View v;
      v.eye_world = eyes[i];
      v.target_world = eyes[i] + t.dir_to_world({std::cos(0.07f * float(i)), 0.0f, std::sin(0.07f * float(i))});
      v.up_world = t.dir_to_world({0.0f, 1.0f, 0.0f});
      EXPECT_TRUE(builder.build(t.world, v, tracker.cell(), options, out).ok());
      cells_seen += out.cells.size();
    }
  };
  ASSERT_TRUE(tracker.reset(t.world, eyes.front()).ok());
  uint64_t warm_cells = 0, counted_cells = 0;
  run_walk(warm_cells);  // warm-up
  g_allocations = 0;
  g_counting = true;
  run_walk(counted_cells);
  g_counting = false;
  EXPECT_EQ(g_allocations, 0) << "allocations after warm-up";
  EXPECT_EQ(counted_cells, warm_cells);
  EXPECT_GT(counted_cells, eyes.size() * 2) << "the walk should see through doors";
  // The counter works: a fresh builder allocates.
  g_allocations = 0;
  g_counting = true;
  {
    VisibilityBuilder fresh;
    VisibleSet fresh_out;
    EXPECT_TRUE(fresh.build(t.world, t.view({2, 1.5f, 2}, {9, 1.5f, 9}), 0, options, fresh_out).ok());
  }
  g_counting = false;
  EXPECT_GT(g_allocations, 0);
}

// A builder prepared together with its output at load (prepare(world, options, out)) allocates
// nothing on its first build either, from any cell, looking anywhere: the frame after a level
// loads has no allocation hitch. Without the output's sizing the same first build allocates.
TEST(NoAlloc, FirstBuildAfterPreparingTheOutputDoesNotAllocate) {
  testing::WorldOptions o;
  o.furnish = true;
  o.door_half_width = 1.5f;
  const testing::TestWorld t = testing::make_grid(6, 6, o);
  VisibilityOptions options;
  options.max_region_polygons = 3;
  for (uint32_t start = 0; start < 36; start += 7) {
    const glm::vec3 eye(2.0f + 4.0f * float(start % 6), 1.5f, 2.0f + 4.0f * float(start / 6));
    const View v = t.view(eye, {24.0f - eye.x + 1.0f, 1.5f, 24.0f - eye.z});  // across the grid
    VisibilityBuilder prepared;
    VisibleSet out;
    prepared.prepare(t.world, options, out);
    g_allocations = 0;
    g_counting = true;
    EXPECT_TRUE(prepared.build(t.world, v, start, options, out).ok());
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "first build from cell " << start;
    EXPECT_GT(out.cells.size(), 1u) << "from cell " << start << ": the view should see through doors";

    VisibilityBuilder builder_only;
    VisibleSet fresh_out;
    builder_only.prepare(t.world, options);
    g_allocations = 0;
    g_counting = true;
    EXPECT_TRUE(builder_only.build(t.world, v, start, options, fresh_out).ok());
    g_counting = false;
    EXPECT_GT(g_allocations, 0) << "from cell " << start << ": the output was not sized, so the build sizes it";
    EXPECT_EQ(fresh_out, out);
  }
}

}  // namespace
}  // namespace lintel
