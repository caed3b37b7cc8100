// Property: a light in a sealed room puts EXACTLY zero light into the neighbouring sealed room
// (docs/rendering.md: light crosses cells only through portals) — every pixel of room B has
// linear radiance 0.0 in all channels, with GI on and four bounces, whichever camera cull draws
// the frame (with CameraCull::None room A is drawn and lit in the same frame, its shadows and GI
// computed, so only the lights' cell masks, the shadow maps and the portal-only GI keep B dark:
// gathering probes over every cell's surfels, for one, fails the frustum and none cases,
// while portal culling from B never activates room A at all). Two controls make the
// zero mean something: room A itself is lit (an all-black renderer fails), and the same rooms
// joined by a door portal DO light room B (so B's zero is due to the sealing, not to B being
// unlit whatever happens). 1 to 5 s on the 2-core lavapipe machine.
#include "render_test_support.h"
#include "two_rooms.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 128, kHeight = 72;

struct RoomPixels {
  uint32_t total = 0;    // pixels whose surface belongs to the room
  uint32_t nonzero = 0;  // of those, with any channel of radiance != 0
  uint32_t negative_or_nan = 0;
  double sum = 0.0;  // summed rgb radiance
};

RoomPixels room_pixels(const RenderedFrame& frame, uint32_t cell) {
  RoomPixels r;
  for (size_t p = 0; p < frame.cell_ids.size(); ++p) {
    if (frame.cell_ids[p] != cell) continue;
    const glm::vec4& c = frame.hdr[p];
    ++r.total;
    r.nonzero += c.r != 0.0f || c.g != 0.0f || c.b != 0.0f;
    r.negative_or_nan += !(c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f);
    r.sum += double(c.r) + double(c.g) + double(c.b);
  }
  return r;
}

View look(const glm::vec3& eye, const glm::vec3& target) {
  View v;
  v.eye_world = eye;
  v.target_world = target;
  v.aspect = float(kWidth) / float(kHeight);
  return v;
}

// From inside B: at the wall towards A (the door wall when there is one), and down a diagonal
// that takes in floor, ceiling, two walls and B's crate.
const View kViewsFromB[] = {look({7.6f, 1.4f, 2.0f}, {4.2f, 1.1f, 2.0f}), look({7.9f, 2.3f, 3.8f}, {4.5f, 0.2f, 0.4f})};
const View kViewFromA = look({0.4f, 1.6f, 3.6f}, {3.6f, 0.8f, 0.6f});

class LeakTest : public ValidatedGpu {
 protected:
  bool build(bool door) {
    const Status s = build_world(two_rooms(door), door ? "two rooms (door)" : "two rooms (sealed)", world_);
    EXPECT_TRUE(s.ok()) << s.message();
    if (!s) return false;
    a_ = uint32_t(world_.find_cell("A"));
    b_ = uint32_t(world_.find_cell("B"));
    EXPECT_EQ(world_.portals.size(), door ? 1u : 0u);
    return true;
  }
  static RenderOptions options(CameraCull cull) {
    RenderOptions o = test_options(kWidth, kHeight);
    o.camera_cull = cull;
    o.gi = true;
    o.gi_options.bounces = 4;
    o.readback_hdr = true;
    o.readback_cells = true;
    return o;
  }
  bool render(Renderer& r, const View& view, RenderedFrame& frame) {
    const uint32_t start = locate_cell(world_, glm::dvec3(view.eye_world)).cell;
    const Status s = r.render(view, start, frame);
    EXPECT_TRUE(s.ok()) << s.message();
    return s.ok();
  }

  World world_;
  uint32_t a_ = 0, b_ = 0;
};

TEST_F(LeakTest, SealedNeighbourReceivesExactlyZero) {
  const double t0 = now_ms();
  ASSERT_TRUE(build(false));
  const char* names[] = {"portal", "frustum", "none"};
  const CameraCull culls[] = {CameraCull::Portal, CameraCull::Frustum, CameraCull::None};
  for (int k = 0; k < 3; ++k) {
    std::unique_ptr<Renderer> r = make_renderer(ctx(), world_, options(culls[k]));
    ASSERT_NE(r, nullptr);
    for (size_t v = 0; v < std::size(kViewsFromB); ++v) {
      RenderedFrame frame;
      ASSERT_TRUE(render(*r, kViewsFromB[v], frame));
      const RoomPixels b = room_pixels(frame, b_);
      std::printf("sealed, cull %s, view %zu from B: %u pixels of B, %u nonzero, %u lights active\n", names[k], v,
                  b.total, b.nonzero, frame.active_lights);
      EXPECT_GT(b.total, kWidth * kHeight / 2) << "the view should be mostly room B";
      EXPECT_EQ(b.nonzero, 0u) << "light leaked into the sealed room (cull " << names[k] << ", view " << v
                               << "): summed radiance " << b.sum;
      if (culls[k] == CameraCull::None) {
        EXPECT_EQ(frame.active_lights, 1u) << "room A's lamp should run in this frame";
      }
    }
    // Control: room A, lit by its own lamp.
    RenderedFrame frame;
    ASSERT_TRUE(render(*r, kViewFromA, frame));
    const RoomPixels a = room_pixels(frame, a_);
    std::printf("sealed, cull %s, from A: %u pixels of A, %u nonzero, mean radiance %.4f\n", names[k], a.total,
                a.nonzero, a.total ? a.sum / (3.0 * a.total) : 0.0);
    EXPECT_GT(a.total, kWidth * kHeight / 2);
    EXPECT_GE(a.nonzero, a.total * 99 / 100) << "room A should be lit by its lamp";
    EXPECT_EQ(a.negative_or_nan, 0u);
    EXPECT_GT(a.sum / (3.0 * a.total), 0.02);
  }
  std::printf("sealed rooms: %.0f ms\n", now_ms() - t0);
}

TEST_F(LeakTest, DoorLetsLightIntoTheNeighbour) {
  const double t0 = now_ms();
  ASSERT_TRUE(build(true));
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world_, options(CameraCull::Portal));
  ASSERT_NE(r, nullptr);
  for (size_t v = 0; v < std::size(kViewsFromB); ++v) {
    RenderedFrame frame;
    ASSERT_TRUE(render(*r, kViewsFromB[v], frame));
    const RoomPixels b = room_pixels(frame, b_);
    std::printf("door, view %zu from B: %u pixels of B, %u nonzero, mean radiance %.4f\n", v, b.total, b.nonzero,
                b.total ? b.sum / (3.0 * b.total) : 0.0);
    EXPECT_GT(b.total, kWidth * kHeight / 2);
    EXPECT_EQ(b.negative_or_nan, 0u);
    EXPECT_GE(b.nonzero, b.total * 9 / 10) << "light through the door should reach most of room B";
  }
  std::printf("joined rooms: %.0f ms\n", now_ms() - t0);
}

}  // namespace
}  // namespace lintel::render::test
