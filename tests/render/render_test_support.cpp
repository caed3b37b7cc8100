// Scene loading, renderer creation and timeline walking for the renderer's tests.
#include "render_test_support.h"

#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include <gtest/gtest.h>

#include <chrono>

namespace lintel::render::test {

Texture block_checker(uint32_t side, uint32_t block, glm::u8vec4 even, glm::u8vec4 odd) {
  Texture t;
  t.name = "checker";
  t.width = t.height = side;
  t.rgba8.resize(size_t(side) * side * 4);
  for (uint32_t j = 0; j < side; ++j)
    for (uint32_t i = 0; i < side; ++i) {
      const glm::u8vec4 c = ((i / block) + (j / block)) % 2 ? odd : even;
      for (int k = 0; k < 4; ++k) t.rgba8[(size_t(j) * side + i) * 4 + size_t(k)] = c[k];
    }
  return t;
}

bool load_committed_scene(const std::string& file, World& out) {
  const std::string path = std::string(LINTEL_SOURCE_DIR) + "/scenes/" + file;
  const Status s = load_world(path, out);
  EXPECT_TRUE(s.ok()) << s.message();
  return s.ok();
}

RenderOptions test_options(uint32_t width, uint32_t height) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.timestamps = false;
  o.gi_persist = false;
  return o;
}

std::unique_ptr<Renderer> make_renderer(gpu::Context& ctx, const World& world, const RenderOptions& options) {
  std::unique_ptr<Renderer> r;
  const Status s = Renderer::create(ctx, world, options, r);
  EXPECT_TRUE(s.ok()) << s.message();
  return s.ok() ? std::move(r) : nullptr;
}

std::vector<TimelineFrame> timeline_frames(const World& world, const Timeline& timeline, uint32_t stride) {
  std::vector<TimelineFrame> out;
  ViewerTracker tracker;
  const size_t frames = timeline_frame_count(timeline);
  for (size_t f = 0; f < frames; ++f) {
    const View view = timeline_view(timeline, double(f) / timeline.fps);
    const Status s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world);
    EXPECT_TRUE(s.ok()) << timeline.name << " frame " << f << ": " << s.message();
    if (!s) return out;
    if (f % stride == 0) out.push_back({uint32_t(f), view, tracker.cell()});
  }
  return out;
}

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool advance_world(const Timeline& timeline, const std::vector<InstanceTrack>& tracks, double t, World& world,
                   DynamicInstances& movers, size_t& next_event) {
  next_event = apply_timeline_events(timeline, t, next_event, world);
  for (const InstanceTrack& track : tracks) {
    glm::mat4 m;
    if (!sample_instance_track(timeline, track, t, m) || m == world.instances[track.instance].mesh_to_world) continue;
    const Status s = movers.move(world, track.instance, m);
    EXPECT_TRUE(s.ok()) << s.message();
    if (!s) return false;
  }
  return true;
}

}  // namespace lintel::render::test
