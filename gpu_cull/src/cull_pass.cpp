// The cull pass: buffers, descriptors, and the recorded sequence
//   frame copy + counter reset -> cull dispatch(es) -> finalize -> barrier to indirect/vertex reads.
// GPU-driven culling as in niagara (zeux) and "GPU-Driven Rendering Pipelines" (Haar & Aaltonen,
// SIGGRAPH 2015): survivors append their id to their group's range; one command per group.
#include <lintel/gpu/cull_pass.h>

#include <lintel/gpu/shader_pipeline.h>
#include "lintel_gpu_cull_spirv.h"
#include <lintel/gpu/vk_status.h>

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstring>
#include <string>

namespace lintel::gpu {
namespace {

// Must match cull_bindings.glsl.
enum Binding : uint32_t {
  kInstances = 0,  // dynamic: the dispatch's window
  kGroups,
  kCellRegion,
  kRegions,
  kPolygons,
  kVertices,
  kCounters,
  kIds,
  kCommands,
  kCompactCommands,
  kCompactGroups,
  kReach,
  kBindingCount
};

constexpr VkDeviceSize kMinBufferBytes = 256;  // Vulkan has no empty buffers

VkDeviceSize at_least(VkDeviceSize bytes) { return std::max(bytes, kMinBufferBytes); }

uint32_t div_up(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

void barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
             VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = src_stage;
  mb.srcAccessMask = src_access;
  mb.dstStageMask = dst_stage;
  mb.dstAccessMask = dst_access;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd, &dep);
}

std::string mib(VkDeviceSize bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

Status check_scene(const CullScene& scene) {
  if (scene.instances.size() > kMaxInstances)
    return Status::error("GPU cull: " + std::to_string(scene.instances.size()) + " instances exceed kMaxInstances (" +
                         std::to_string(kMaxInstances) + ")");
  if (scene.groups.size() > kMaxDrawGroups)
    return Status::error("GPU cull: " + std::to_string(scene.groups.size()) + " draw groups exceed kMaxDrawGroups (" +
                         std::to_string(kMaxDrawGroups) + ")");
  if (scene.cell_count > kMaxCells)
    return Status::error("GPU cull: " + std::to_string(scene.cell_count) + " cells exceed kMaxCells (" +
                         std::to_string(kMaxCells) + ")");
  // Id ranges inside the id buffer and disjoint, so no group can write into another's.
  std::vector<std::pair<uint32_t, uint32_t>> ranges;
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    const GpuDrawGroup& group = scene.groups[g];
    if (uint64_t(group.base) + group.capacity > scene.id_capacity)
      return Status::error("GPU cull: draw group " + std::to_string(g) + " ids [" + std::to_string(group.base) + ", +" +
                           std::to_string(group.capacity) + ") exceed the id buffer (" +
                           std::to_string(scene.id_capacity) + ")");
    if (group.capacity) ranges.emplace_back(group.base, group.capacity);
  }
  std::sort(ranges.begin(), ranges.end());
  for (size_t i = 1; i < ranges.size(); ++i)
    if (ranges[i - 1].first + ranges[i - 1].second > ranges[i].first)
      return Status::error("GPU cull: draw groups' id ranges overlap at id " + std::to_string(ranges[i].first));
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].group >= scene.groups.size())
      return Status::error("GPU cull: instance " + std::to_string(i) + " has draw group " +
                           std::to_string(scene.instances[i].group) + " of " + std::to_string(scene.groups.size()));
  // Reach lists inside the reach buffer, within kMaxReachCells, so the shader never reads past it.
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const uint32_t cell = scene.instances[i].cell;
    if (cell == kNoRegion || !(cell & kReachListBit)) continue;
    const uint64_t at = cell & ~kReachListBit;
    if (at >= scene.reach.size() || scene.reach[at] > kMaxReachCells || at + 1 + scene.reach[at] > scene.reach.size())
      return Status::error("GPU cull: instance " + std::to_string(i) + " has reach list " + std::to_string(at) +
                           " outside the " + std::to_string(scene.reach.size()) + " reach entries or over kMaxReachCells");
  }
  return {};
}

Status check_frame(const CullFrame& frame, uint32_t cell_count) {
  if (frame.cell_region.size() != cell_count)
    return Status::error("GPU cull: frame has " + std::to_string(frame.cell_region.size()) + " cells, the scene " +
                         std::to_string(cell_count));
  for (size_t c = 0; c < frame.cell_region.size(); ++c)
    if (frame.cell_region[c] != kNoRegion && frame.cell_region[c] >= frame.regions.size())
      return Status::error("GPU cull: cell " + std::to_string(c) + " has region " + std::to_string(frame.cell_region[c]) +
                           " of " + std::to_string(frame.regions.size()));
  for (size_t r = 0; r < frame.regions.size(); ++r) {
    const GpuRegion& region = frame.regions[r];
    if (region.polygon_count > kMaxRegionPolygons ||
        uint64_t(region.first_polygon) + region.polygon_count > frame.polygons.size())
      return Status::error("GPU cull: region " + std::to_string(r) + " has polygons [" +
                           std::to_string(region.first_polygon) + ", +" + std::to_string(region.polygon_count) +
                           ") of " + std::to_string(frame.polygons.size()) + " (limit kMaxRegionPolygons = " +
                           std::to_string(kMaxRegionPolygons) + ")");
  }
  for (size_t p = 0; p < frame.polygons.size(); ++p) {
    const GpuPolygon& poly = frame.polygons[p];
    if (poly.vertex_count > kMaxPolygonVertices || uint64_t(poly.first_vertex) + poly.vertex_count > frame.vertices_ndc.size())
      return Status::error("GPU cull: polygon " + std::to_string(p) + " has vertices [" + std::to_string(poly.first_vertex) +
                           ", +" + std::to_string(poly.vertex_count) + ") of " + std::to_string(frame.vertices_ndc.size()) +
                           " (limit kMaxPolygonVertices = " + std::to_string(kMaxPolygonVertices) + ")");
  }
  return {};
}

}  // namespace

Status CullPass::create(Context& ctx, const CullPassOptions& options, std::unique_ptr<CullPass>& out) {
  out.reset();
  assert(options.instances_per_dispatch > 0 && options.instances_per_dispatch <= kMaxInstancesPerDispatch &&
         options.instances_per_dispatch % kCullWorkgroupSize == 0);
  std::unique_ptr<CullPass> pass(new CullPass(ctx, options));
  pass->subgroup_aggregate_ = options.subgroup_aggregate && ctx.info().subgroup_ballot;
  if (Status s = pass->create_pipelines(); !s) return s;
  if (options.timestamps && ctx.info().timestamps) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
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
  VkDescriptorSetLayoutBinding bindings[kBindingCount];
  for (uint32_t b = 0; b < kBindingCount; ++b) {
    bindings[b] = {};
    bindings[b].binding = b;
    bindings[b].descriptorType = b == kInstances ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[b].descriptorCount = 1;
    bindings[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = kBindingCount;
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

  const SpecConstant cull_constants[] = {{1, options_.test_regions ? 1u : 0u}, {2, subgroup_aggregate_ ? 1u : 0u}};
  if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::cull_comp(), cull_constants, "cull.comp",
                                         cull_pipeline_);
      !s)
    return s;
  if (Status s = create_compute_pipeline(device, pipeline_layout_, spirv::finalize_comp(), {},
                                         "finalize.comp", finalize_pipeline_);
      !s)
    return s;

  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, 1},
                                        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindingCount - 1}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
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
  return vk_check(vkAllocateDescriptorSets(device, &alloc, &set_), "vkAllocateDescriptorSets", "cull");
}

CullPass::~CullPass() {
  VkDevice device = ctx_.device();
  vkDeviceWaitIdle(device);
  if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
  if (descriptor_pool_) vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
  if (cull_pipeline_) vkDestroyPipeline(device, cull_pipeline_, nullptr);
  if (finalize_pipeline_) vkDestroyPipeline(device, finalize_pipeline_, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
}

Status CullPass::set_scene(const CullScene& scene) {
  if (Status s = check_scene(scene); !s) return s;
  const DeviceInfo& info = ctx_.info();
  const uint32_t n = uint32_t(scene.instances.size());
  const uint32_t groups = uint32_t(scene.groups.size());
  window_instances_ = std::max(1u, std::min(n, options_.instances_per_dispatch));
  // The instance buffer is a whole number of windows, so every dispatch binds a full window.
  const VkDeviceSize window_bytes = VkDeviceSize(window_instances_) * sizeof(GpuInstance);
  const VkDeviceSize instance_bytes = VkDeviceSize(div_up(std::max(n, 1u), window_instances_)) * window_bytes;
  const VkDeviceSize id_bytes = at_least(VkDeviceSize(scene.id_capacity) * 4);
  if (window_bytes > info.max_storage_buffer_range || id_bytes > info.max_storage_buffer_range)
    return Status::unsupported("GPU cull: Vulkan device '" + info.name + "' binds at most " +
                         mib(info.max_storage_buffer_range) + " per storage buffer (maxStorageBufferRange); the scene needs " +
                         mib(std::max(window_bytes, id_bytes)));
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkBufferUsageFlags readable = storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  const VkBufferUsageFlags indirect = readable | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  const VkDeviceSize group_bytes = at_least(VkDeviceSize(groups) * sizeof(GpuDrawGroup));
  const VkDeviceSize command_bytes = at_least(VkDeviceSize(groups) * sizeof(DrawIndexedCommand));
  const VkDeviceSize counter_bytes = sizeof(GpuCullStats) + VkDeviceSize(groups) * 4;
  const VkDeviceSize cell_bytes = at_least(VkDeviceSize(scene.cell_count) * 4);
  Status s;
  if (s = Buffer::create(ctx_, instance_bytes, storage, MemoryUse::Device, "cull instances", instances_); !s) return s;
  if (s = Buffer::create(ctx_, group_bytes, storage, MemoryUse::Device, "cull draw groups", groups_); !s) return s;
  if (s = Buffer::create(ctx_, id_bytes, readable | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUse::Device, "cull instance ids", ids_); !s)
    return s;
  if (s = Buffer::create(ctx_, counter_bytes, indirect, MemoryUse::Device, "cull counters", counters_); !s) return s;
  if (s = Buffer::create(ctx_, command_bytes, indirect, MemoryUse::Device, "cull draw commands", commands_); !s) return s;
  if (s = Buffer::create(ctx_, command_bytes, indirect, MemoryUse::Device, "cull compacted commands", compact_commands_); !s)
    return s;
  if (s = Buffer::create(ctx_, at_least(VkDeviceSize(groups) * 4), readable, MemoryUse::Device, "cull compacted groups",
                         compact_groups_);
      !s)
    return s;
  if (s = Buffer::create(ctx_, cell_bytes, storage, MemoryUse::Device, "cull cell regions", cell_region_); !s) return s;
  const VkDeviceSize reach_upload = VkDeviceSize(scene.reach.size()) * 4;
  if (s = Buffer::create(ctx_, at_least(reach_upload), storage, MemoryUse::Device, "cull reach lists", reach_); !s) return s;
  if (s = Buffer::create(ctx_, command_bytes + counter_bytes + id_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryUse::Readback, "cull readback", readback_);
      !s)
    return s;
  frame_staging_.reset();  // frame buffers are (re)made by the next set_frame
  regions_.reset();
  polygons_.reset();
  vertices_.reset();
  std::fill(std::begin(frame_bytes_), std::end(frame_bytes_), 0);

  const VkDeviceSize inst_upload = VkDeviceSize(n) * sizeof(GpuInstance);
  const VkDeviceSize group_upload = VkDeviceSize(groups) * sizeof(GpuDrawGroup);
  Buffer staging;
  if (s = Buffer::create(ctx_, at_least(inst_upload + group_upload + reach_upload), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         MemoryUse::Upload, "cull scene staging", staging);
      !s)
    return s;
  if (n) std::memcpy(staging.mapped(), scene.instances.data(), inst_upload);
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
        // Unused id slots read back as ~0 rather than as whatever the memory held.
        vkCmdFillBuffer(cmd, ids_.handle(), 0, VK_WHOLE_SIZE, 0xffffffffu);
        barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      },
      "cull scene upload");
  if (!s) return s;
  instance_count_ = n;
  group_count_ = groups;
  cell_count_ = scene.cell_count;
  id_capacity_ = scene.id_capacity;
  return {};
}

Status CullPass::ensure_frame_capacity(const CullFrame& frame) {
  const VkDeviceSize need[3] = {frame.regions.size() * sizeof(GpuRegion), frame.polygons.size() * sizeof(GpuPolygon),
                                frame.vertices_ndc.size() * sizeof(glm::vec2)};
  Buffer* buffers[3] = {&regions_, &polygons_, &vertices_};
  const char* labels[3] = {"cull regions", "cull polygons", "cull polygon vertices"};
  bool changed = !regions_;
  for (int i = 0; i < 3; ++i) {
    if (*buffers[i] && buffers[i]->size() >= need[i]) continue;
    // Grow geometrically: a camera moving through a building settles on a capacity quickly.
    VkDeviceSize bytes = at_least(std::max(need[i], *buffers[i] ? 2 * buffers[i]->size() : 0));
    if (Status s = Buffer::create(ctx_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryUse::Device, labels[i], *buffers[i]);
        !s)
      return s;
    changed = true;
  }
  const VkDeviceSize staging_bytes = VkDeviceSize(cell_count_) * 4 + need[0] + need[1] + need[2];
  if (!frame_staging_ || frame_staging_.size() < staging_bytes) {
    VkDeviceSize bytes = at_least(std::max(staging_bytes, frame_staging_ ? 2 * frame_staging_.size() : 0));
    if (Status s = Buffer::create(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, "cull frame staging",
                                  frame_staging_);
        !s)
      return s;
  }
  if (changed) write_descriptors();
  return {};
}

void CullPass::write_descriptors() {
  const VkBuffer buffers[kBindingCount] = {instances_.handle(),        groups_.handle(),         cell_region_.handle(),
                                           regions_.handle(),          polygons_.handle(),       vertices_.handle(),
                                           counters_.handle(),         ids_.handle(),            commands_.handle(),
                                           compact_commands_.handle(), compact_groups_.handle(),  reach_.handle()};
  VkDescriptorBufferInfo infos[kBindingCount];
  VkWriteDescriptorSet writes[kBindingCount];
  for (uint32_t b = 0; b < kBindingCount; ++b) {
    infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
    writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = set_;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = b == kInstances ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  infos[kInstances].range = VkDeviceSize(window_instances_) * sizeof(GpuInstance);
  vkUpdateDescriptorSets(ctx_.device(), kBindingCount, writes, 0, nullptr);
}

Status CullPass::set_frame(const CullFrame& frame) {
  assert(instances_ && "set_scene before set_frame");
  if (Status s = check_frame(frame, cell_count_); !s) return s;
  if (Status s = ensure_frame_capacity(frame); !s) return s;
  const void* sources[4] = {frame.cell_region.data(), frame.regions.data(), frame.polygons.data(), frame.vertices_ndc.data()};
  frame_bytes_[0] = VkDeviceSize(frame.cell_region.size()) * 4;
  frame_bytes_[1] = frame.regions.size() * sizeof(GpuRegion);
  frame_bytes_[2] = frame.polygons.size() * sizeof(GpuPolygon);
  frame_bytes_[3] = frame.vertices_ndc.size() * sizeof(glm::vec2);
  char* dst = static_cast<char*>(frame_staging_.mapped());
  for (int i = 0; i < 4; ++i) {
    if (frame_bytes_[i]) std::memcpy(dst, sources[i], frame_bytes_[i]);
    dst += frame_bytes_[i];
  }
  constants_ = {};
  constants_.view_proj_rel = frame.view_proj_rel;
  constants_.far_row_rel = frame.far_row_rel;
  constants_.eye_world = glm::vec4(frame.eye_world, 0.0f);
  constants_.group_count = group_count_;
  constants_.cell_count = cell_count_;
  return {};
}

void CullPass::record(VkCommandBuffer cmd) const {
  assert(instances_ && frame_staging_ && "set_scene and set_frame before record");
  // Previous users of these buffers (last frame's cull, draws and readback) finish first.
  barrier(cmd,
          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT |
              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_TRANSFER_BIT,
          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
          VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
          VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  const VkBuffer frame_dst[4] = {cell_region_.handle(), regions_.handle(), polygons_.handle(), vertices_.handle()};
  VkDeviceSize src_offset = 0;
  for (int i = 0; i < 4; ++i) {
    if (frame_bytes_[i]) {
      VkBufferCopy copy{src_offset, 0, frame_bytes_[i]};
      vkCmdCopyBuffer(cmd, frame_staging_.handle(), frame_dst[i], 1, &copy);
    }
    src_offset += frame_bytes_[i];
  }
  vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
  barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  if (timestamps_) {
    vkCmdResetQueryPool(cmd, timestamps_, 0, 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 0);
  }

  GpuCullConstants pc = constants_;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cull_pipeline_);
  for (uint32_t first = 0; first < instance_count_; first += window_instances_) {
    if (first > 0)  // counters are shared by all windows: atomics of the previous dispatch first
      barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const uint32_t window_offset = uint32_t(VkDeviceSize(first) * sizeof(GpuInstance));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_, 1, &window_offset);
    pc.first_instance = first;
    pc.instance_count = std::min(window_instances_, instance_count_ - first);
    vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
    vkCmdDispatch(cmd, div_up(pc.instance_count, kCullWorkgroupSize), 1, 1);
  }
  barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  if (group_count_) {
    const uint32_t zero = 0;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, finalize_pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_, 1, &zero);
    pc.first_instance = 0;
    pc.instance_count = 0;
    vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
    vkCmdDispatch(cmd, div_up(group_count_, kFinalizeWorkgroupSize), 1, 1);
  }
  if (timestamps_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 1);
  // The draws read the commands (and the count) as indirect arguments and the ids in the vertex
  // shader.
  barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
          VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
          VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void CullPass::record_readback(VkCommandBuffer cmd, bool stats_only) const {
  barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
          VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkDeviceSize command_bytes = VkDeviceSize(group_count_) * sizeof(DrawIndexedCommand);
  const VkDeviceSize counter_bytes = sizeof(GpuCullStats) + VkDeviceSize(group_count_) * 4;
  const VkDeviceSize id_bytes = stats_only ? 0 : VkDeviceSize(id_capacity_) * 4;
  if (stats_only) {
    VkBufferCopy stats{0, command_bytes, sizeof(GpuCullStats)};
    vkCmdCopyBuffer(cmd, counters_.handle(), readback_.handle(), 1, &stats);
  } else if (command_bytes) {
    VkBufferCopy copy{0, 0, command_bytes};
    vkCmdCopyBuffer(cmd, commands_.handle(), readback_.handle(), 1, &copy);
  }
  if (!stats_only) {
    VkBufferCopy counters{0, command_bytes, counter_bytes};
    vkCmdCopyBuffer(cmd, counters_.handle(), readback_.handle(), 1, &counters);
  }
  if (id_bytes) {
    VkBufferCopy copy{0, command_bytes + counter_bytes, id_bytes};
    vkCmdCopyBuffer(cmd, ids_.handle(), readback_.handle(), 1, &copy);
  }
  barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
          VK_ACCESS_2_HOST_READ_BIT);
}

Status CullPass::run(CullReadback* out, CullTimings* timings) {
  const auto start = std::chrono::steady_clock::now();
  Status s = ctx_.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        record(cmd);
        record_readback(cmd, out == nullptr);
      },
      "GPU cull");
  const auto end = std::chrono::steady_clock::now();
  if (!s) return s;
  if (timings) {
    timings->wall_ms = std::chrono::duration<double, std::milli>(end - start).count();
    timings->gpu_ms = -1.0;
    uint64_t ticks[2] = {0, 0};
    if (timestamps_ && vkGetQueryPoolResults(ctx_.device(), timestamps_, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                                             VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS)
      timings->gpu_ms = double(ticks[1] - ticks[0]) * ctx_.info().timestamp_period_ns * 1e-6;
  }
  const char* base = static_cast<const char*>(readback_.mapped());
  const VkDeviceSize command_bytes = VkDeviceSize(group_count_) * sizeof(DrawIndexedCommand);
  GpuCullStats stats;
  std::memcpy(&stats, base + command_bytes, sizeof(stats));
  if (out) {
    out->commands.resize(group_count_);
    out->instance_ids.resize(id_capacity_);
    out->stats = stats;
    if (command_bytes) std::memcpy(out->commands.data(), base, command_bytes);
    if (id_capacity_)
      std::memcpy(out->instance_ids.data(), base + command_bytes + sizeof(GpuCullStats) + VkDeviceSize(group_count_) * 4,
                  VkDeviceSize(id_capacity_) * 4);
  }
  if (stats.overflow_instances)
    return Status::error("GPU cull: " + std::to_string(stats.overflow_instances) + " visible instances overflowed the id capacity of " +
                         std::to_string(stats.overflow_groups) + " draw groups and were not drawn (ids stayed in bounds)");
  return {};
}

}  // namespace lintel::gpu
