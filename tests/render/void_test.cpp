// Property ("no void"): along every committed timeline, no pixel is background where
// the ground truth sees geometry. Each scene in scenes/ is walked along each of its timelines
// (every Nth frame, N below, the viewer cell tracked through every frame), rendered at R x R
// with the timeline's aspect — so pixel (i, j)'s centre is exactly pixel_center_ndc(i, j, R),
// the point the Embree ray of RayGroundTruth::cast goes through — and every pixel whose ray hits
// a shell or an instance (hit cell != kNone) must have a surface in the g-buffer (cell id !=
// kNoCell). The ground truth ignores portals, so a cell the portal traversal or the GPU cull
// wrongly dropped shows up here as a void.
//
// RayGroundTruth::cast reports "rim rays" (within ~30 um of a portal edge in these scenes) as
// seeing nothing; here a background pixel whose ray cast() skipped that way is cast again
// without that rule (raw_pixel_hit) and checked like every other pixel, and counted.
//
// Excused, counted and printed: a void pixel whose centre lies within kEdgeSlackPx of the
// projected edge of the triangle its ray hit (the ray and the rasterizer decide a pixel centre
// on an edge with different rounding, ray_hit_geometry.h). No pixel farther from an edge is
// excused.
//
// Mirrors and teleports: the ground truth's rays stop at the wall a linked portal hangs on, while
// the renderer shows what lies beyond the link -- the sky, say, through a reflected window. A
// background pixel whose ray meets a linked portal's polygon (from its front, before or at the
// hit) is followed through the link with Embree (up to kMaxLinkDepth links): it is excused,
// counted apart, when the followed ray then hits nothing; when it hits a surface, the pixel is a
// void like any other, its edge distance measured from where the link shows that surface.
//
// About 35 s on the 2-core lavapipe machine under load (cottage 15 s, grid16 11 s, ring64 7 s).
#include "ray_hit_geometry.h"
#include "render_test_support.h"

#include <lintel/portal_link.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <string>

namespace lintel::render::test {
namespace {

constexpr uint32_t kResolution = 128;
// A void pixel is excused when its centre is within this many pixels of its triangle's projected
// edge: two steps of lavapipe's 8-bit sub-pixel grid, where the rasterizer snaps vertices.
constexpr double kEdgeSlackPx = 2.0 / 256.0;

struct Walk {
  const char* file;
  uint32_t stride;  // every Nth frame
};
// cottage: all 682 frames; grid16: 2058 -> 258 (256 rooms, 52 lamps: its frames cost most);
// ring64: 2059 -> 412.
constexpr Walk kWalks[] = {
    {"cottage.gltf", 1}, {"grid16.gltf", 8}, {"ring64.gltf", 5}, {"mirror.gltf", 4}, {"teleport.gltf", 6}};

// Pixel (i, j)'s ray followed through the linked portals it meets.
struct FollowedRay {
  RayHitId hit;           // the last hit beyond a link (kNone fields when it met no link or escaped)
  bool escaped = false;   // nothing hit beyond the links (a shell met from behind is not nothing)
  glm::dmat4 link{1.0};   // the links' product: where the eye sees the hit from
  double view_depth = 0;  // of the hit, along the (linked) ray
};
FollowedRay follow_links(const World& world, const RayGroundTruth& truth, const RayCamera& camera, uint32_t i,
                         uint32_t j, float first_depth) {
  FollowedRay out;
  glm::dvec3 o(camera.eye_world), d(pixel_ray_direction(camera, i, j, kResolution));
  double t_hit = first_depth, travelled = 0.0;
  for (uint32_t depth = 0; depth < kMaxLinkDepth; ++depth) {
    double t = 0.0;
    const int p = linked_portal_on_ray(world.portals, o, d, t_hit, t);
    if (p < 0) return out;
    const glm::dmat4& link = world.portals[size_t(p)].link_world;
    o = glm::dvec3(link * glm::dvec4(o + t * d, 1.0));
    d = glm::dvec3(link * glm::dvec4(d, 0.0));
    out.link = link * out.link;
    travelled += t;
    bool blocked = false;
    const RayHitId next =
        truth.cast_ray(glm::vec3(o), glm::vec3(d), 1e-4f, std::numeric_limits<float>::infinity(), &blocked);
    out.hit = next;
    out.view_depth = travelled + double(next.depth);
    if (next.cell == RayHitId::kNone) {
      out.escaped = !blocked;  // blocked: the followed ray left the building's interior; not excused
      return out;
    }
    t_hit = next.depth;
  }
  return out;
}

// The view from where the eye, seen through `link`, looks from: a mirror's turns the image over
// left to right (`flip`: pixel i is pixel R - 1 - i there).
View linked_view(const View& view, const glm::dmat4& link, bool& flip) {
  View v = view;
  v.eye_world = glm::vec3(link * glm::dvec4(glm::dvec3(view.eye_world), 1.0));
  v.target_world = glm::vec3(link * glm::dvec4(glm::dvec3(view.target_world), 1.0));
  v.up_world = glm::vec3(link * glm::dvec4(glm::dvec3(view.up_world), 0.0));
  flip = glm::determinant(glm::dmat3(link)) < 0.0;
  return v;
}

struct VoidCounts {
  uint64_t through_links = 0;  // background seen through a mirror or teleport, where the followed ray escapes
  uint64_t frames = 0, hit_pixels = 0, voids = 0, excused = 0;
  uint64_t rim_rays = 0, rim_rays_checked = 0;  // cast()'s rim rays; those on background pixels hitting something
};

class VoidTest : public ValidatedGpu, public ::testing::WithParamInterface<Walk> {};

TEST_P(VoidTest, NoBackgroundWhereTheGroundTruthHitsGeometry) {
  const Walk walk = GetParam();
  const double t0 = now_ms();
  World world;
  ASSERT_TRUE(load_committed_scene(walk.file, world));
  ASSERT_FALSE(world.timelines.empty()) << walk.file << " has no timeline";
  RayGroundTruth truth;
  ASSERT_TRUE(truth.build(world).ok());
  RenderOptions options = test_options(kResolution, kResolution);
  options.readback_cells = true;
  // What this test reads, the g-buffer's cell ids, does not depend on lighting: small shadow
  // maps and no GI keep the walk affordable (the golden and leak tests run the full lighting).
  options.shadow_resolution = 64;
  options.gi = false;
  std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world, options);
  ASSERT_NE(renderer, nullptr);
  VisibilityBuilder builder;
  VisibleSet visible;
  VoidCounts counts;
  uint32_t reported = 0;
  for (const Timeline& timeline : world.timelines) {
    for (const TimelineFrame& f : timeline_frames(world, timeline, walk.stride)) {
      RenderedFrame frame;
      const Status s = renderer->render(f.view, f.start_cell, frame);
      ASSERT_TRUE(s.ok()) << s.message();
      ASSERT_EQ(frame.cell_ids.size(), size_t(kResolution) * kResolution);
      const RayCamera camera = ray_camera(f.view);
      GroundTruth gt;
      truth.cast(camera, kResolution, gt);
      ++counts.frames;
      counts.rim_rays += gt.rim_pixels;
      for (uint32_t j = 0; j < kResolution; ++j)
        for (uint32_t i = 0; i < kResolution; ++i) {
          const size_t p = size_t(j) * kResolution + i;
          RayHitId hit = gt.pixels[p];
          if (hit.cell == RayHitId::kNone && frame.cell_ids[p] == kNoCell && gt.rim_pixels != 0) {
            hit = raw_pixel_hit(truth, camera, i, j, kResolution);  // a rim ray cast() skipped?
            counts.rim_rays_checked += hit.cell != RayHitId::kNone;
          }
          if (hit.cell == RayHitId::kNone) continue;
          ++counts.hit_pixels;
          if (frame.cell_ids[p] != kNoCell) continue;
          const FollowedRay followed = follow_links(world, truth, camera, i, j, hit.depth);
          const RayHitId& beyond = followed.hit;
          if (followed.escaped) {
            ++counts.through_links;
            continue;
          }
          ++counts.voids;
          double edge = 0.0;
          if (beyond.cell != RayHitId::kNone) {  // the surface beyond the link, from where the link shows it
            bool flip = false;
            const View seen = linked_view(f.view, followed.link, flip);
            RayHitId at = beyond;
            at.depth = float(followed.view_depth);
            edge = pixels_to_triangle_edge(world, seen, at, flip ? kResolution - 1 - i : i, j, kResolution);
          } else {
            edge = pixels_to_triangle_edge(world, f.view, hit, i, j, kResolution);
          }
          if (edge <= kEdgeSlackPx) {
            ++counts.excused;
            std::printf("  excused: %s '%s' frame %u pixel (%u, %u): centre %.4f px from its triangle's edge\n",
                        walk.file, timeline.name.c_str(), f.index, i, j, edge);
            continue;
          }
          if (reported++ < 10) {
            VisibilityOptions vo = options.visibility;
            vo.cull_instances = false;
            bool cell_in_set = false;
            if (builder.build(world, f.view, f.start_cell, vo, visible).ok())
              cell_in_set = std::any_of(visible.cells.begin(), visible.cells.end(),
                                        [&](const VisibleCell& c) { return c.cell == hit.cell; });
            ADD_FAILURE() << walk.file << " '" << timeline.name << "' frame " << f.index << " pixel (" << i << ", " << j
                          << "): background, but the ray hits cell '" << world.cells[hit.cell].name << "' "
                          << (hit.instance == RayHitId::kNone ? std::string("shell")
                                                              : "instance '" + world.instances[hit.instance].name + "'")
                          << " at depth " << hit.depth << " m, centre " << edge
                          << " px from its triangle's edge; viewer cell '" << world.cells[f.start_cell].name
                          << "', that cell is " << (cell_in_set ? "in" : "NOT in") << " the portal visible set"
                          << (beyond.cell == RayHitId::kNone
                                  ? std::string()
                                  : "; through a linked portal the ray goes on to cell '" +
                                        world.cells[beyond.cell].name + "' " +
                                        (beyond.instance == RayHitId::kNone
                                             ? std::string("shell")
                                             : "instance '" + world.instances[beyond.instance].name + "'") +
                                        " (the edge distance is measured there)");
          }
        }
    }
  }
  std::printf(
      "%s: %llu frames (every %u-th) at %ux%u, %llu pixels hit geometry, %llu void, %llu of them excused "
      "(within %.4f px of an edge); %llu rim rays, %llu of them on background and hitting something, "
      "checked; %llu background through mirrors or teleports (the followed ray escapes); %.0f ms\n",
      walk.file, (unsigned long long)counts.frames, walk.stride, kResolution, kResolution,
      (unsigned long long)counts.hit_pixels, (unsigned long long)counts.voids, (unsigned long long)counts.excused,
      kEdgeSlackPx, (unsigned long long)counts.rim_rays, (unsigned long long)counts.rim_rays_checked,
      (unsigned long long)counts.through_links, now_ms() - t0);
  EXPECT_GT(counts.frames, 20u);
  EXPECT_GT(counts.hit_pixels, counts.frames * kResolution * kResolution / 2) << "the walk should mostly see geometry";
  EXPECT_EQ(counts.voids, counts.excused);
}

// "Every committed timeline": a scene added to scenes/ with a timeline must be added to kWalks.
TEST(VoidTestCoverage, EveryCommittedSceneWithATimelineIsWalked) {
  const std::filesystem::path dir = std::filesystem::path(LINTEL_SOURCE_DIR) / "scenes";
  uint32_t with_timelines = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string(), file = entry.path().filename().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    World world;
    ASSERT_TRUE(load_committed_scene(file, world));
    if (world.timelines.empty()) continue;
    ++with_timelines;
    EXPECT_TRUE(std::any_of(std::begin(kWalks), std::end(kWalks), [&](const Walk& w) { return file == w.file; }))
        << "scenes/" << file << " has timelines but the void test does not walk it";
  }
  EXPECT_GE(with_timelines, 1u);
}

INSTANTIATE_TEST_SUITE_P(CommittedTimelines, VoidTest, ::testing::ValuesIn(kWalks),
                         [](const ::testing::TestParamInfo<Walk>& walk) {
                           std::string name = walk.param.file;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace lintel::render::test
