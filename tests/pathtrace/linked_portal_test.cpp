// Property: the path tracer shows through a mirror what an eye on its far side sees directly,
// mirrored left to right, as the renderer's linked views do (render_linked_view_test). A camera
// ray entering the mirror's polygon at x along d goes on from link*x along link*d, so pixel
// (x, y) of the view from E looking at the mirror equals pixel (W - 1 - x, y) of the view from
// E' = link*E looking along link*dir. E' stands outside the room, behind the mirror's wall, whose
// shell is single-sided: camera rays pass through its back faces (path_tracer.h), so the direct
// view sees the room. Direct light only (no bounces), so the two images differ only by the
// pixels' jitter (at 256 samples a few high-contrast edge pixels by more than 10 %); pixels well
// inside the mirror are compared. With the link skipped, the mirror shows the wall it hangs on: 119 of 756 such pixels
// close (measured).
#include <lintel/portal_link.h>
#include <lintel/reference/path_tracer.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lintel {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

// Whether pixel (x, y)'s centre ray meets the mirror `portal` of `world` with no wall before it
// (the view's basis as path_tracer.h states it).
bool through_mirror(const World& world, const View& view, int portal, double x, double y) {
  const glm::dvec3 eye(view.eye_world), f = glm::normalize(glm::dvec3(view.target_world) - eye);
  const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(view.up_world))), u = glm::cross(s, f);
  const double t = std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
  const double nx = x / kWidth * 2.0 - 1.0, ny = 1.0 - y / kHeight * 2.0;
  const glm::dvec3 d = glm::normalize(f + nx * t * double(view.aspect) * s + ny * t * u);
  double t_hit = 0.0;
  return linked_portal_on_ray(world.portals, eye, d, 1e9, t_hit) == portal;
}

TEST(PathTracerLinkedPortal, MirrorShowsTheRoomAsSeenFromBehindIt) {
  World world;
  ASSERT_TRUE(build_world(generate_mirror({}), "mirror", world).ok());
  const int p = world.find_portal("mirror_west");
  ASSERT_GE(p, 0);
  const Portal& mirror = world.portals[size_t(p)];
  ASSERT_EQ(mirror.link, PortalLinkKind::Mirror);

  const glm::dvec3 eye(3.0, 1.3, 0.2), dir(-1.0, 0.0, 0.0);
  View a;
  a.eye_world = glm::vec3(eye);
  a.target_world = glm::vec3(eye + dir);
  a.aspect = float(kWidth) / float(kHeight);
  View b = a;
  const glm::dvec3 far_eye(mirror.link_world * glm::dvec4(eye, 1.0)), far_dir(mirror.link_world * glm::dvec4(dir, 0.0));
  b.eye_world = glm::vec3(far_eye);
  b.target_world = glm::vec3(far_eye + far_dir);

  PathTracer tracer;
  ASSERT_TRUE(tracer.build(world).ok());
  PathTraceOptions o;
  o.width = kWidth;
  o.height = kHeight;
  o.samples_per_pixel = 256;
  o.max_bounces = 0;
  LinearImage through, direct;
  tracer.render(a, o, through);
  tracer.render(b, o, direct);

  uint32_t interior = 0, close = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      // Well inside the mirror: the pixel's corners a pixel and a half out meet it too.
      bool inside = true;
      for (double dy : {-1.5, 0.5, 2.5})
        for (double dx : {-1.5, 0.5, 2.5}) inside = inside && through_mirror(world, a, p, x + dx, y + dy);
      if (!inside) continue;
      ++interior;
      const glm::vec3 ra = through.rgb[size_t(y) * kWidth + x], rb = direct.rgb[size_t(y) * kWidth + (kWidth - 1 - x)];
      const float scale = std::max({ra.r, ra.g, ra.b, rb.r, rb.g, rb.b, 1e-3f});
      const glm::vec3 d = glm::abs(ra - rb);
      close += std::max({d.r, d.g, d.b}) <= 0.10f * scale;
    }
  std::printf("mirror: %u interior pixels, %u within 10 %% of the direct view\n", interior, close);
  EXPECT_GT(interior, kWidth * kHeight / 10) << "the mirror should fill a good part of the frame";
  EXPECT_GE(close, interior * 95 / 100);
}

}  // namespace
}  // namespace lintel
