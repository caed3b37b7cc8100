// The cull pass: buffers, descriptors, and the recorded sequence
//   barrier after the previous frame -> frame copy, instance updates, counter reset -> cull
//   dispatch(es) -> finalize -> (optional) barrier to indirect/vertex reads.
// GPU-driven culling as in niagara (zeux) and "GPU-Driven Rendering Pipelines" (Haar & Aaltonen,
// SIGGRAPH 2015): survivors append their id to their group's range; one command per group.
#include <lintel/gpu/cull_pass.h>

#include "shader_pipeline.h"
#include "cull_pass_internal.h"
#include "lintel_gpu_cull_spirv.h"
#include "vk_status.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <string>

namespace lintel::gpu {

Status CullPass::create(Context& ctx, const CullPassOptions& options, std::unique_ptr<CullPass>& out) {
  out.reset();
  assert(options.instances_per_dispatch > 0 && options.instances_per_dispatch <= kMaxInstancesPerDispatch &&
         options.instances_per_dispatch % kCullWorkgroupSize == 0);
  assert(options.frames_in_flight >= 1 && options.frames_in_flight <= kMaxFramesInFlight);
  assert(options.work_per_dispatch >= 1 && options.work_per_dispatch <= kMaxWorkPerDispatch);
  std::unique_ptr<CullPass> pass(new CullPass(ctx, options));
  pass->slots_.resize(options.frames_in_flight);
  pass->append_ = options.append;
  if (options.append == CullAppend::Auto)
    pass->append_ = ctx.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU ? CullAppend::Atomic : CullAppend::Subgroup;
  if (pass->append_ == CullAppend::Subgroup && !ctx.info().subgroup_ballot) pass->append_ = CullAppend::Atomic;
  pass->defer_straddlers_ =
      options.straddlers == CullStraddlers::Deferred ||
      (options.straddlers == CullStraddlers::Auto && ctx.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU);
  if (Status s = pass->create_pipelines(); !s) return s;
  if (options.timestamps && ctx.info().timestamps) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * options.frames_in_flight;
    if (Status s = vk_check(vkCreateQueryPool(ctx.device(), &info, nullptr, &pass->timestamps_), "vkCreateQueryPool",
                            "cull timestamps");
        !s)
      return s;
  }
  out = std::move(pass);
  return {};
}

Status CullPass::create_pipelines() {
  VkDevice device = ctx_.device();
  VkDescriptorSetLayoutBinding bindings[detail::kBindingCount];
  for (uint32_t b = 0; b < detail::kBindingCount; ++b) {
    bindings[b] = {};
    bindings[b].binding = b;
    bindings[b].descriptorType =
        b == detail::kInstances ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[b].descriptorCount = 1;
    bindings[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = detail::kBindingCount;
  set_info.pBindings = bindings;
  if (Status s = vk_check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_),
                          "vkCreateDescriptorSetLayout", "cull bindings");
      !s)
    return s;
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(GpuCullConstants)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout_;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  if (Status s = vk_check(vkCreatePipelineLayout(device, &layout_info, nullptr, &pipeline_layout_),
                          "vkCreatePipelineLayout", "cull");
      !s)
    return s;

  const uint32_t test_regions = options_.test_regions ? 1u : 0u;
  const uint32_t defer = defer_straddlers_ ? 1u : 0u;
  const SpecConstant cell_constants[] = {{1, test_regions}, {2, uint32_t(append_)}, {3, 0u}, {4, defer}, {5, 0u}};
  if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::cull_comp(), cell_constants, "cull.comp",
                                         cull_pipeline_);
      !s)
    return s;
  // Loose items and moved entries: threads may leave early, so no workgroup-wide slots there.
  const uint32_t own_append =
      ctx_.info().subgroup_ballot && append_ != CullAppend::Atomic ? kAppendSubgroup : kAppendAtomic;
  const SpecConstant own_constants[] = {{1, test_regions}, {2, own_append}, {3, 1u}, {4, 0u}, {5, 0u}};
  if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::cull_comp(), own_constants,
                                         "cull.comp (own regions)", cull_own_pipeline_);
      !s)
    return s;
  if (defer_straddlers_) {
    const SpecConstant straddle_constants[] = {{1, test_regions}, {2, kAppendAtomic}, {3, 0u}, {4, 0u}, {5, 1u}};
    if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::cull_comp(), straddle_constants,
                                           "cull.comp (straddlers)", straddle_pipeline_);
        !s)
      return s;
  }
  if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::finalize_comp(), {}, "finalize.comp",
                                         finalize_pipeline_);
      !s)
    return s;

  const uint32_t sets = uint32_t(slots_.size());
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, sets},
                                        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, (detail::kBindingCount - 1) * sets}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = sets;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = sizes;
  if (Status s = vk_check(vkCreateDescriptorPool(device, &pool_info, nullptr, &descriptor_pool_),
                          "vkCreateDescriptorPool", "cull");
      !s)
    return s;
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = descriptor_pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  for (Slot& slot : slots_)
    if (Status s = vk_check(vkAllocateDescriptorSets(device, &alloc, &slot.set), "vkAllocateDescriptorSets", "cull");
        !s)
      return s;
  return {};
}

CullPass::~CullPass() {
  VkDevice device = ctx_.device();
  vkDeviceWaitIdle(device);
  if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
  if (descriptor_pool_) vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
  if (cull_pipeline_) vkDestroyPipeline(device, cull_pipeline_, nullptr);
  if (cull_own_pipeline_) vkDestroyPipeline(device, cull_own_pipeline_, nullptr);
  if (straddle_pipeline_) vkDestroyPipeline(device, straddle_pipeline_, nullptr);
  if (finalize_pipeline_) vkDestroyPipeline(device, finalize_pipeline_, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
}

Status CullPass::set_scene(const CullScene& scene) {
  if (Status s = detail::check_scene(scene); !s) return s;
  // Cell order (a counting sort): each cell's instances in one range, so a frame dispatches the
  // ranges of its visible cells only; instances reaching several cells, or empty, after them.
  const uint32_t cells = scene.cell_count;
  cell_begin_.assign(size_t(cells) + 2, 0);
  for (const GpuInstance& inst : scene.instances) ++cell_begin_[(inst.cell < cells ? inst.cell : cells) + 1];
  for (uint32_t c = 0; c <= cells; ++c) cell_begin_[c + 1] += cell_begin_[c];
  position_of_id_.resize(scene.instances.size());
  {
    // Within a cell, by draw group (a counting sort of the ids by group first): a workgroup's
    // instances then share few groups, and so do its survivors' slot atomics.
    std::vector<uint32_t> order;
    if (options_.sort_by_group) {
      std::vector<uint32_t> group_begin(scene.groups.size() + 1, 0);
      for (const GpuInstance& inst : scene.instances) ++group_begin[inst.group + 1];
      for (size_t g = 0; g < scene.groups.size(); ++g) group_begin[g + 1] += group_begin[g];
      order.resize(scene.instances.size());
      for (uint32_t i = 0; i < uint32_t(scene.instances.size()); ++i)
        order[group_begin[scene.instances[i].group]++] = i;
    }
    std::vector<uint32_t> next(cell_begin_.begin(), cell_begin_.end() - 1);
    for (size_t k = 0; k < scene.instances.size(); ++k) {
      const size_t i = order.empty() ? k : order[k];
      const uint32_t cell = scene.instances[i].cell;
      position_of_id_[i] = next[cell < cells ? cell : cells]++;
    }
  }
  cell_begin_.pop_back();  // [cells] is now where the loose range begins
  const DeviceInfo& info = ctx_.info();
  const uint32_t n = uint32_t(scene.instances.size());
  const uint32_t groups = uint32_t(scene.groups.size());
  window_instances_ = std::max(1u, std::min(n, options_.instances_per_dispatch));
  // The instance buffer is a whole number of windows, so every dispatch binds a full window.
  const VkDeviceSize window_bytes = VkDeviceSize(window_instances_) * sizeof(GpuInstance);
  const VkDeviceSize instance_bytes = VkDeviceSize(detail::div_up(std::max(n, 1u), window_instances_)) * window_bytes;
  const VkDeviceSize id_bytes = detail::at_least(VkDeviceSize(scene.id_capacity) * 4);
  if (window_bytes > info.max_storage_buffer_range || id_bytes > info.max_storage_buffer_range)
    return Status::unsupported("GPU cull: Vulkan device '" + info.name + "' binds at most " +
                               detail::mib(info.max_storage_buffer_range) +
                               " per storage buffer (maxStorageBufferRange); the scene needs " +
                               detail::mib(std::max(window_bytes, id_bytes)));
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkBufferUsageFlags readable = storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  const VkBufferUsageFlags indirect = readable | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  const VkDeviceSize group_bytes = detail::at_least(VkDeviceSize(groups) * sizeof(GpuDrawGroup));
  const VkDeviceSize command_bytes = detail::at_least(VkDeviceSize(groups) * sizeof(DrawIndexedCommand));
  const VkDeviceSize counter_bytes = sizeof(GpuCullStats) + VkDeviceSize(groups) * 4;
  const VkDeviceSize cell_bytes = detail::at_least(VkDeviceSize(scene.cell_count) * 4);
  Status s;
  if (s = Buffer::create(ctx_, instance_bytes, storage, MemoryUse::Device, "cull instances", instances_); !s) return s;
  if (s = Buffer::create(ctx_, group_bytes, storage, MemoryUse::Device, "cull draw groups", groups_); !s) return s;
  if (s = Buffer::create(ctx_, id_bytes, readable | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::Device,
                         "cull instance ids", ids_);
      !s)
    return s;
  if (s = Buffer::create(ctx_, counter_bytes, indirect, MemoryUse::Device, "cull counters", counters_); !s) return s;
  if (s = Buffer::create(ctx_, command_bytes, indirect, MemoryUse::Device, "cull draw commands", commands_); !s)
    return s;
  if (s = Buffer::create(ctx_, command_bytes, indirect, MemoryUse::Device, "cull compacted commands",
                         compact_commands_);
      !s)
    return s;
  if (s = Buffer::create(ctx_, detail::at_least(VkDeviceSize(groups) * 4), readable, MemoryUse::Device,
                         "cull compacted groups", compact_groups_);
      !s)
    return s;
  const VkDeviceSize reach_upload = VkDeviceSize(scene.reach.size()) * 4;
  // Room after the scene's lists for those update_instances re-uploads.
  const VkDeviceSize reach_bytes = reach_upload + VkDeviceSize(kReachSpareEntries) * 4;
  if (s = Buffer::create(ctx_, reach_bytes, storage, MemoryUse::Device, "cull reach lists", reach_); !s) return s;
  // A cell dispatch tests at most a window: its straddlers fit a window's worth of entries.
  const VkDeviceSize straddle_bytes =
      defer_straddlers_ ? sizeof(GpuStraddleHeader) + VkDeviceSize(window_instances_) * sizeof(glm::uvec2)
                        : detail::kMinBufferBytes;
  if (s = Buffer::create(
          ctx_, straddle_bytes,
          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
          MemoryUse::Device, "cull straddlers", straddlers_);
      !s)
    return s;
  const VkDeviceSize position_bytes = detail::at_least(VkDeviceSize(n) * 4);
  if (s = Buffer::create(ctx_, position_bytes, storage, MemoryUse::Device, "cull position ids", position_ids_); !s)
    return s;
  for (Slot& slot : slots_) {
    if (s = Buffer::create(ctx_, cell_bytes, storage, MemoryUse::Device, "cull cell regions", slot.cell_region); !s)
      return s;
    if (s = Buffer::create(ctx_, VkDeviceSize(kMaxMovedInstances) * sizeof(glm::uvec2),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "cull moved list", slot.moved);
        !s)
      return s;
    if (s = Buffer::create(ctx_, command_bytes + counter_bytes + id_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           MemoryUse::Readback, "cull readback", slot.readback);
        !s)
      return s;
    slot.staging.reset();  // frame buffers are (re)made by the slot's next set_frame
    slot.regions.reset();
    slot.polygons.reset();
    slot.vertices.reset();
    slot.work.reset();
    slot.update_staging.reset();
    slot.dispatches.clear();
    slot.item_dispatches = 0;
    std::fill(std::begin(slot.frame_bytes), std::end(slot.frame_bytes), 0);
    slot.instance_copies.clear();
    slot.reach_copies.clear();
    slot.staged_instance.clear();
  }

  const VkDeviceSize inst_upload = VkDeviceSize(n) * sizeof(GpuInstance);
  const VkDeviceSize group_upload = VkDeviceSize(groups) * sizeof(GpuDrawGroup);
  const VkDeviceSize position_upload = VkDeviceSize(n) * 4;
  Buffer staging;
  if (s = Buffer::create(ctx_, detail::at_least(inst_upload + group_upload + reach_upload + position_upload),
                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, "cull scene staging", staging);
      !s)
    return s;
  {
    GpuInstance* sorted = static_cast<GpuInstance*>(staging.mapped());
    uint32_t* ids =
        reinterpret_cast<uint32_t*>(static_cast<char*>(staging.mapped()) + inst_upload + group_upload + reach_upload);
    for (uint32_t i = 0; i < n; ++i) {
      sorted[position_of_id_[i]] = scene.instances[i];
      ids[position_of_id_[i]] = i;
    }
  }
  if (groups) std::memcpy(static_cast<char*>(staging.mapped()) + inst_upload, scene.groups.data(), group_upload);
  if (reach_upload)
    std::memcpy(static_cast<char*>(staging.mapped()) + inst_upload + group_upload, scene.reach.data(), reach_upload);
  s = ctx_.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        if (inst_upload) {
          VkBufferCopy copy{0, 0, inst_upload};
          vkCmdCopyBuffer(cmd, staging.handle(), instances_.handle(), 1, &copy);
        }
        if (group_upload) {
          VkBufferCopy copy{inst_upload, 0, group_upload};
          vkCmdCopyBuffer(cmd, staging.handle(), groups_.handle(), 1, &copy);
        }
        if (reach_upload) {
          VkBufferCopy copy{inst_upload + group_upload, 0, reach_upload};
          vkCmdCopyBuffer(cmd, staging.handle(), reach_.handle(), 1, &copy);
        }
        if (position_upload) {
          VkBufferCopy copy{inst_upload + group_upload + reach_upload, 0, position_upload};
          vkCmdCopyBuffer(cmd, staging.handle(), position_ids_.handle(), 1, &copy);
        }
        // Unused id slots read back as ~0 rather than as whatever the memory held.
        vkCmdFillBuffer(cmd, ids_.handle(), 0, VK_WHOLE_SIZE, 0xffffffffu);
        detail::barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      },
      "cull scene upload");
  if (!s) return s;
  instance_count_ = n;
  group_count_ = groups;
  cell_count_ = scene.cell_count;
  id_capacity_ = scene.id_capacity;
  reach_used_ = uint32_t(scene.reach.size());
  reach_capacity_ = reach_used_ + kReachSpareEntries;
  moved_by_window_.assign(detail::div_up(std::max(n, 1u), window_instances_), {});
  position_listed_.assign(n, 0);
  moved_count_ = 0;
  return {};
}

Status CullPass::ensure_frame_capacity(const CullFrame& frame, Slot& slot) {
  const VkDeviceSize need[4] = {frame.regions.size() * sizeof(GpuRegion), frame.polygons.size() * sizeof(GpuPolygon),
                                frame.edges_ndc.size() * sizeof(glm::vec4),
                                slot.work_items.size() * sizeof(GpuCullWork)};
  Buffer* buffers[4] = {&slot.regions, &slot.polygons, &slot.vertices, &slot.work};
  const char* labels[4] = {"cull regions", "cull polygons", "cull polygon edges", "cull work items"};
  bool changed = !slot.regions;
  for (int i = 0; i < 4; ++i) {
    if (*buffers[i] && buffers[i]->size() >= need[i]) continue;
    // Grow geometrically: a camera moving through a building settles on a capacity quickly.
    VkDeviceSize bytes = detail::at_least(std::max(need[i], *buffers[i] ? 2 * buffers[i]->size() : 0));
    if (Status s = Buffer::create(ctx_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryUse::Device, labels[i], *buffers[i]);
        !s)
      return s;
    changed = true;
  }
  const VkDeviceSize staging_bytes = VkDeviceSize(cell_count_) * 4 + need[0] + need[1] + need[2] + need[3];
  if (!slot.staging || slot.staging.size() < staging_bytes) {
    VkDeviceSize bytes = detail::at_least(std::max(staging_bytes, slot.staging ? 2 * slot.staging.size() : 0));
    if (Status s = Buffer::create(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload,
                                  "cull frame staging", slot.staging);
        !s)
      return s;
  }
  if (changed) write_descriptors(slot);
  return {};
}

void CullPass::write_descriptors(const Slot& slot) {
  const VkBuffer buffers[detail::kBindingCount] = {
      instances_.handle(),    groups_.handle(),           slot.cell_region.handle(), slot.regions.handle(),
      slot.polygons.handle(), slot.vertices.handle(),     counters_.handle(),        ids_.handle(),
      commands_.handle(),     compact_commands_.handle(), compact_groups_.handle(),  reach_.handle(),
      position_ids_.handle(), slot.work.handle(),         slot.moved.handle(),       straddlers_.handle()};
  VkDescriptorBufferInfo infos[detail::kBindingCount];
  VkWriteDescriptorSet writes[detail::kBindingCount];
  for (uint32_t b = 0; b < detail::kBindingCount; ++b) {
    infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
    writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = slot.set;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType =
        b == detail::kInstances ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  infos[detail::kInstances].range = VkDeviceSize(window_instances_) * sizeof(GpuInstance);
  vkUpdateDescriptorSets(ctx_.device(), detail::kBindingCount, writes, 0, nullptr);
}

Status CullPass::set_frame(const CullFrame& frame, uint32_t slot_index) {
  assert(instances_ && "set_scene before set_frame");
  assert(slot_index < slots_.size());
  Slot& slot = slots_[slot_index];
  if (Status s = detail::check_frame(frame, cell_count_); !s) return s;
  plan_work(frame.cell_region, slot);
  if (Status s = ensure_frame_capacity(frame, slot); !s) return s;
  const void* sources[5] = {frame.cell_region.data(), frame.regions.data(), frame.polygons.data(),
                            frame.edges_ndc.data(), slot.work_items.data()};
  slot.frame_bytes[0] = VkDeviceSize(frame.cell_region.size()) * 4;
  slot.frame_bytes[1] = frame.regions.size() * sizeof(GpuRegion);
  slot.frame_bytes[2] = frame.polygons.size() * sizeof(GpuPolygon);
  slot.frame_bytes[3] = frame.edges_ndc.size() * sizeof(glm::vec4);
  slot.frame_bytes[4] = slot.work_items.size() * sizeof(GpuCullWork);
  char* dst = static_cast<char*>(slot.staging.mapped());
  for (int i = 0; i < 5; ++i) {
    if (slot.frame_bytes[i]) std::memcpy(dst, sources[i], slot.frame_bytes[i]);
    dst += slot.frame_bytes[i];
  }
  slot.constants = {};
  slot.constants.view_proj_rel = frame.view_proj_rel;
  slot.constants.far_row_rel = frame.far_row_rel;
  slot.constants.eye_world = glm::vec4(frame.eye_world, 0.0f);
  slot.constants.group_count = group_count_;
  slot.constants.cell_count = cell_count_;
  return {};
}

void CullPass::record(VkCommandBuffer cmd, uint32_t slot_index) const {
  assert(slot_index < slots_.size());
  const Slot& slot = slots_[slot_index];
  assert(instances_ && slot.staging && "set_scene and set_frame(slot) before record(slot)");
  // Previous users of the shared buffers (the previous frame's cull, its draws' indirect and
  // vertex/fragment reads, its readback and instance updates) finish first: on one queue this
  // orders frame k+1's writes after frame k's reads, whichever command buffer they were in. The
  // slot's own buffers need no such wait: the caller's fence freed the slot.
  detail::barrier(
      cmd,
      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT |
          VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
          VK_PIPELINE_STAGE_2_TRANSFER_BIT,
      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
      VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
      VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  const VkBuffer frame_dst[5] = {slot.cell_region.handle(), slot.regions.handle(), slot.polygons.handle(),
                                 slot.vertices.handle(), slot.work.handle()};
  VkDeviceSize src_offset = 0;
  for (int i = 0; i < 5; ++i) {
    if (slot.frame_bytes[i]) {
      VkBufferCopy copy{src_offset, 0, slot.frame_bytes[i]};
      vkCmdCopyBuffer(cmd, slot.staging.handle(), frame_dst[i], 1, &copy);
    }
    src_offset += slot.frame_bytes[i];
  }
  // Moved instances (update_instances): copied once, by the first record of this slot after them.
  if (!slot.instance_copies.empty())
    vkCmdCopyBuffer(cmd, slot.update_staging.handle(), instances_.handle(), uint32_t(slot.instance_copies.size()),
                    slot.instance_copies.data());
  if (!slot.reach_copies.empty())
    vkCmdCopyBuffer(cmd, slot.update_staging.handle(), reach_.handle(), uint32_t(slot.reach_copies.size()),
                    slot.reach_copies.data());
  slot.instance_copies.clear();
  slot.reach_copies.clear();
  slot.staged_instance.clear();
  vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
  detail::barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  if (timestamps_) {
    vkCmdResetQueryPool(cmd, timestamps_, 2 * slot_index, 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 2 * slot_index);
  }

  GpuCullConstants pc = slot.constants;
  plan_moved(slot);  // the moved list as of now: every instance moved out of its range so far
  VkPipeline bound = VK_NULL_HANDLE;
  for (size_t d = 0; d < slot.dispatches.size(); ++d) {
    const Dispatch& dispatch = slot.dispatches[d];
    if (d > 0)  // the counters are shared by all dispatches: atomics of the previous one first
      detail::barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const bool cell_items = dispatch.kind == kWorkItems;
    if (cell_items && defer_straddlers_) {
      // An empty straddler list (and its indirect dispatch) for this cell dispatch, once the last
      // straddler dispatch has read the previous one.
      if (d > 0)
        detail::barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT);
      const GpuStraddleHeader empty{0, 1, 1, 0};
      vkCmdUpdateBuffer(cmd, straddlers_.handle(), 0, sizeof(empty), &empty);
      detail::barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    const VkPipeline pipeline = cell_items ? cull_pipeline_ : cull_own_pipeline_;
    if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bound = pipeline);
    pc.window_first = dispatch.window * window_instances_;
    const uint32_t window_offset = uint32_t(VkDeviceSize(pc.window_first) * sizeof(GpuInstance));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &slot.set, 1, &window_offset);
    pc.work_first = dispatch.first;
    pc.work_count = dispatch.count;
    pc.work_kind = dispatch.kind;
    vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
    vkCmdDispatch(
        cmd, dispatch.kind == kWorkMoved ? detail::div_up(dispatch.count, kCullWorkgroupSize) : dispatch.count, 1, 1);
    if (cell_items && defer_straddlers_) {
      // Same window, push constants and descriptor set (one pipeline layout): only the pipeline changes.
      detail::barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bound = straddle_pipeline_);
      vkCmdDispatchIndirect(cmd, straddlers_.handle(), 0);
    }
  }
  detail::barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  if (group_count_) {
    const uint32_t zero = 0;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, finalize_pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &slot.set, 1, &zero);
    pc.work_first = 0;
    pc.work_count = 0;
    pc.window_first = 0;
    vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
    vkCmdDispatch(cmd, detail::div_up(group_count_, kFinalizeWorkgroupSize), 1, 1);
  }
  if (timestamps_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 2 * slot_index + 1);
  // The draws read the commands (and the count) as indirect arguments and the ids in the vertex
  // shader. Without output_barrier the caller's render graph places this (output_barrier_info()).
  if (options_.output_barrier) {
    const CullOutputBarrier out = output_barrier_info();
    detail::barrier(cmd, out.src_stage, out.src_access, out.dst_stage, out.dst_access);
  }
}

}  // namespace lintel::gpu
