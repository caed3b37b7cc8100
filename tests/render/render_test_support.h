// Shared by the renderer's GPU tests: committed scenes, a Renderer on the validated context of
// tests/gpu_cull/gpu_test_support.h (every validation message fails the test), and the frames
// of a timeline with the viewer's cell tracked through every frame, as `lintel walk` does.
#pragma once

#include "gpu_test_support.h"

#include <lintel/dynamic_instances.h>
#include <lintel/render/renderer.h>
#include <lintel/timeline.h>
#include <lintel/world.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lintel::render::test {

using gpu::test::ValidatedGpu;

// scenes/<file> of the source tree; fails the test (returns false) when it does not load.
bool load_committed_scene(const std::string& file, World& out);

// A side x side texture of block x block squares, `even` where (column block + row block) is
// even, `odd` elsewhere (RGBA8 as stored in the file).
Texture block_checker(uint32_t side, uint32_t block, glm::u8vec4 even, glm::u8vec4 odd);

// Options every test starts from: the given size, no timestamps (lavapipe's are unreliable and
// tests do not read them), every frame computed from its view alone (gi_persist off).
RenderOptions test_options(uint32_t width, uint32_t height);

// Creates a renderer; fails the test and returns null on an error.
std::unique_ptr<Renderer> make_renderer(gpu::Context& ctx, const World& world, const RenderOptions& options);

struct TimelineFrame {
  uint32_t index = 0;  // frame number (time = index / fps)
  View view;
  uint32_t start_cell = 0;  // the tracked viewer cell
};

// Every `stride`-th frame of `timeline` (frame 0 first), with the viewer cell followed by
// ViewerTracker across EVERY frame (so crossings are seen as the walk makes them).
std::vector<TimelineFrame> timeline_frames(const World& world, const Timeline& timeline, uint32_t stride);

// The world at time `t` of `timeline`, as a walk plays it: its door events from `next_event` on
// (advanced past them) and its tracked instances moved through `movers` (take_moved() lists
// them). Fails the test (returns false) when a move fails.
bool advance_world(const Timeline& timeline, const std::vector<InstanceTrack>& tracks, double t, World& world,
                   DynamicInstances& movers, size_t& next_event);

// Milliseconds since an arbitrary epoch (for the runtimes the tests print).
double now_ms();

}  // namespace lintel::render::test
