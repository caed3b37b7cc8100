// Property: the g-buffer draws what is seen and nothing the portal visibility excluded. Along the
// cottage's doorway timeline (every Nth frame, R x R with the timeline's aspect), with
// RenderOptions::count_fragments:
//   * every drawable the Embree ground truth sees has fragments — each World instance some ray
//     hits, and each cell whose shell some ray hits (shell drawables follow the World's
//     instances, render_scene.h). This is also the firstInstance check of LESSONS.md: draw
//     groups with a non-zero base must rasterize, and the frames below cover many groups;
//   * no drawable has a fragment when the portal visibility reached none of the cells its box
//     reaches (instance_reach.h: its own cell, plus the neighbours a large box pokes into through
//     portals; the cull draws a drawable only from those cells).
// Fragments are counted before the depth test (the fragment shader writes a buffer, so it runs
// for every covered sample), so an occluded but GT-visible drawable still counts — the check is
// about rasterization, not about who wins the depth test.
// "Seen" includes what RayGroundTruth::cast's rim rays (within ~30 um of a portal edge) hit: they
// are cast again without that rule (raw_pixel_hit), so nothing is skipped.
// Excused and counted: a seen drawable without fragments whose every hit pixel lies within
// kEdgeSlackPx of its triangle's projected edge (ray vs raster rounding on a pixel centre).
// About 8 s on the 2-core lavapipe machine.
#include "ray_hit_geometry.h"
#include "render_test_support.h"

#include <lintel/instance_reach.h>
#include <lintel/reference/ray_ground_truth.h>
#include "render_scene.h"
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <set>

namespace lintel::render::test {
namespace {

constexpr uint32_t kResolution = 128;
constexpr uint32_t kStride = 2;               // 683 frames -> 342
constexpr double kEdgeSlackPx = 2.0 / 256.0;  // as in void_test.cpp

class FragmentsTest : public ValidatedGpu {};

TEST_F(FragmentsTest, SeenDrawablesRasterizeAndUnreachedCellsDoNot) {
  const double t0 = now_ms();
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  const int walk = world.find_timeline("doorway");
  ASSERT_GE(walk, 0);
  RenderScene scene;  // the renderer's drawables, to map shells back to their cells
  ASSERT_TRUE(build_render_scene(world, scene).ok());
  const uint32_t drawables = uint32_t(scene.drawables.instances.size());
  std::vector<uint32_t> shell_of_cell(world.cells.size(), std::numeric_limits<uint32_t>::max());
  for (uint32_t d = scene.world_instance_count; d < drawables; ++d)
    shell_of_cell[scene.drawables.instances[d].cell] = d;

  RayGroundTruth truth;
  ASSERT_TRUE(truth.build(world).ok());
  RenderOptions options = test_options(kResolution, kResolution);
  options.count_fragments = true;
  options.shadow_resolution = 64;  // the counts come from the g-buffer pass alone (as void_test.cpp)
  options.gi = false;
  std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world, options);
  ASSERT_NE(renderer, nullptr);
  ASSERT_EQ(renderer->drawable_count(), drawables);
  ASSERT_EQ(renderer->world_instance_count(), scene.world_instance_count);

  VisibilityBuilder builder;
  VisibleSet visible;
  VisibilityOptions vo = options.visibility;
  vo.cull_instances = false;  // as the renderer asks it: the GPU culls the instances
  uint64_t frames = 0, seen = 0, excused = 0, unreached = 0, rim_rays = 0;
  InstanceReach reach;  // the cells each drawable may be drawn from (the cull's rule)
  reach.compute(scene.drawables);
  std::set<uint32_t> groups_drawn;
  for (const TimelineFrame& f : timeline_frames(world, world.timelines[size_t(walk)], kStride)) {
    RenderedFrame frame;
    ASSERT_TRUE(renderer->render(f.view, f.start_cell, frame).ok());
    ASSERT_EQ(frame.fragment_counts.size(), drawables);
    const RayCamera camera = ray_camera(f.view);
    GroundTruth gt;
    truth.cast(camera, kResolution, gt);
    ++frames;
    rim_rays += gt.rim_pixels;

    // Per drawable: seen by some ray, and (when it has no fragments) the largest distance of its
    // hits from a triangle edge.
    std::vector<uint8_t> seen_now(drawables, 0);
    std::vector<double> farthest_from_edge(drawables, 0.0);
    for (uint32_t j = 0; j < kResolution; ++j)
      for (uint32_t i = 0; i < kResolution; ++i) {
        RayHitId hit = gt.pixels[size_t(j) * kResolution + i];
        if (hit.cell == RayHitId::kNone && gt.rim_pixels != 0) hit = raw_pixel_hit(truth, camera, i, j, kResolution);
        if (hit.cell == RayHitId::kNone) continue;
        const uint32_t d = hit.instance != RayHitId::kNone ? hit.instance : shell_of_cell[hit.cell];
        ASSERT_LT(d, drawables);
        seen_now[d] = 1;
        if (frame.fragment_counts[d] != 0 || farthest_from_edge[d] > kEdgeSlackPx) continue;
        const double edge = pixels_to_triangle_edge(world, f.view, hit, i, j, kResolution);
        farthest_from_edge[d] = std::max(farthest_from_edge[d], edge);
      }
    for (uint32_t d = 0; d < drawables; ++d) {
      if (frame.fragment_counts[d] != 0) groups_drawn.insert(scene.drawables.instances[d].group);
      seen += seen_now[d];
      if (!seen_now[d] || frame.fragment_counts[d] != 0) continue;
      if (farthest_from_edge[d] <= kEdgeSlackPx) {
        ++excused;
        std::printf("  excused: frame %u drawable '%s': every hit within %.4f px of its triangle's edge\n", f.index,
                    scene.drawables.instances[d].name.c_str(), farthest_from_edge[d]);
        continue;
      }
      ADD_FAILURE() << "frame " << f.index << ": drawable " << d << " '" << scene.drawables.instances[d].name
                    << "' (cell '" << world.cells[scene.drawables.instances[d].cell].name
                    << "') is seen by the ground truth but produced no fragments";
    }

    ASSERT_TRUE(builder.build(world, f.view, f.start_cell, vo, visible).ok());
    std::vector<uint8_t> reached(world.cells.size(), 0);
    for (const VisibleCell& c : visible.cells) reached[c.cell] = 1;
    for (uint32_t d = 0; d < drawables; ++d) {
      const uint32_t cell = scene.drawables.instances[d].cell;
      if (std::any_of(reach.begin(d), reach.end(d), [&](uint32_t c) { return reached[c] != 0; })) continue;
      ++unreached;
      EXPECT_EQ(frame.fragment_counts[d], 0u)
          << "frame " << f.index << ": drawable '" << scene.drawables.instances[d].name << "' of cell '"
          << world.cells[cell].name << "', none of whose reached cells the "
          << "portal visibility reached, was drawn";
    }
  }
  std::printf(
      "cottage doorway: %llu frames (every %u-th) at %ux%u; %llu seen drawables checked drawn (%llu "
      "excused; %llu rim rays cast again); %zu draw groups produced fragments; %llu drawables of unreached "
      "cells checked undrawn; %.0f ms\n",
      (unsigned long long)frames, kStride, kResolution, kResolution, (unsigned long long)seen,
      (unsigned long long)excused, (unsigned long long)rim_rays, groups_drawn.size(), (unsigned long long)unreached,
      now_ms() - t0);
  EXPECT_GT(frames, 20u);
  EXPECT_GT(groups_drawn.size(), 10u) << "the walk should draw many groups (most with a non-zero base)";
  EXPECT_GT(unreached, 0u) << "the walk should have frames where some cells are out of reach";
}

}  // namespace
}  // namespace lintel::render::test
