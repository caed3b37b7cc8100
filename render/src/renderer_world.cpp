// A world that changes between frames: doors (portal open state) and moved instances reach the
// renderer's copy of the world, its draw and cull records, and every light's reach, cell mask and
// shadow casters (a closed door is a wall for light as for sight).
#include "render_bindings.h"
#include "renderer_impl.h"
#include "vk_helpers.h"

#include <algorithm>

namespace lintel::render {

Status Renderer::Impl::rebuild_lights(std::span<const uint32_t> moved) {
  LightViewOptions lvo;
  lvo.shadow_resolution = options.shadow_resolution;
  LightViews before = std::move(light_views);
  if (Status s = build_light_views(scene, lvo, light_views); !s) return s;
  // A shadow map depends only on its view's matrix, its caster list and those casters' transforms:
  // a light keeps its cached layers unless one of them changed.
  std::vector<uint8_t> is_moved(scene.drawables.instances.size(), 0);
  for (uint32_t i : moved) is_moved[i] = 1;
  for (uint32_t l = 0; l < scene.drawables.lights.size(); ++l) {
    bool changed = before.view_count[l] != light_views.view_count[l];
    for (uint32_t k = 0; k < light_views.view_count[l] && !changed; ++k) {
      const ShadowView& a = before.views[before.first_view[l] + k];
      const ShadowView& b = light_views.views[light_views.first_view[l] + k];
      changed = a.world_to_clip != b.world_to_clip || a.casters != b.casters;
      for (uint32_t c : a.casters) changed = changed || is_moved[c];
    }
    if (!changed) continue;
    for (uint64_t& content : layer_content)
      if (content >> 8 == uint64_t(l) + 1) content = 0;
  }
  fill_gpu_lights();
  std::vector<glm::mat4> matrices;
  for (const ShadowView& v : light_views.views) matrices.push_back(v.world_to_clip);
  // The matrix buffer was made for every light's most views (create_static_buffers).
  if (matrices.size() * sizeof(glm::mat4) > shadow_matrices.size())
    return Status::internal("shadow views outgrew the matrix buffer");
  Status s = write_buffer(ctx, lights, 0, gpu_lights.data(), gpu_lights.size() * sizeof(GpuLight), "lights");
  if (s)
    s = write_buffer(ctx, shadow_matrices, 0, matrices.data(), matrices.size() * sizeof(glm::mat4), "shadow matrices");
  if (s)
    s = write_buffer(ctx, light_masks, 0, light_views.cell_mask.data(), light_views.cell_mask.size() * 4,
                     "light cell masks");
  if (!s) return s;
  // Opening a door can make the lists longer than any frame before: larger buffers, same binding.
  if (const uint32_t entries = light_list_entries(); entries > light_list_capacity) {
    if (Status e = create_light_lists(entries); !e) return e;
    std::vector<VkBufferView> views(slots());
    std::vector<VkWriteDescriptorSet> writes(slots());
    for (uint32_t k = 0; k < slots(); ++k) {
      views[k] = active_light_texels[k].handle();
      writes[k] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[k].dstSet = compute.sets[k];
      writes[k].dstBinding = kBindActiveLights;
      writes[k].descriptorCount = 1;
      writes[k].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
      writes[k].pTexelBufferView = &views[k];
    }
    vkUpdateDescriptorSets(ctx.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
  return shadow_pass.set_casters(ctx, scene, light_views);
}

Status Renderer::update_world(const World& world, std::span<const uint32_t> moved) {
  Impl& m = *impl_;
  bool doors_changed = false;
  // Host data only (no frame reads the drawables' World): safe while frames are in flight.
  if (Status s = update_render_scene(world, moved, m.scene, doors_changed); !s) return s;
  if (!doors_changed && moved.empty()) return {};
  if (!moved.empty()) m.one_sided = all_one_sided(m.scene);  // a mover may have turned mirrored
  vkDeviceWaitIdle(m.ctx.device());
  if (!moved.empty()) {
    const auto [lo, hi] = std::minmax_element(moved.begin(), moved.end());
    if (Status s = write_buffer(m.ctx, m.draw_instances, VkDeviceSize(*lo) * sizeof(GpuDrawInstance),
                                &m.scene.draw_instances[*lo], VkDeviceSize(*hi - *lo + 1) * sizeof(GpuDrawInstance),
                                "draw instances");
        !s)
      return s;
    // Every slot stages the new records: whichever slot records next applies them, and a later
    // slot re-applies the same records (no newer ones exist until the next update_world).
    if (m.cull)
      for (uint32_t k = 0; k < m.slots(); ++k)
        if (Status s = m.cull->update_instances(moved, m.scene.cull_scene, k); !s) return s;
    if (m.hiz)
      if (Status s = m.hiz->update_bounds(m.ctx, m.scene); !s) return s;
    // The frustum cull's cell boxes only grow (conservative).
    for (uint32_t i : moved) {
      const Instance& inst = m.scene.drawables.instances[i];
      m.cell_bounds_world[inst.cell].extend(inst.bounds_world);
    }
  }
  if (m.full())
    if (Status s = m.rebuild_lights(moved); !s) return s;
  // Probes kept between frames (gi_persist) hold light that came through doors now closed: they
  // start again from zero (a cell no longer active would otherwise keep showing it).
  if (doors_changed) m.gi_warm = false;  // the probes start again from zero below: a full frame next
  if (doors_changed && m.full() && m.options.gi && m.options.gi_persist)
    if (Status s = m.ctx.submit_and_wait(
            [&](VkCommandBuffer cmd) {
              memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
              const VkBufferCopy c{0, 0, m.probes.size()};
              vkCmdCopyBuffer(cmd, m.probes_initial.handle(), m.probes.handle(), 1, &c);
              memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
            },
            "reset probes");
        !s)
      return s;
  return m.check_validation("update world");
}

}  // namespace lintel::render
