// One frame: the active cells and lights from a visible set, the graph recorded into a caller's
// command buffer (record_frame) or into one submission with readback (render).
#include "clip_volume.h"
#include "renderer_impl.h"

#include "vk_status.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstring>

namespace lintel::render {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

Status Renderer::create(gpu::Context& ctx, const World& world, const RenderOptions& options,
                        std::unique_ptr<Renderer>& out) {
  auto impl = std::make_unique<Impl>(ctx);
  if (Status s = impl->setup(world, options); !s) return s;
  out.reset(new Renderer(std::move(impl)));
  return {};
}

std::string Renderer::describe_graph() const { return impl_->graph.describe(); }

Status Renderer::set_debug_view(uint32_t view) {
  if (view > kViewAo) return Status::error("debug view " + std::to_string(view) + " does not exist");
  impl_->options.view = view;
  return {};
}
uint32_t Renderer::drawable_count() const { return uint32_t(impl_->scene.drawables.instances.size()); }
uint32_t Renderer::world_instance_count() const { return impl_->scene.world_instance_count; }
const std::string& Renderer::setup_note() const { return impl_->shadow_plan.note; }
uint32_t Renderer::shadow_resolution() const { return impl_->shadow_plan.resolution; }
uint32_t Renderer::shadow_slots() const { return impl_->shadow_plan.slots; }
uint32_t Renderer::frames_in_flight() const { return impl_->options.frames_in_flight; }

Status Renderer::image(RenderImage which, ImageAccess& out) const {
  const Impl& m = *impl_;
  struct Entry {
    const GpuImage* image;
    ResourceId id;
  };
  const Entry entries[] = {{&m.gbuffer.albedo, m.albedo_id},
                           {&m.gbuffer.normal, m.normal_id},
                           {&m.gbuffer.cell_ids, m.cell_id},
                           {&m.gbuffer.depth, m.depth_id},
                           {&m.hdr, m.hdr_id},
                           {&m.ldr, m.ldr_id},
                           {&m.gbuffer.emission, m.emission_id}};  // RenderImage order
  const GpuImage* img = entries[size_t(which)].image;
  const ResourceId id = entries[size_t(which)].id;
  if (id.index == UINT32_MAX) return Status::error("this renderer's passes (RenderPasses::GBuffer) make no such image");
  const ResourceState st = m.graph.state_after_frame(id);
  out = {img->handle(), img->view(), img->desc().format, st.layout,
         st.stage,      st.access,   img->desc().width,  img->desc().height};
  return {};
}

Status Renderer::Impl::check_validation(const char* step) {
  if (!ctx.validation()) return {};
  const std::vector<std::string> messages = ctx.take_validation_messages();
  if (messages.empty()) return {};
  return Status::internal(std::string("validation (") + step + "): " + messages.front() +
                          (messages.size() > 1 ? " (and " + std::to_string(messages.size() - 1) + " more)" : ""));
}

// Active lights: those whose cell mask meets the active cells (a word-wise AND). Ordered so that
// when the shadow atlas cannot hold them all, the ones that matter most keep their shadows: lights
// reaching a drawn cell before those reaching only a neighbour, then nearest to the eye first
// (the sun counts as nearest).
void Renderer::Impl::pick_frame_lights(const uint32_t* active, uint32_t slot) {
  const World& world = scene.drawables;
  const uint32_t cell_count = uint32_t(world.cells.size());
  const uint32_t words = light_views.words_per_light;
  drawn_words.assign(words, 0u);
  active_words.assign(words, 0u);
  for (uint32_t c = 0; c < cell_count; ++c) {
    if (active[c]) active_words[c / 32] |= 1u << (c % 32);
    if (drawn[c]) drawn_words[c / 32] |= 1u << (c % 32);
  }
  std::vector<LightCandidate>& candidates = light_candidates;
  candidates.clear();
  for (uint32_t l = 0; l < world.lights.size(); ++l) {
    const uint32_t* mask = &light_views.cell_mask[size_t(l) * words];
    bool reaches = false, reaches_drawn = false;
    for (uint32_t w = 0; w < words; ++w) {
      reaches = reaches || (mask[w] & active_words[w]) != 0;
      reaches_drawn = reaches_drawn || (mask[w] & drawn_words[w]) != 0;
    }
    if (!reaches) continue;
    const Light& light = world.lights[l];
    const float d =
        light.type == Light::Type::Directional ? 0.0f : glm::length(light.position_world - frame.view.eye_world);
    candidates.push_back({!reaches_drawn, d, l});
  }
  // std::sort with the light index as the last key: the stable order, without stable_sort's
  // temporary buffer (no allocation per frame).
  std::sort(candidates.begin(), candidates.end(), [](const LightCandidate& a, const LightCandidate& b) {
    if (a.neighbour_only != b.neighbour_only) return !a.neighbour_only;
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.light < b.light;
  });
  frame_lights.clear();
  for (const LightCandidate& c : candidates) frame_lights.push_back(c.light);
  held_slot.resize(world.lights.size(), kNoShadowSlot);
  layer_content.resize(shadow_plan.slots, 0);
  if (options.cache_shadow_maps)
    shadow_slots_stable(frame_lights, light_views.view_count, shadow_plan.slots, held_slot, slot_scratch, frame_slots);
  else
    shadow_slots_for_frame(frame_lights, light_views.view_count, shadow_plan.slots, frame_slots);
  // A light's layers are drawn unless they already hold its views (drawn in an earlier frame into
  // these slots, and not forgotten since by a change of its views or a move of one of its casters).
  frame_shadow_views = 0;
  frame_shadow_views_drawn = 0;
  frame_redraw.assign(frame_lights.size(), 0);
  for (size_t i = 0; i < frame_lights.size(); ++i) {
    if (frame_slots[i] == kNoShadowSlot) continue;
    const uint32_t l = frame_lights[i], n = light_views.view_count[l];
    frame_shadow_views += n;
    bool cached = options.cache_shadow_maps;
    for (uint32_t k = 0; k < n && cached; ++k) cached = layer_content[frame_slots[i] + k] == light_layer_code(l, k);
    if (cached) continue;
    frame_redraw[i] = 1;
    frame_shadow_views_drawn += n;
    for (uint32_t k = 0; k < n; ++k) layer_content[frame_slots[i] + k] = light_layer_code(l, k);
  }

  // Per active cell, the frame's lights that reach it, in the frame's order: the shaders loop over
  // their cell's list only, adding the same lights in the same order as a loop over every active
  // light with a mask test would (so the image is the same, bit for bit).
  active_entries.assign(size_t(cell_count) * 2, 0u);
  for (uint32_t c = 0; c < cell_count; ++c) {
    if (!active[c]) continue;
    const uint32_t first = uint32_t(active_entries.size() / 2);
    for (size_t i = 0; i < frame_lights.size(); ++i) {
      const uint32_t* mask = &light_views.cell_mask[size_t(frame_lights[i]) * words];
      if (!((mask[c / 32] >> (c % 32)) & 1u)) continue;
      active_entries.push_back(frame_lights[i]);
      active_entries.push_back(frame_slots[i]);
    }
    active_entries[2 * c] = first;
    active_entries[2 * c + 1] = uint32_t(active_entries.size() / 2) - first;
  }
  // Each list entry is one set bit of a light's mask: light_list_entries() bounds them.
  assert(active_entries.size() / 2 <= size_t(cell_count) + light_list_capacity);
  std::memcpy(active_lights[slot].mapped(), active_entries.data(), active_entries.size() * 4);
}

uint32_t Renderer::Impl::choose_gi_bounces(const uint32_t* active, uint32_t cell_count) {
  const GiOptions& go = options.gi_options;
  if (!options.gi || !options.gi_persist || go.amortized_bounces == 0) return go.bounces;
  bool cold = !gi_warm || gi_prev_active.size() != cell_count;
  for (uint32_t c = 0; c < cell_count && !cold; ++c) cold = active[c] && !gi_prev_active[c];
  gi_prev_active.assign(active, active + cell_count);
  gi_warm = true;
  return cold ? go.bounces : std::min(go.amortized_bounces, go.bounces);
}

Status Renderer::Impl::prepare_frame(const VisibleSet* visible_set, const View& view, uint32_t slot) {
  if (Status s = validate_view(view); !s) return s;
  const World& world = scene.drawables;
  const uint32_t cell_count = uint32_t(world.cells.size());
  frame.view = view;
  frame.view_proj = view_projection(view);
  frame.slot = slot;
  frame.debug_view = options.view;
  frame.one_sided = one_sided;
  const glm::dmat4 vp = view_projection_d(view);

  // The cells the camera draws from, by the chosen cull.
  drawn.assign(cell_count, 0);
  if (portal_cull(options.camera_cull)) {
    const VisibleSet& vs = *visible_set;
    if (vs.slot_of_cell.size() != cell_count)
      return Status::error("visible set covers " + std::to_string(vs.slot_of_cell.size()) + " cells; the world has " +
                           std::to_string(cell_count));
    for (const VisibleCell& c : vs.cells)
      if (c.cell >= cell_count)
        return Status::error("visible set names cell " + std::to_string(c.cell) + " out of range");
    gpu::pack_visible_set(vs, view, cell_count, cull_frame);
    for (const VisibleCell& c : vs.cells) drawn[c.cell] = 1;
    // Cells seen through mirrors and teleports are drawn too (lit where they are: their lights
    // and probes must be active).
    if (Status s = linked.prepare(scene, vs, view, options.width, options.height, slot); !s) return s;
    for (const VisibleCell& c : vs.linked_cells) drawn[c.cell] = 1;
  } else {
    cull_frame.clear(cell_count, vp, view.eye_world);
    for (uint32_t c = 0; c < cell_count; ++c) {
      if (options.camera_cull == CameraCull::Frustum && !box_may_meet_clip_volume(vp, cell_bounds_world[c])) continue;
      drawn[c] = 1;
      if (cull)
        cull_frame.add_region(c, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f), std::span<const std::vector<glm::vec2>>());
    }
  }
  if (cull)
    if (Status s = cull->set_frame(cull_frame, slot); !s) return s;

  // GI and lights cover the drawn cells and the neighbours whose light can come in through an open
  // portal (the neighbour sees into the drawn cell: a portal surfel of the drawn cell reads the
  // neighbour's probes).
  auto* active = static_cast<uint32_t*>(active_cells[slot].mapped());
  std::memset(active, 0, size_t(cell_count) * 4);
  // After the cells, each portal's door state per direction (the GI's portal surfels read it).
  for (size_t p = 0; p < world.portals.size(); ++p) {
    active[cell_count + 2 * p] = world.portals[p].open_from_to ? 1u : 0u;
    active[cell_count + 2 * p + 1] = world.portals[p].open_to_from ? 1u : 0u;
  }
  cells_drawn = 0;
  for (uint32_t c = 0; c < cell_count; ++c) {
    if (!drawn[c]) continue;
    ++cells_drawn;
    active[c] = 1;
    for (const PortalLink& link : world.cells[c].links)
      if (world.portal_open(link.portal, world.portals[link.portal].from == link.neighbour ? PortalDirection::FromTo
                                                                                           : PortalDirection::ToFrom))
        active[link.neighbour] = 1;
  }
  pick_frame_lights(active, slot);
  frame.gi_bounces = choose_gi_bounces(active, cell_count);
  frame.lights = frame_lights;
  frame.light_slots = frame_slots;
  frame.light_redraw = frame_redraw;
  const LinkedFrame lf = linked.frame(slot);
  frame.linked_set = lf.set;
  frame.linked_commands = lf.commands;
  frame.linked_views = portal_cull(options.camera_cull) ? lf.views : std::span<const LinkedViewDraw>();
  return {};
}

Status Renderer::record_frame(VkCommandBuffer cmd, const VisibleSet& visible, const View& view, uint32_t frame_slot) {
  Impl& m = *impl_;
  if (frame_slot >= m.slots())
    return Status::error("frame slot " + std::to_string(frame_slot) + " is outside 0.." +
                         std::to_string(m.slots() - 1) + " (RenderOptions::frames_in_flight)");
  if (Status s = m.prepare_frame(&visible, view, frame_slot); !s) return s;
  RecordOptions ro;
  ro.slot = frame_slot;
  ro.timestamps = m.timestamps;
  ro.first_query = uint32_t(2 * m.graph.pass_count() * frame_slot);
  m.graph.record(cmd, ro);
  return {};
}

Status Renderer::render(const View& view, uint32_t start_cell, RenderedFrame& out) {
  Impl& m = *impl_;
  const auto t0 = std::chrono::steady_clock::now();
  if (!m.full()) return Status::error("render() needs RenderPasses::All; record_frame() draws the g-buffer alone");
  if (Status s = validate_view(view); !s) return s;
  const World& world = m.scene.drawables;
  const uint32_t cell_count = uint32_t(world.cells.size());
  if (start_cell >= cell_count) return Status::error("start cell " + std::to_string(start_cell) + " out of range");
  if (portal_cull(m.options.camera_cull)) {
    VisibilityOptions vo = m.options.visibility;
    vo.cull_instances = false;  // the GPU culls the instances
    if (Status s = m.builder.build(world, view, start_cell, vo, m.visible); !s) return s;
  }
  return render_prepared(&m.visible, view, t0, out);
}

Status Renderer::render(const VisibleSet& visible, const View& view, RenderedFrame& out) {
  Impl& m = *impl_;
  const auto t0 = std::chrono::steady_clock::now();
  if (!m.full()) return Status::error("render() needs RenderPasses::All; record_frame() draws the g-buffer alone");
  if (Status s = validate_view(view); !s) return s;
  return render_prepared(&visible, view, t0, out);
}

Status Renderer::render_prepared(const VisibleSet* visible, const View& view, std::chrono::steady_clock::time_point t0,
                                 RenderedFrame& out) {
  Impl& m = *impl_;
  if (Status s = m.prepare_frame(visible, view, 0); !s) return s;
  out.cells_drawn = m.cells_drawn;
  out.gi_bounces = m.options.gi ? m.frame.gi_bounces : 0;
  out.linked_draws = portal_cull(m.options.camera_cull) ? m.linked.record_count(0) : 0;
  out.cpu_visibility_ms = ms_since(t0);

  RecordOptions ro;
  ro.timestamps = m.timestamps;
  ro.readback = true;
  if (Status s = m.ctx.submit_and_wait([&](VkCommandBuffer cmd) { m.graph.record(cmd, ro); }, "render frame"); !s)
    return s;
  if (Status s = m.check_validation("render frame"); !s) return s;
  m.readback_pass.read(m.options.width, m.options.height, out);
  if (m.hiz) {
    const HizStats h = m.hiz->read_stats();
    out.occlusion = {h.drawn_early, h.drawn_late, h.tested, h.passed};
  }
  out.passes.clear();
  if (m.timestamps) {
    const uint32_t n = uint32_t(2 * m.graph.pass_count());
    std::vector<uint64_t> ticks(n);
    if (Status s = gpu::vk_check(vkGetQueryPoolResults(m.ctx.device(), m.timestamps, 0, n, n * 8, ticks.data(), 8,
                                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                                 "vkGetQueryPoolResults", "render timestamps");
        !s)
      return s;
    const double period_ms = double(m.ctx.info().timestamp_period_ns) * 1e-6;
    for (size_t p = 0; p < m.graph.pass_count(); ++p)
      out.passes.push_back({m.graph.pass_name(p), double(ticks[2 * p + 1] - ticks[2 * p]) * period_ms});
  }
  out.active_lights = uint32_t(m.frame_lights.size());
  out.shadow_views = m.frame_shadow_views;
  out.shadow_views_drawn = m.frame_shadow_views_drawn;
  out.unshadowed_lights = uint32_t(std::count(m.frame_slots.begin(), m.frame_slots.end(), kNoShadowSlot));
  out.wall_ms = ms_since(t0);
  return {};
}

}  // namespace lintel::render
