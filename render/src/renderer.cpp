// One frame: CPU visibility, the active cells and lights, one submission of the render graph,
// readback.
#include "clip_volume.h"
#include "renderer_impl.h"

#include <lintel/gpu/vk_status.h>

#include <algorithm>
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
void Renderer::Impl::pick_frame_lights(const uint32_t* active) {
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
    const float d = light.type == Light::Type::Directional ? 0.0f : glm::length(light.position_world - view.eye_world);
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
  shadow_slots_for_frame(frame_lights, light_views.view_count, shadow_plan.slots, frame_slots);
  frame_shadow_views = 0;
  active_entries.clear();
  for (size_t i = 0; i < frame_lights.size(); ++i) {
    if (frame_slots[i] != kNoShadowSlot) frame_shadow_views += light_views.view_count[frame_lights[i]];
    active_entries.push_back(frame_lights[i]);
    active_entries.push_back(frame_slots[i]);
  }
  if (!active_entries.empty())
    std::memcpy(active_lights.mapped(), active_entries.data(), active_entries.size() * 4);
}

Status Renderer::render(const View& view, uint32_t start_cell, RenderedFrame& out) {
  Impl& m = *impl_;
  const auto t0 = std::chrono::steady_clock::now();
  if (Status s = validate_view(view); !s) return s;
  const World& world = m.scene.drawables;
  const uint32_t cell_count = uint32_t(world.cells.size());
  if (start_cell >= cell_count) return Status::error("start cell " + std::to_string(start_cell) + " out of range");
  m.view = view;
  m.view_proj = view_projection(view);
  const glm::dmat4 vp = view_projection_d(view);

  // The cells the camera draws from, by the chosen cull.
  std::vector<uint8_t>& drawn = m.drawn;
  drawn.assign(cell_count, 0);
  if (m.options.camera_cull == CameraCull::Portal) {
    VisibilityOptions vo = m.options.visibility;
    vo.cull_instances = false;  // the GPU culls the instances
    if (Status s = m.builder.build(world, view, start_cell, vo, m.visible); !s) return s;
    gpu::pack_visible_set(m.visible, view, cell_count, m.frame);
    for (const VisibleCell& c : m.visible.cells) drawn[c.cell] = 1;
  } else {
    m.frame.clear(cell_count, vp, view.eye_world);
    const std::vector<glm::vec2> no_polygons;
    for (uint32_t c = 0; c < cell_count; ++c) {
      if (m.options.camera_cull == CameraCull::Frustum && !box_may_meet_clip_volume(vp, m.cell_bounds_world[c])) continue;
      drawn[c] = 1;
      if (m.cull) m.frame.add_region(c, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f), std::span<const std::vector<glm::vec2>>());
    }
  }
  if (m.cull)
    if (Status s = m.cull->set_frame(m.frame); !s) return s;

  // GI and lights cover the drawn cells and their portal neighbours (light comes in through them).
  auto* active = static_cast<uint32_t*>(m.active_cells.mapped());
  std::memset(active, 0, size_t(cell_count) * 4);
  out.cells_drawn = 0;
  for (uint32_t c = 0; c < cell_count; ++c) {
    if (!drawn[c]) continue;
    ++out.cells_drawn;
    active[c] = 1;
    for (uint32_t n : m.cell_neighbours[c]) active[n] = 1;
  }
  m.pick_frame_lights(active);
  out.cpu_visibility_ms = ms_since(t0);

  if (Status s = m.ctx.submit_and_wait([&](VkCommandBuffer cmd) { m.graph.record(cmd, m.timestamps); }, "render frame");
      !s)
    return s;
  if (Status s = m.check_validation("render frame"); !s) return s;

  const uint32_t w = m.options.width, h = m.options.height;
  const size_t pixels = size_t(w) * h;
  out.width = w;
  out.height = h;
  out.rgba8.resize(pixels * 4);
  std::memcpy(out.rgba8.data(), m.ldr_readback.mapped(), pixels * 4);
  if (m.options.readback_hdr) {
    out.hdr.resize(pixels);
    std::memcpy(out.hdr.data(), m.hdr_readback.mapped(), pixels * 16);
  }
  if (m.options.readback_cells) {
    out.cell_ids.resize(pixels);
    std::memcpy(out.cell_ids.data(), m.cell_readback.mapped(), pixels * 4);
  }
  if (m.options.count_fragments) {
    out.fragment_counts.resize(world.instances.size());
    std::memcpy(out.fragment_counts.data(), m.counts_readback.mapped(), out.fragment_counts.size() * 4);
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
  out.unshadowed_lights = uint32_t(std::count(m.frame_slots.begin(), m.frame_slots.end(), kNoShadowSlot));
  out.wall_ms = ms_since(t0);
  return {};
}

}  // namespace lintel::render
