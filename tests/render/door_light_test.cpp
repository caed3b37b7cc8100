// Property: a closed door is a wall for light as it is for sight (issue 11 item 2, renderer side).
// Two rooms joined by a door, the lamp in A, the camera in B looking at the door:
//  * door open: light comes through it (most of B's pixels are lit) and A shows through it;
//  * door closed with Renderer::update_world: every pixel of B has exactly 0.0 linear radiance
//    (direct light, shadows and GI all honour the door), so has every pixel of A that still shows
//    through the hole, and the lamp costs no shadow view (it reaches no cell the frame lights);
//  * the closed frame equals, bit for bit, a renderer created with the door already closed, and
//    opening the door again restores the open frame bit for bit (and a fresh renderer's).
// The frames depend only on their view (gi_persist off), so bit-identity is the right bar.
// About 5 s on the 2-core lavapipe machine.
#include "render_test_support.h"
#include "two_rooms.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 128, kHeight = 72;

struct RoomPixels {
  uint32_t total = 0, nonzero = 0;
};

RoomPixels room_pixels(const RenderedFrame& frame, uint32_t cell) {
  RoomPixels r;
  for (size_t p = 0; p < frame.cell_ids.size(); ++p) {
    if (frame.cell_ids[p] != cell) continue;
    const glm::vec4& c = frame.hdr[p];
    ++r.total;
    r.nonzero += c.r != 0.0f || c.g != 0.0f || c.b != 0.0f;
  }
  return r;
}

bool same_hdr(const RenderedFrame& a, const RenderedFrame& b) {
  return a.hdr.size() == b.hdr.size() && std::memcmp(a.hdr.data(), b.hdr.data(), a.hdr.size() * sizeof(glm::vec4)) == 0;
}

class DoorLightTest : public ValidatedGpu {
 protected:
  void SetUp() override {
    ValidatedGpu::SetUp();
    const Status s = build_world(two_rooms(true), "two rooms (door)", world_);
    ASSERT_TRUE(s.ok()) << s.message();
    a_ = uint32_t(world_.find_cell("A"));
    b_ = uint32_t(world_.find_cell("B"));
    ASSERT_EQ(world_.portals.size(), 1u);
    view_.eye_world = {7.6f, 1.4f, 2.0f};  // in B, facing the door wall
    view_.target_world = {4.2f, 1.1f, 2.0f};
    view_.aspect = float(kWidth) / float(kHeight);
  }
  static RenderOptions options() {
    RenderOptions o = test_options(kWidth, kHeight);
    o.gi_options.bounces = 4;
    o.readback_hdr = true;
    o.readback_cells = true;
    return o;
  }
  bool render(Renderer& r, RenderedFrame& frame) {
    const Status s = r.render(view_, locate_cell(world_, glm::dvec3(view_.eye_world)).cell, frame);
    EXPECT_TRUE(s.ok()) << s.message();
    return s.ok();
  }
  bool update(Renderer& r) {
    const Status s = r.update_world(world_, {});
    EXPECT_TRUE(s.ok()) << s.message();
    return s.ok();
  }

  World world_;
  View view_;
  uint32_t a_ = 0, b_ = 0;
};

TEST_F(DoorLightTest, ClosedDoorBlocksLightAndOpeningRestoresTheImage) {
  const double t0 = now_ms();
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world_, options());
  ASSERT_NE(r, nullptr);
  RenderedFrame open;
  ASSERT_TRUE(render(*r, open));
  const RoomPixels open_b = room_pixels(open, b_), open_a = room_pixels(open, a_);
  std::printf("open: B %u pixels (%u lit), A %u pixels through the door, %u lights, %u shadow views\n", open_b.total,
              open_b.nonzero, open_a.total, open.active_lights, open.shadow_views);
  // Controls: the door does let light and sight through while open.
  EXPECT_GT(open_b.total, kWidth * kHeight / 2);
  EXPECT_GE(open_b.nonzero, open_b.total * 9 / 10);
  EXPECT_GT(open_a.total, 0u) << "room A should show through the open door";
  EXPECT_EQ(open.active_lights, 1u);
  EXPECT_EQ(open.shadow_views, 6u);

  world_.set_portal_open(0, false);
  ASSERT_TRUE(update(*r));
  RenderedFrame closed;
  ASSERT_TRUE(render(*r, closed));
  const RoomPixels closed_b = room_pixels(closed, b_), closed_a = room_pixels(closed, a_);
  std::printf("closed: B %u pixels (%u lit), A %u pixels (%u lit), %u lights, %u shadow views\n", closed_b.total,
              closed_b.nonzero, closed_a.total, closed_a.nonzero, closed.active_lights, closed.shadow_views);
  EXPECT_EQ(closed_b.nonzero, 0u) << "light came through the closed door";
  // Pixels of A may still show through the hole the door leaves (its shell's box reaches B, and
  // the instance reach lists do not follow doors), but nothing lights them from this frame.
  EXPECT_EQ(closed_a.nonzero, 0u) << "room A's pixels behind the closed door are lit";
  EXPECT_EQ(closed.active_lights, 0u) << "the lamp behind the closed door reaches no cell of this frame";
  EXPECT_EQ(closed.shadow_views, 0u);

  // The same closed world from scratch gives the same frame.
  {
    std::unique_ptr<Renderer> fresh = make_renderer(ctx(), world_, options());
    ASSERT_NE(fresh, nullptr);
    RenderedFrame f;
    ASSERT_TRUE(render(*fresh, f));
    EXPECT_TRUE(same_hdr(f, closed)) << "update_world (closing) differs from a renderer made with the door closed";
  }

  world_.set_portal_open(0, true);
  ASSERT_TRUE(update(*r));
  RenderedFrame reopened;
  ASSERT_TRUE(render(*r, reopened));
  EXPECT_TRUE(same_hdr(reopened, open)) << "opening the door again does not restore the open frame";
  EXPECT_EQ(reopened.cell_ids, open.cell_ids);
  std::printf("door closed and reopened: %.0f ms\n", now_ms() - t0);
}

// Light travels as sight does, per direction: closing only A -> B (A no longer sees B; B still
// sees A) keeps every pixel of B dark, while A, seen from B through the door, is drawn and lit.
TEST_F(DoorLightTest, OneDirectionClosedBlocksLightThatWay) {
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world_, options());
  ASSERT_NE(r, nullptr);
  const Portal& door = world_.portals[0];
  const PortalDirection a_to_b = door.from == a_ ? PortalDirection::FromTo : PortalDirection::ToFrom;
  world_.set_portal_open(0, a_to_b, false);
  ASSERT_TRUE(update(*r));
  RenderedFrame frame;
  ASSERT_TRUE(render(*r, frame));
  const RoomPixels b = room_pixels(frame, b_), a = room_pixels(frame, a_);
  std::printf("A -> B closed: B %u pixels (%u lit), A %u pixels (%u lit)\n", b.total, b.nonzero, a.total, a.nonzero);
  EXPECT_GT(b.total, kWidth * kHeight / 2);
  EXPECT_EQ(b.nonzero, 0u);
  EXPECT_GT(a.total, 0u) << "B still sees A";
  EXPECT_GE(a.nonzero, a.total * 9 / 10) << "A's lamp lights A";
}

TEST_F(DoorLightTest, UpdateWorldRejectsAnotherWorld) {
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world_, options());
  ASSERT_NE(r, nullptr);
  World other;
  ASSERT_TRUE(build_world(two_rooms(false), "two rooms (sealed)", other).ok());
  const Status s = r->update_world(other, {});
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::BadInput) << s.message();
  const uint32_t out_of_range[] = {uint32_t(world_.instances.size())};
  EXPECT_FALSE(r->update_world(world_, out_of_range).ok());
}

}  // namespace
}  // namespace lintel::render::test
