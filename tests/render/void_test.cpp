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
// About 35 s on the 2-core lavapipe machine under load (cottage 15 s, grid16 11 s, ring64 7 s).
#include "ray_hit_geometry.h"
#include "render_test_support.h"

#include <lintel/reference/ray_ground_truth.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
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

struct VoidCounts {
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
          ++counts.voids;
          const double edge = pixels_to_triangle_edge(world, f.view, hit, i, j, kResolution);
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
                          << "', that cell is " << (cell_in_set ? "in" : "NOT in") << " the portal visible set";
          }
        }
    }
  }
  std::printf(
      "%s: %llu frames (every %u-th) at %ux%u, %llu pixels hit geometry, %llu void, %llu of them excused "
      "(within %.4f px of an edge); %llu rim rays, %llu of them on background and hitting something, "
      "checked; %.0f ms\n",
      walk.file, (unsigned long long)counts.frames, walk.stride, kResolution, kResolution,
      (unsigned long long)counts.hit_pixels, (unsigned long long)counts.voids, (unsigned long long)counts.excused,
      kEdgeSlackPx, (unsigned long long)counts.rim_rays, (unsigned long long)counts.rim_rays_checked, now_ms() - t0);
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
