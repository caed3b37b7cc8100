// Rendering with Lintel in a client: a headless Vulkan context, a Renderer built once per scene,
// then one render() per frame with the viewer's cell (tracked by portal crossings, as a game
// would). Writes the middle frame of the scene's first timeline as a PNG.
// Usage: render_client <scene.gltf|.glb> <out.png> [--validate]
// --validate: Khronos validation with synchronization validation and GPU-assisted validation
// (ContextOptions::validation); any message fails the run (exit 1).
#include <lintel/gpu/context.h>
#include <lintel/render/image_io.h>
#include <lintel/render/renderer.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  const bool validate = argc == 4 && std::string(argv[3]) == "--validate";
  if (argc != 3 && !validate) {
    std::fprintf(stderr, "usage: %s <scene.gltf|.glb> <out.png> [--validate]\n", argv[0]);
    return 2;
  }
  lintel::World world;
  if (lintel::Status s = lintel::load_world(argv[1], world, nullptr); !s) {
    std::fprintf(stderr, "render_client: %s\n", s.message().c_str());
    return 2;
  }
  if (world.timelines.empty()) {
    std::fprintf(stderr, "render_client: %s has no timeline\n", argv[1]);
    return 2;
  }
  std::unique_ptr<lintel::gpu::Context> context;
  std::unique_ptr<lintel::render::Renderer> renderer;
  lintel::render::RenderOptions options;  // 640 x 360, shadows, GI, GTAO
  options.gi_persist = true;              // probes converge over the frames
  lintel::gpu::ContextOptions context_options;
  context_options.validation = validate;
  lintel::Status s = lintel::gpu::Context::create(context_options, context);
  if (s) s = lintel::render::Renderer::create(*context, world, options, renderer);
  if (!s) {
    std::fprintf(stderr, "render_client: %s\n", s.message().c_str());
    return 1;
  }
  const lintel::Timeline& timeline = world.timelines.front();
  const size_t frames = lintel::timeline_frame_count(timeline);
  lintel::ViewerTracker tracker;
  lintel::render::RenderedFrame frame;
  // Track every frame (the tracker needs the path); render the last few before the middle.
  for (size_t f = 0; f <= frames / 2; ++f) {
    lintel::View view = lintel::timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    view.aspect = float(options.width) / float(options.height);
    s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world);
    if (s && f + 3 > frames / 2) s = renderer->render(view, tracker.cell(), frame);
    if (!s) {
      std::fprintf(stderr, "render_client: frame %zu: %s\n", f, s.message().c_str());
      return 1;
    }
  }
  if (s = lintel::render::write_png(argv[2], {frame.width, frame.height, frame.rgba8}); !s) {
    std::fprintf(stderr, "render_client: %s\n", s.message().c_str());
    return 2;
  }
  const std::vector<std::string> messages = context->take_validation_messages();
  for (const std::string& m : messages) std::fprintf(stderr, "render_client: validation: %s\n", m.c_str());
  if (!messages.empty()) return 1;
  std::printf("rendered %ux%u on %s: %u cells drawn, %u lights, %.1f ms\n", frame.width, frame.height,
              context->info().name.c_str(), frame.cells_drawn, frame.active_lights, frame.wall_ms);
  return 0;
}
