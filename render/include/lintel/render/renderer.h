// The deferred renderer: per frame, the portal visibility picks the cells (CPU), the GPU cull
// writes the indirect draws, and a render graph runs
//   cull -> shadows -> g-buffer -> GTAO -> GI (surfel light, probe gather) x bounces
//        -> lighting -> exposure -> tonemap [-> readback]
// either headless into host memory (render(); PNG via image_io.h) or into a caller's command
// buffer (record_frame(), with frames in flight). The g-buffer is drawn only through the cull's
// vkCmdDrawIndexedIndirect commands. docs/rendering.md describes every pass.
//
//   std::unique_ptr<lintel::gpu::Context> ctx;   // lintel/gpu/context.h
//   lintel::gpu::Context::create({}, ctx);
//   std::unique_ptr<lintel::render::Renderer> r;
//   lintel::render::Renderer::create(*ctx, world, {}, r);
//   lintel::render::RenderedFrame frame;
//   r->render(view, start_cell, frame);           // frame.rgba8: width x height, row 0 at the top
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/render/gi_options.h>
#include <lintel/render/render_shared.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace lintel::render {

// Which cells the camera's draws come from.
enum class CameraCull {
  Portal,   // the portal visibility's cells and clip regions (Lintel's way)
  Frustum,  // every cell whose box meets the view frustum, whole-screen regions
  None,     // everything, every frame (no cull pass at all)
  // Portal, then two-phase hierarchical-Z occlusion of the camera's draws (niagara's scheme;
  // docs/rendering.md, "Occlusion inside visible cells"): what passed last frame's occlusion test
  // is drawn first, a depth pyramid is built from it, every draw is tested against it and the
  // newly visible are drawn second. The image is the Portal one; fewer instances are drawn.
  PortalHiz,
};

// Whether the camera's draws come from the portal visibility (Portal or PortalHiz).
inline bool portal_cull(CameraCull c) { return c == CameraCull::Portal || c == CameraCull::PortalHiz; }

// Which passes the graph runs.
enum class RenderPasses {
  All,      // cull, shadows, g-buffer, AO, GI, lighting, exposure, tonemap
  GBuffer,  // cull and g-buffer only: an engine lights the g-buffer itself (Renderer::image())
};

struct RenderOptions {
  uint32_t width = 640, height = 360;
  uint32_t view = kViewFinal;  // kViewAlbedo ... kViewAo: a debug view of one pass
  // Automatic exposure (exposure.comp): the frame's log-average luminance to middle grey, held
  // down so that only the brightest 0.5 % of lit pixels can reach white; `exposure` multiplies it. Off:
  // `exposure` is the absolute multiplier before tonemapping (the old fixed rule).
  bool auto_exposure = true;
  float exposure = 1.0f;
  bool gi = true;
  bool ao = true;
  GiOptions gi_options;
  // Keep the probes between frames (a walk converges over frames); off: every frame starts from
  // zero, so a frame depends only on its view (tests, references).
  bool gi_persist = false;
  uint32_t shadow_resolution = 512;
  // Keep shadow-map layers across frames: a light's layers are redrawn only when its views change
  // (a door in its reach), a caster in its reach moves (update_world), or it gets other layers of
  // the atlas. Off: every active light's shadow maps are drawn every frame.
  bool cache_shadow_maps = true;
  // Cap on the shadow atlas (MiB). The atlas is also kept within the device's limits
  // (maxImageArrayLayers, maxMemoryAllocationSize, a quarter of the heap); when the lights' views
  // do not fit, the resolution is halved, then lights past the atlas light unshadowed
  // (Renderer::setup_note(), RenderedFrame::unshadowed_lights; docs/rendering.md).
  uint32_t shadow_memory_budget_mib = 512;
  float ao_radius_m = 0.6f;
  uint32_t ao_slices = 3, ao_steps = 6;
  // GTAO on one pixel per 2x2 block, then a depth- and cell-aware upsample (about 4x cheaper);
  // off: every pixel.
  bool ao_half_resolution = true;
  CameraCull camera_cull = CameraCull::Portal;
  VisibilityOptions visibility;
  bool readback_hdr = false;     // fill RenderedFrame::hdr
  bool readback_cells = false;   // fill RenderedFrame::cell_ids
  bool count_fragments = false;  // fill RenderedFrame::fragment_counts (tests; slower)
  bool timestamps = true;        // per-pass GPU times where the device has timestamps
  // Frames the caller may have in flight at once (1..4; 2 for a game loop): every buffer the host
  // writes per frame (active lights and cells, the cull's frame data) has one copy per slot, so
  // record_frame(slot k) may run while the frame of slot k-1 executes.
  uint32_t frames_in_flight = 1;
  RenderPasses passes = RenderPasses::All;
};

// One of the renderer's images, for a caller that reads (or lights) it after record_frame().
// Emission (rgba16f, linear radiance of what surfaces give off by themselves: Mesh::emissive)
// belongs with the g-buffer: a caller lighting it adds it to its own lighting.
enum class RenderImage { Albedo, Normal, Cell, Depth, Hdr, Final, Emission };

// An image and the state the frame leaves it in: a caller that reads it after record_frame()
// waits for `stage`/`access` and transitions from `layout`. The renderer's next frame discards
// the contents (it starts from UNDEFINED after all earlier work), so the caller may leave the
// image in any layout.
struct ImageAccess {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
  uint32_t width = 0, height = 0;
};

struct PassTime {
  std::string name;
  double gpu_ms = 0.0;
};

struct RenderedFrame {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba8;  // width x height x 4, row 0 at the top, sRGB
  std::vector<glm::vec4> hdr;  // linear radiance (readback_hdr)
  // Per pixel: the surface's cell or kNoCell (readback_cells); seen through a mirror or teleport,
  // the cell | view transform << kCellLinkShift (render_shared.h).
  std::vector<uint32_t> cell_ids;
  std::vector<uint32_t> fragment_counts;  // per drawable (count_fragments)
  std::vector<PassTime> passes;           // GPU time per graph pass (timestamps)
  double cpu_visibility_ms = 0.0;         // portal visibility + frame packing on the CPU
  double wall_ms = 0.0;                   // the whole render() call
  uint32_t cells_drawn = 0;               // cells whose draws the camera cull took (linked ones included)
  uint32_t linked_draws = 0;              // drawables drawn through mirrors and teleports
  uint32_t gi_bounces = 0;                // GI iterations run (GiOptions::amortized_bounces)
  uint32_t active_lights = 0;             // lights whose shadows and light were computed
  uint32_t shadow_views = 0;              // shadow maps the frame's lights use
  uint32_t shadow_views_drawn = 0;        // of those, drawn this frame (the rest kept from earlier frames)
  uint32_t unshadowed_lights = 0;         // active lights that got no atlas slot (lit unshadowed)
  // CameraCull::PortalHiz: drawables drawn first (visible last frame), drawn second (newly
  // visible), tested against the depth pyramid (every draw of the portal cull) and not occluded.
  struct Occlusion {
    uint32_t drawn_early = 0, drawn_late = 0, tested = 0, passed = 0;
  } occlusion;
};

class Renderer {
 public:
  // Builds everything static: geometry, the cull, the lights' views and casters, the GI layout,
  // pipelines and the render graph. Errors: scene over the limits, Vulkan failures, a device too
  // small for even one shadow map (Unsupported); with a validated context, any validation message
  // raised while setting up (Internal), so a violation is reported where it happens.
  static Status create(gpu::Context& ctx, const World& world, const RenderOptions& options,
                       std::unique_ptr<Renderer>& out);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders `view` with the eye in `start_cell`. Errors: invalid view, Vulkan failures; with a
  // validated context, any validation message of this frame's submission (Internal).
  // Needs RenderPasses::All. Builds the visibility, records the frame into slot 0, reads back,
  // submits and waits.
  Status render(const View& view, uint32_t start_cell, RenderedFrame& out);
  // The same for the caller's `visible` (built for this world and `view`; CameraCull::Portal reads
  // it, the other camera culls ignore it): no second visibility build. Errors as record_frame.
  Status render(const VisibleSet& visible, const View& view, RenderedFrame& out);

  // Records the whole frame into `cmd` (no readback, no submit, no wait) for the caller's
  // `visible` (CameraCull::Portal; built for this world and `view`, instance culling optional:
  // the GPU culls the instances; ignored by the other camera culls). Host-side, it writes
  // `frame_slot`'s per-frame buffers, so the caller must know that slot's previous frame has
  // finished (its fence), and must submit frames in the order they were recorded. Errors: an
  // invalid view, a slot >= frames_in_flight, a visible set of another world (BadInput).
  Status record_frame(VkCommandBuffer cmd, const VisibleSet& visible, const View& view, uint32_t frame_slot);

  // One of the images (Hdr and Final need RenderPasses::All) and the state record_frame() leaves
  // it in. Errors: an image this pass set does not make.
  Status image(RenderImage which, ImageAccess& out) const;

  // Brings the renderer's copy of the world up to date after the caller changed `world` (the one
  // it was created from, or one of the same counts): door state (Portal::open_*, e.g. by
  // apply_timeline_events) and the instances `moved` since the last call (DynamicInstances::taken()).
  // Closed portals block light as they block sight: every light's reach, cell mask, shadow casters
  // and the GI's portal transport follow the doors. A door change or a move re-derives every
  // light's portal visibility (as at creation); moved instances get new draw and cull records.
  // Nothing to do (no door changed, nothing moved) costs one pass over the portals. Waits for
  // the device to be idle first (call it between frames). Errors: a world of other counts or a
  // moved index out of range (BadInput), Vulkan failures.
  Status update_world(const World& world, std::span<const uint32_t> moved);

  // Shows `view` (kViewFinal ... kViewAo) from the next frame on: the same graph, so a viewer or a
  // test can switch debug views without rebuilding the renderer. Errors: an unknown view.
  Status set_debug_view(uint32_t view);

  // The render graph's passes and what they read and write, one line each.
  std::string describe_graph() const;
  // Drawables = World instances followed by one shell per cell that has one.
  uint32_t drawable_count() const;
  uint32_t world_instance_count() const;
  // What the device limits changed at creation (empty when nothing): one line, for stderr/JSON.
  const std::string& setup_note() const;
  uint32_t shadow_resolution() const;  // as planned (<= RenderOptions::shadow_resolution)
  uint32_t shadow_slots() const;       // shadow-atlas layers: shadow views one frame can render
  uint32_t frames_in_flight() const;

 private:
  Status render_prepared(const VisibleSet* visible, const View& view, std::chrono::steady_clock::time_point t0,
                         RenderedFrame& out);
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace lintel::render
