// Property tests of portal+hiz's occlusion (accuracy/src/hiz_method.cpp) on generated scenes with
// random camera paths (rapidcheck + the Embree ground truth). ctest runs a fixed seed and 300
// cases; LINTEL_SOAK=1 runs 5,000; RC_PARAMS overrides both. About 5 s on the 2-core machine.
#include <lintel/reference/bench_views.h>
#include <lintel/reference/cull_method.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/viewer_tracker.h>

#include <rapidcheck.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace {

using namespace lintel;

struct Scene {
  std::string label;
  World world;
  RayGroundTruth rays;
  std::vector<BenchView> views;
};

// Eight random buildings (13..20 cells, cell frames far from their rooms) and two grids, each with
// its sampled bench views: the ends of the camera paths.
std::vector<std::unique_ptr<Scene>>& pool() {
  static std::vector<std::unique_ptr<Scene>> scenes = [] {
    std::vector<std::unique_ptr<Scene>> out;
    for (uint64_t seed = 1; seed <= 8; ++seed) {
      auto s = std::make_unique<Scene>();
      RandomOptions o;
      o.seed = 900 + seed;
      o.cells = 12 + uint32_t(seed);
      s->label = "random --seed " + std::to_string(o.seed) + " --cells " + std::to_string(o.cells);
      if (!build_world(generate_random(o), s->label, s->world).ok() || !s->rays.build(s->world).ok()) std::abort();
      s->views = make_bench_views(s->world, s->rays, 24, seed);
      out.push_back(std::move(s));
    }
    // Grids of rooms with doors in line: furniture in rooms seen through rows of doors, where
    // occlusion has the most to cull.
    for (uint32_t n : {6u, 10u}) {
      auto s = std::make_unique<Scene>();
      s->label = "grid --width " + std::to_string(n) + " --height " + std::to_string(n);
      if (!build_world(generate_grid({n, n, false, 1}), s->label, s->world).ok() || !s->rays.build(s->world).ok())
        std::abort();
      s->views = make_bench_views(s->world, s->rays, 24, n);
      out.push_back(std::move(s));
    }
    return out;
  }();
  return scenes;
}

}  // namespace

uint64_t g_frames = 0, g_seen = 0, g_drawn = 0, g_occluded = 0;  // over all cases: the property was exercised

int main() {
  const bool soak = std::getenv("LINTEL_SOAK") != nullptr;
  if (!std::getenv("RC_PARAMS"))
    setenv("RC_PARAMS", soak ? "max_success=5000 seed=91" : "max_success=300 seed=20261127", 1);
  std::printf("building the scene pool...\n");
  pool();
  bool ok = true;

  // Occlusion never hides what a ray sees, in any frame of any camera path, whatever the frames
  // before it left: along a path from one sampled view to another (eye and target moving
  // linearly over 2..12 frames, the start cell tracked by portal crossings, so the camera moves,
  // turns and crosses portals, in big or small steps), every instance that the ground truth sees
  // (64 x 64 rays) and that the portal method alone draws is also drawn by portal+hiz, whose
  // history is the previous frame's. (Instances the portal method itself misses, e.g. with the
  // eye inside a wall on the way, are the portal method's and are not judged here.)
  ok &= rc::check("portal+hiz never culls an instance a ray sees, frame after frame", [] {
    const auto& scenes = pool();
    const Scene& s = *scenes[*rc::gen::inRange<size_t>(0, scenes.size())];
    RC_PRE(s.views.size() >= 2);
    const BenchView& a = s.views[*rc::gen::inRange<size_t>(0, s.views.size())];
    const BenchView& b = s.views[*rc::gen::inRange<size_t>(0, s.views.size())];
    const int frames = *rc::gen::inRange(2, 13);
    const uint32_t size = 1u << *rc::gen::inRange(5, 9);  // 32 .. 256 texels
    RC_LOG() << "scene: lintel gen " << s.label << ", " << frames << " frames at " << size << "^2\n";
    auto hiz = make_portal_hiz_method(size, HizHistory::Cut);  // Cut: the history is the previous run()'s
    auto polygon = make_polygon_method(1024, 16);
    ViewerTracker tracker;
    GroundTruth gt;
    MethodResult h, p;
    for (int f = 0; f <= frames; ++f) {
      const float t = float(f) / float(frames);
      View v = a.view;
      v.eye_world = a.view.eye_world + t * (b.view.eye_world - a.view.eye_world);
      v.target_world = a.view.target_world + t * (b.view.target_world - a.view.target_world);
      if (!validate_view(v)) continue;
      RC_ASSERT((f == 0 ? tracker.reset(s.world, v.eye_world) : tracker.update(s.world, v.eye_world)).ok());
      const uint32_t start = f == 0 ? a.start_cell : tracker.cell();
      RC_ASSERT(hiz->run(s.world, v, start, h).ok());
      RC_ASSERT(polygon->run(s.world, v, start, p).ok());
      s.rays.cast(ray_camera_of(v), 64, gt);
      ++g_frames;
      for (size_t i = 0; i < s.world.instances.size(); ++i) {
        g_seen += gt.instance_visible[i];
        g_drawn += p.instance_visible[i];
        g_occluded += p.instance_visible[i] && !h.instance_visible[i];
        if (gt.instance_visible[i] && p.instance_visible[i] && !h.instance_visible[i]) {
          RC_LOG() << "frame " << f << ": instance " << i << " (" << s.world.instances[i].name << ") culled, eye "
                   << v.eye_world.x << "," << v.eye_world.y << "," << v.eye_world.z << "\n";
          RC_FAIL("an instance a ray sees was occluded");
        }
      }
    }
  });

  std::printf("%llu frames: (frame, instance) pairs seen %llu, drawn by portals %llu, of those occluded %llu\n",
              (unsigned long long)g_frames, (unsigned long long)g_seen, (unsigned long long)g_drawn,
              (unsigned long long)g_occluded);
  if (g_occluded == 0) ok = false;  // the property must have been exercised
  return ok ? 0 : 1;
}
