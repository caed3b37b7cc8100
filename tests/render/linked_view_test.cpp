// Property: what a mirror or a teleport shows is what an eye on its far side sees directly.
// A linked portal maps a ray entering its polygon at x along d onto link*x along link*d, so the
// view through it from eye E equals the direct view from E' = link*E looking along link*dir --
// mirrored left to right for a mirror (a reflection turns the image over), as it is for a
// teleport. Lintel's generated scenes hang linked portals on a wall's inner face, and E' stands
// behind that wall; the direct frame puts its near plane 3 mm past the portal's plane, so the wall
// is clipped away just as the linked view clips what lies before the portal. Shading is Lambertian
// (no view dependence) and lit where the surface really is, so the two frames must agree pixel for
// pixel inside the portal (away from its outline, where the two rasterize different neighbours):
// cell ids, and linear radiance within 1 %. This checks the linked view's transform, its
// clip to the portal's pyramid, the drop of the wall the portal hangs on, the winding flip of a
// mirror, and lighting, shadows and GI in the surface's own place. GTAO is off: it is a
// screen-space effect whose noise pattern is not mirror-symmetric. About 10 s on lavapipe.
#include "render_test_support.h"

#include <lintel/cell_locate.h>
#include <lintel/render/image_io.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

RenderOptions options() {
  RenderOptions o = test_options(kWidth, kHeight);
  o.readback_hdr = true;
  o.readback_cells = true;
  o.ao = false;
  return o;
}

struct Comparison {
  uint32_t linked = 0;      // pixels of frame A drawn through a linked view
  uint32_t interior = 0;    // of those, 3 px or more from any plain pixel
  uint32_t cell_match = 0;  // interior pixels whose cell is the direct frame's
  uint32_t close = 0;       // interior pixels whose radiance is within 1 % of the direct frame's
};

// Pixel of `frame` at (x, y), x mirrored when `flip`.
size_t at(uint32_t x, uint32_t y, bool flip) { return size_t(y) * kWidth + (flip ? kWidth - 1 - x : x); }

Comparison compare(const RenderedFrame& through, const RenderedFrame& direct, bool flip) {
  Comparison c;
  auto linked = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= int(kWidth) || y >= int(kHeight)) return false;
    const uint32_t id = through.cell_ids[size_t(y) * kWidth + size_t(x)];
    return id != kNoCell && (id >> kCellLinkShift) != 0;
  };
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      if (!linked(int(x), int(y))) continue;
      ++c.linked;
      bool inside = true;
      for (int dy = -3; dy <= 3 && inside; ++dy)
        for (int dx = -3; dx <= 3 && inside; ++dx) inside = linked(int(x) + dx, int(y) + dy);
      if (!inside) continue;
      ++c.interior;
      const size_t a = at(x, y, false), b = at(x, y, flip);
      c.cell_match += (through.cell_ids[a] & kCellIdMask) == (direct.cell_ids[b] & kCellIdMask);
      const glm::vec3 ra(through.hdr[a]), rb(direct.hdr[b]);
      const float scale = std::max({ra.r, ra.g, ra.b, rb.r, rb.g, rb.b, 1e-4f});
      const glm::vec3 d = glm::abs(ra - rb);
      c.close += std::max({d.r, d.g, d.b}) <= 0.01f * scale;
    }
  return c;
}

class LinkedViewTest : public ValidatedGpu {
 protected:
  // Frame A from `eye` looking along `dir` at `portal` of `world`; frame B from the far side.
  void check(const World& world, const std::string& portal_name, const glm::dvec3& eye, const glm::dvec3& dir) {
    const int p = world.find_portal(portal_name);
    ASSERT_GE(p, 0) << portal_name;
    const Portal& portal = world.portals[size_t(p)];
    ASSERT_TRUE(portal.linked());
    const bool flip = portal.link == PortalLinkKind::Mirror;
    const glm::dmat4& link = portal.link_world;

    View a;
    a.eye_world = glm::vec3(eye);
    a.target_world = glm::vec3(eye + dir);
    a.aspect = float(kWidth) / float(kHeight);
    View b = a;
    const glm::dvec3 far_eye = glm::dvec3(link * glm::dvec4(eye, 1.0));
    const glm::dvec3 far_dir = glm::dvec3(link * glm::dvec4(dir, 0.0));
    b.eye_world = glm::vec3(far_eye);
    b.target_world = glm::vec3(far_eye + far_dir);
    // The portal's plane lies at the same distance before both eyes (the link is rigid).
    const double to_plane = std::abs(glm::dot(glm::dvec3(portal.normal_world), eye) - double(portal.plane_d_world)) /
                            std::abs(glm::dot(glm::dvec3(portal.normal_world), dir));
    b.near_m = float(to_plane + 0.003);

    const CellLocation where = locate_cell(world, eye);
    ASSERT_EQ(where.reason, LocateReason::Containment);
    RenderedFrame through, direct;
    {
      std::unique_ptr<Renderer> r = make_renderer(ctx(), world, options());
      ASSERT_NE(r, nullptr);
      const Status s = r->render(a, where.cell, through);
      ASSERT_TRUE(s.ok()) << s.message();
      EXPECT_GT(through.linked_draws, 0u);
    }
    {
      // The far eye stands in the wall, behind `portal`, with its near plane at the portal's: the
      // doorway rule (rightly) looks through `portal` (a mirror) or its target (a teleport) from
      // there. The direct frame must not: those views are dropped (their cells taken out).
      VisibilityOptions vo;
      vo.cull_instances = false;
      VisibilityBuilder builder;
      VisibleSet visible;
      const Status built = builder.build(world, b, portal.to, vo, visible);
      ASSERT_TRUE(built.ok()) << built.message();
      auto through_portal = [&](uint32_t t) {
        while (t != 0 && visible.transforms[t].parent != 0) t = visible.transforms[t].parent;
        return t != 0 &&
               (visible.transforms[t].portal == uint32_t(p) || int(visible.transforms[t].portal) == portal.link_target);
      };
      std::erase_if(visible.linked_cells, [&](const VisibleCell& c) { return through_portal(c.transform); });
      std::erase_if(visible.linked_instances, [&](const LinkedInstance& i) { return through_portal(i.transform); });
      std::unique_ptr<Renderer> r = make_renderer(ctx(), world, options());
      ASSERT_NE(r, nullptr);
      const Status s = r->render(visible, b, direct);
      ASSERT_TRUE(s.ok()) << s.message();
    }
    if (const char* dump = std::getenv("LINTEL_TEST_DUMP")) {  // for a look when it fails
      (void)write_png(std::string(dump) + "/" + portal_name + "_through.png", {kWidth, kHeight, through.rgba8});
      (void)write_png(std::string(dump) + "/" + portal_name + "_direct.png", {kWidth, kHeight, direct.rgba8});
    }
    const Comparison c = compare(through, direct, flip);
    std::printf("%s: %u linked pixels, %u interior, %u same cell, %u within 1 %%\n", portal_name.c_str(), c.linked,
                c.interior, c.cell_match, c.close);
    EXPECT_GT(c.interior, kWidth * kHeight / 10) << "the portal should fill a good part of the frame";
    EXPECT_GE(c.cell_match, c.interior * 99 / 100);
    EXPECT_GE(c.close, c.interior * 97 / 100);
  }
};

TEST_F(LinkedViewTest, MirrorShowsTheRoomAsSeenFromBehindIt) {
  World world;
  ASSERT_TRUE(build_world(generate_mirror({}), "mirror", world).ok());
  check(world, "mirror_west", {3.0, 1.3, 0.2}, {-1.0, 0.0, 0.0});
}

TEST_F(LinkedViewTest, TeleportShowsTheFarRoomAsSeenFromThere) {
  World world;
  ASSERT_TRUE(build_world(generate_teleport({4}), "teleport", world).ok());
  const Portal& seam = world.portals[size_t(world.find_portal("seam_east"))];
  // 1.5 m before the seam, in the last room, looking through it.
  const glm::dvec3 centre(seam.centroid_world);
  const glm::dvec3 n(seam.normal_world);  // from the last room into the first (through the link)
  check(world, "seam_east", centre - 1.5 * n + glm::dvec3(0.0, 0.0, 0.2), n);
}

// Bad input: a hand-made VisibleSet whose linked entries name a cell out of range, or are out of
// transform order, is refused with one line saying so -- never drawn without them.
TEST_F(LinkedViewTest, BadLinkedEntriesAreErrors) {
  World world;
  ASSERT_TRUE(build_world(generate_mirror({}), "mirror", world).ok());
  View view;
  view.eye_world = {3.0f, 1.3f, 0.2f};
  view.target_world = {0.0f, 1.3f, 0.2f};
  view.aspect = float(kWidth) / float(kHeight);
  VisibilityOptions vo;
  vo.cull_instances = false;
  VisibilityBuilder builder;
  VisibleSet good;
  ASSERT_TRUE(builder.build(world, view, locate_cell(world, glm::dvec3(view.eye_world)).cell, vo, good).ok());
  ASSERT_GE(good.linked_cells.size(), 2u) << "facing mirrors: several linked views";
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world, options());
  ASSERT_NE(r, nullptr);
  RenderedFrame frame;
  ASSERT_TRUE(r->render(good, view, frame).ok());

  VisibleSet bad = good;
  bad.linked_cells[0].cell = uint32_t(world.cells.size()) + 7;
  Status s = r->render(bad, view, frame);
  EXPECT_EQ(s.kind(), StatusKind::BadInput);
  EXPECT_NE(s.message().find("linked cell"), std::string::npos) << s.message();

  bad = good;
  std::swap(bad.linked_cells.front(), bad.linked_cells.back());  // transforms out of order
  s = r->render(bad, view, frame);
  EXPECT_EQ(s.kind(), StatusKind::BadInput);
  EXPECT_NE(s.message().find("ascending transform order"), std::string::npos) << s.message();

  bad = good;
  bad.linked_cells.back().transform = uint32_t(bad.transforms.size());  // a transform it lacks
  s = r->render(bad, view, frame);
  EXPECT_EQ(s.kind(), StatusKind::BadInput);
  EXPECT_NE(s.message().find("ascending transform order"), std::string::npos) << s.message();

  EXPECT_TRUE(r->render(good, view, frame).ok()) << "the renderer stays usable after refusing";
}

}  // namespace
}  // namespace lintel::render::test
