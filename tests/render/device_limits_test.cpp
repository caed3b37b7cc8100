// The renderer within the device's limits: the shadow atlas is planned against
// maxImageArrayLayers, maxMemoryAllocationSize, the heap and a budget before anything is created,
// and frames give atlas slots only to their active lights. Scenes that would crash an unplanned atlas (SIGSEGV) or
// break the Vulkan rules (more than 2048 layers) render under validation + sync validation + GPU-AV
// with no message. Small images and shadow maps keep each case to seconds on lavapipe.
#include "render_test_support.h"
#include "two_rooms.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include "../../render/src/shadow_plan.h"
#include "../../render/src/texel_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace lintel::render::test {
namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;

// lavapipe (Mesa 22.3) as it reports itself: 2048 layers, 2 GiB per allocation.
ShadowDeviceLimits lavapipe_like() {
  ShadowDeviceLimits l;
  l.max_layers = 2048;
  l.max_extent = 16384;
  l.max_allocation_bytes = 2048 * kMiB;
  l.max_resource_bytes = 0;
  l.heap_bytes = 8192 * kMiB;
  return l;
}

// Property: for any request, the plan stays within every cap (layers, extent, one allocation,
// the budget, a quarter of the heap), never raises the resolution, keeps the requested
// resolution whenever min(views, kMinShadowSlots) layers of it fit, and gives at least that many
// slots whenever it can (the resolution only drops to make them fit).
TEST(ShadowPlanTest, StaysWithinEveryLimit) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    ShadowDeviceLimits l;
    l.max_layers = 1u + rng() % 4096;
    l.max_extent = 256u << (rng() % 6);
    l.max_allocation_bytes = (uint64_t(1) + rng() % 4096) * kMiB;
    l.max_resource_bytes = rng() % 2 ? 0 : (uint64_t(1) + rng() % 8192) * kMiB;
    l.heap_bytes = (uint64_t(64) + rng() % 16384) * kMiB;
    const uint32_t requested = 16u << (rng() % 10);
    const uint32_t views = rng() % 5000;
    const uint64_t budget = (uint64_t(1) + rng() % 1024) * kMiB;
    ShadowPlan p;
    const Status s = plan_shadow_atlas(l, requested, views, budget, p);
    uint64_t cap = std::min({l.max_allocation_bytes, budget, l.heap_bytes / 4});
    if (l.max_resource_bytes) cap = std::min(cap, l.max_resource_bytes);
    if (!s) {
      // Refused only when not one 16 x 16 layer fits.
      EXPECT_LT(cap, 16u * 16u * 4u) << s.message();
      continue;
    }
    EXPECT_GE(p.slots, 1u);
    EXPECT_LE(p.slots, std::max(1u, views));
    EXPECT_LE(p.slots, l.max_layers);
    EXPECT_LE(p.resolution, std::min(requested, l.max_extent));
    EXPECT_LE(p.bytes, cap);
    EXPECT_EQ(p.bytes, uint64_t(p.resolution) * p.resolution * 4 * p.slots);
    const uint32_t need = std::min(std::max(1u, views), kMinShadowSlots);
    const uint32_t req = std::min(requested, l.max_extent);
    const uint64_t fit_at_request = std::min<uint64_t>(l.max_layers, cap / (uint64_t(req) * req * 4));
    if (fit_at_request >= need) {
      EXPECT_EQ(p.resolution, req);
    }
    if (p.resolution > 16) {
      EXPECT_GE(p.slots, need);
    }
    EXPECT_EQ(p.note.empty(), p.resolution == requested && p.slots == std::max(1u, views));
  }
}

TEST(ShadowPlanTest, CottageAt8192IsReducedToFit) {
  ShadowPlan p;
  ASSERT_TRUE(plan_shadow_atlas(lavapipe_like(), 8192, 15, 512 * kMiB, p).ok());
  // 15 layers of 8192^2 D32 are 3.75 GiB: the resolution halves until 15 fit in 512 MiB.
  EXPECT_LT(p.resolution, 8192u);
  EXPECT_EQ(p.slots, 15u);
  EXPECT_LE(p.bytes, 512 * kMiB);
  EXPECT_FALSE(p.note.empty());
}

// Slots are consecutive per light, never past the atlas, first come first served; a light that
// does not fit whole gets none (and a later, smaller one may still fit).
TEST(ShadowPlanTest, FrameSlotsNeverOverflow) {
  const std::vector<uint32_t> view_count = {6, 1, 6, 2, 6};
  const std::vector<uint32_t> lights = {0, 2, 4, 1, 3};
  std::vector<uint32_t> first;
  // 14 slots: 6 + 6; the third point light does not fit (2 left), the spot does (1), the sun's
  // two views then do not (1 left).
  EXPECT_EQ(shadow_slots_for_frame(lights, view_count, 14, first), 2u);
  EXPECT_EQ(first[0], 0u);
  EXPECT_EQ(first[1], 6u);
  EXPECT_EQ(first[2], kNoShadowSlot);
  EXPECT_EQ(first[3], 12u);
  EXPECT_EQ(first[4], kNoShadowSlot);
  for (uint32_t slots : {0u, 1u, 5u, 6u, 13u, 21u, 100u}) {
    const uint32_t unshadowed = shadow_slots_for_frame(lights, view_count, slots, first);
    uint32_t used = 0, without = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
      if (first[i] == kNoShadowSlot) {
        ++without;
        continue;
      }
      EXPECT_EQ(first[i], used) << "slots " << slots;
      used += view_count[lights[i]];
    }
    EXPECT_LE(used, slots);
    EXPECT_EQ(unshadowed, without);
  }
}

class DeviceLimitsTest : public ValidatedGpu {
 protected:
  // Renders `view` once; the fixture fails the test on any validation message.
  void render_once(const World& world, const View& view, RenderOptions options, RenderedFrame& frame,
                   std::unique_ptr<Renderer>* keep = nullptr) {
    const double t0 = now_ms();
    std::unique_ptr<Renderer> r = make_renderer(ctx(), world, options);
    ASSERT_NE(r, nullptr);
    const uint32_t cell = locate_cell(world, glm::dvec3(view.eye_world)).cell;
    const Status s = r->render(view, cell, frame);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_LE(frame.shadow_views, r->shadow_slots());
    EXPECT_EQ(frame.rgba8.size(), size_t(options.width) * options.height * 4);
    std::printf("  %zu cells, %zu lights: %u active, %u shadow views, %u unshadowed; atlas %u x %u^2; %.0f ms\n",
                world.cells.size(), world.lights.size(), frame.active_lights, frame.shadow_views,
                frame.unshadowed_lights, r->shadow_slots(), r->shadow_resolution(), now_ms() - t0);
    std::fflush(stdout);
    if (keep) *keep = std::move(r);
  }
};

RenderOptions small_options() {
  RenderOptions o = test_options(64, 36);
  o.shadow_resolution = 64;
  o.gi_options.bounces = 1;
  return o;
}

View first_timeline_view(const World& world, double t) {
  View v = timeline_view(world.timelines.front(), t);
  v.aspect = 64.0f / 36.0f;
  return v;
}

// The full sizes (grid 64 x 64: 819 lights, 4914 views; random 4096 cells: 1334 lights)
// take 90-105 s each under validation on the shared 2-core machine, almost all of it the
// renderer's per-scene setup (every light's portal visibility, the GI layout), so they run with
// LINTEL_SOAK=1. By default smaller scenes of the same generators take the same paths: more
// views than the 512 MiB budget holds at the default 512^2 resolution.
bool soak() { return std::getenv("LINTEL_SOAK") != nullptr; }

// `lintel gen grid --width 64 --height 64` then `render --time 1`: crashed (SIGSEGV).
TEST_F(DeviceLimitsTest, GridRenders) {
  GridOptions g;
  g.width = g.height = soak() ? 64 : 24;
  World world;
  ASSERT_TRUE(build_world(generate_grid(g), "grid", world).ok());
  RenderOptions o = small_options();
  o.shadow_resolution = 512;
  RenderedFrame frame;
  std::unique_ptr<Renderer> r;
  render_once(world, first_timeline_view(world, 1.0), o, frame, &r);
  ASSERT_NE(r, nullptr);
  // More views than the budget: the plan is smaller than one slot per view, and says so.
  EXPECT_LT(r->shadow_slots(), 6 * world.lights.size());
  EXPECT_FALSE(r->setup_note().empty());
}

// `lintel gen random --cells 4096` then a render: crashed.
TEST_F(DeviceLimitsTest, RandomCellsRender) {
  RandomOptions ro;
  ro.cells = soak() ? 4096 : 1024;
  World world;
  ASSERT_TRUE(build_world(generate_random(ro), "random", world).ok());
  ASSERT_FALSE(world.timelines.empty());
  RenderOptions o = small_options();
  o.shadow_resolution = 512;
  RenderedFrame frame;
  render_once(world, first_timeline_view(world, 1.0), o, frame);
}

// One cell with 400 point lights: 2400 shadow views, past maxImageArrayLayers (2048 on lavapipe).
// 342 lights crashed before. Now the atlas has at most the device's layers and the lights that
// do not fit in a frame light unshadowed, counted.
TEST_F(DeviceLimitsTest, FourHundredLightsInOneCell) {
  SceneDesc s = two_rooms(false);
  const int cell_a = [&] {
    for (size_t n = 0; n < s.nodes.size(); ++n)
      if (s.nodes[n].light == 0) return s.nodes[n].parent;
    return -1;
  }();
  ASSERT_GE(cell_a, 0);
  const NodeDesc lamp = [&] {
    for (const NodeDesc& n : s.nodes)
      if (n.light == 0) return n;
    return NodeDesc{};
  }();
  for (int i = 1; i < 400; ++i) {
    NodeDesc extra = lamp;
    extra.name = "lamp_" + std::to_string(i);
    // Spread over the room (cell space of A is world space shifted by its frame: 4 x 2.5 x 4 m).
    extra.translation += glm::vec3(0.15f * float(i % 20) - 1.5f, -0.0025f * float(i % 7), 0.15f * float(i / 20) - 1.5f);
    s.nodes.push_back(extra);
  }
  World world;
  ASSERT_TRUE(build_world(s, "400 lights", world).ok());
  ASSERT_EQ(world.lights.size(), 400u);
  View view;
  view.eye_world = {0.5f, 1.6f, 0.5f};
  view.target_world = {3.5f, 1.0f, 3.5f};
  view.aspect = 64.0f / 36.0f;
  RenderedFrame frame;
  std::unique_ptr<Renderer> r;
  render_once(world, view, small_options(), frame, &r);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(frame.active_lights, 400u);
  // Every light has 6 views; the atlas holds slots / 6 whole lights.
  const uint32_t shadowed = std::min(400u, r->shadow_slots() / 6);
  EXPECT_EQ(frame.unshadowed_lights, 400u - shadowed);
  EXPECT_EQ(frame.shadow_views, 6 * shadowed);
  EXPECT_FALSE(r->setup_note().empty() && frame.unshadowed_lights > 0);
  // The lit room is lit: the unshadowed lights still add their light.
  uint64_t sum = 0;
  for (size_t i = 0; i < frame.rgba8.size(); i += 4) sum += frame.rgba8[i];
  EXPECT_GT(sum, 0u);
}

// `render scenes/cottage.gltf --time 5 --width 64 --height 36 --shadow-res 8192`: crashed. The
// plan lowers the resolution until every view fits the budget, and says so.
TEST_F(DeviceLimitsTest, CottageShadowRes8192IsReduced) {
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  RenderOptions o = small_options();
  o.shadow_resolution = 8192;
  o.shadow_memory_budget_mib = 64;  // keeps lavapipe's per-frame clears small; the rule is the same
  RenderedFrame frame;
  std::unique_ptr<Renderer> r;
  render_once(world, first_timeline_view(world, 5.0), o, frame, &r);
  ASSERT_NE(r, nullptr);
  EXPECT_LT(r->shadow_resolution(), 8192u);
  EXPECT_LE(uint64_t(r->shadow_resolution()) * r->shadow_resolution() * 4 * r->shadow_slots(), 64 * kMiB);
  EXPECT_NE(r->setup_note().find("reduced"), std::string::npos) << r->setup_note();
  EXPECT_EQ(frame.unshadowed_lights, 0u);
}

// The renderer reads its per-pixel data as texel buffers; a device that reads fewer texels than
// a buffer holds (the Vulkan minimum is 65,536) is refused up front with one line naming the
// device, the buffer and both counts, never a view cut short.
TEST(TexelLimit, TooManyTexelsIsUnsupportedNamingTheBuffer) {
  EXPECT_TRUE(check_texel_count("small GPU", 65536, 65536, "probes").ok());
  const Status s = check_texel_count("small GPU", 65536, 65537, "probes");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::Unsupported);
  EXPECT_NE(s.message().find("small GPU"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("probes"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("65536"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("65537"), std::string::npos) << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << "one line";
}

}  // namespace
}  // namespace lintel::render::test
