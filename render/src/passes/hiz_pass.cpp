// The hierarchical-Z pass's buffers, descriptor set and four pipeline stages (hiz_*.comp, hiz.glsl).
#include "hiz_pass.h"

#include "../binding_tables.h"
#include "../spirv_bindings.h"
#include "render_bindings.h"
#include "shader_pipeline.h"

#include "lintel_render_spirv.h"

#include <algorithm>
#include <array>

namespace lintel::render {
namespace {

constexpr uint32_t kGroupSize = 64;  // hiz.glsl's local_size_x
// The storage buffers are bindings 0 .. kHizBindDepth - 1 (render_bindings.h), the depth sampler last.
constexpr uint32_t kBindings = kHizBindingCount;
static_assert(kHizBindDepth == kHizBindingCount - 1);

uint32_t workgroups(uint64_t threads) { return uint32_t((threads + kGroupSize - 1) / kGroupSize); }

}  // namespace

HizPass::~HizPass() {
  if (!device_) return;
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
}

Status HizPass::create(gpu::Context& ctx, const RenderScene& scene, VkBuffer cull_commands, VkBuffer cull_ids,
                       const GpuImage& depth, VkSampler sampler, HizPass& out) {
  VkDevice d = ctx.device();
  out.device_ = d;
  const gpu::CullScene& cs = scene.cull_scene;
  out.capacity_ = std::max<uint32_t>(cs.id_capacity, 1);
  out.first_shell_ = scene.world_instance_count;
  out.groups_ = uint32_t(cs.groups.size());
  out.width_ = depth.desc().width;
  out.height_ = depth.desc().height;
  // Levels down to 1 x 1; level 0 is the depth image halved (hiz.glsl's level_size).
  uint64_t pyramid_texels = 0;
  out.levels_ = 0;
  for (uint32_t l = 0;; ++l) {
    const uint32_t w = (out.width_ + (2u << l) - 1) >> (l + 1), h = (out.height_ + (2u << l) - 1) >> (l + 1);
    pyramid_texels += uint64_t(w) * h;
    ++out.levels_;
    if (w <= 1 && h <= 1) break;
  }
  std::vector<uint32_t> slot_groups(out.capacity_, 0);
  for (uint32_t g = 0; g < cs.groups.size(); ++g)
    for (uint32_t k = 0; k < cs.groups[g].capacity; ++k) slot_groups[cs.groups[g].base + k] = g;
  const std::vector<uint32_t> zeros(cs.instances.size() + 1, 0);
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  Status s = gpu::Buffer::create(
      ctx, VkDeviceSize(2) * std::max<uint32_t>(out.groups_, 1) * sizeof(gpu::DrawIndexedCommand),
      storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUse::Device, "hiz commands", out.commands_);
  if (s)
    s = gpu::Buffer::create(ctx, VkDeviceSize(2) * out.capacity_ * 4, storage, gpu::MemoryUse::Device, "hiz ids",
                            out.ids_);
  if (s)
    s = gpu::Buffer::create(ctx, (VkDeviceSize(2) * out.groups_ + 2) * 4,
                            storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                            gpu::MemoryUse::Device, "hiz counters", out.counters_);
  if (s)
    s = gpu::Buffer::create(ctx, (VkDeviceSize(2) * out.groups_ + 2) * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            gpu::MemoryUse::Readback, "hiz counters readback", out.counters_host_);
  if (s)
    s = gpu::Buffer::create(ctx, std::max<uint64_t>(pyramid_texels, 1) * 4, storage, gpu::MemoryUse::Device,
                            "depth pyramid", out.pyramid_);
  // Nothing was visible before the first frame: it draws nothing first and tests everything.
  if (s) s = upload_vector(ctx, zeros, storage, "hiz visibility", out.visibility_);
  if (s) s = upload_vector(ctx, slot_groups, storage, "hiz slot groups", out.slot_groups_);
  if (s) s = upload_vector(ctx, cs.instances, storage, "hiz bounds", out.instances_);
  if (!s) return s;

  if (Status st = create_set_layout(d, hiz_set_bindings(), "hiz set layout", out.set_layout_); !st) return st;
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(HizPush)};
  VkPipelineLayoutCreateInfo li{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  li.setLayoutCount = 1;
  li.pSetLayouts = &out.set_layout_;
  li.pushConstantRangeCount = 1;
  li.pPushConstantRanges = &push;
  if (vkCreatePipelineLayout(d, &li, nullptr, &out.layout_) != VK_SUCCESS)
    return Status::error("hiz: cannot create the pipeline layout");
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindings - 1},
                                         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
  VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pi.maxSets = 1;
  pi.poolSizeCount = 2;
  pi.pPoolSizes = sizes;
  if (vkCreateDescriptorPool(d, &pi, nullptr, &out.pool_) != VK_SUCCESS)
    return Status::error("hiz: cannot create the descriptor pool");
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = out.pool_;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &out.set_layout_;
  if (vkAllocateDescriptorSets(d, &ai, &out.set_) != VK_SUCCESS)
    return Status::error("hiz: cannot allocate the descriptor set");
  const VkBuffer buffers[kBindings - 1] = {cull_commands,
                                           cull_ids,
                                           out.commands_.handle(),
                                           out.ids_.handle(),
                                           out.counters_.handle(),
                                           out.visibility_.handle(),
                                           out.pyramid_.handle(),
                                           out.instances_.handle(),
                                           out.slot_groups_.handle()};
  VkDescriptorBufferInfo infos[kBindings - 1];
  VkWriteDescriptorSet writes[kBindings];
  for (uint32_t b = 0; b < kBindings - 1; ++b) {
    infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
    writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = out.set_;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  const VkDescriptorImageInfo image{sampler, depth.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  writes[kHizBindDepth] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  writes[kHizBindDepth].dstSet = out.set_;
  writes[kHizBindDepth].dstBinding = kHizBindDepth;
  writes[kHizBindDepth].descriptorCount = 1;
  writes[kHizBindDepth].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[kHizBindDepth].pImageInfo = &image;
  vkUpdateDescriptorSets(d, kBindings, writes, 0, nullptr);
  const std::span<const uint32_t> spirv[4] = {gpu::spirv::hiz_early_comp(), gpu::spirv::hiz_commands_comp(),
                                              gpu::spirv::hiz_pyramid_comp(), gpu::spirv::hiz_late_comp()};
  const char* const labels[4] = {"hiz_early.comp", "hiz_commands.comp", "hiz_pyramid.comp", "hiz_late.comp"};
  for (uint32_t stage = 0; stage < 4; ++stage) {
    if (Status st = check_shader_bindings(spirv[stage], VK_SHADER_STAGE_COMPUTE_BIT, hiz_set_bindings(), labels[stage]);
        !st)
      return st;
    VkPipeline p = VK_NULL_HANDLE;
    if (Status st = gpu::create_compute_pipeline(d, out.layout_, spirv[stage], {}, labels[stage], p); !st) return st;
    out.stages_[stage].adopt(d, p);
  }
  return {};
}

Status HizPass::update_bounds(gpu::Context& ctx, const RenderScene& scene) {
  const auto& inst = scene.cull_scene.instances;
  return write_buffer(ctx, instances_, 0, inst.data(), inst.size() * sizeof(inst[0]), "hiz bounds");
}

void HizPass::dispatch(VkCommandBuffer cmd, uint32_t stage, const void* push, uint32_t groups) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, stages_[stage].handle());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(HizPush), push);
  if (groups) vkCmdDispatch(cmd, groups, 1, 1);
}

void HizPass::record_readback(VkCommandBuffer cmd) const {
  const VkBufferCopy c{0, 0, counters_.size()};
  vkCmdCopyBuffer(cmd, counters_.handle(), counters_host_.handle(), 1, &c);
}

HizStats HizPass::read_stats() const {
  const auto* n = static_cast<const uint32_t*>(counters_host_.mapped());
  HizStats s;
  for (uint32_t g = 0; g < groups_; ++g) s.drawn_early += n[g], s.drawn_late += n[groups_ + g];
  s.tested = n[2 * groups_];
  s.passed = n[2 * groups_ + 1];
  return s;
}

void HizPass::record_reset(VkCommandBuffer cmd) const {
  vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0u);
}

void HizPass::record_early(VkCommandBuffer cmd) const {
  HizPush p{};
  p.counts = glm::uvec4(capacity_, groups_, 0, levels_);
  p.image = glm::uvec4(width_, height_, 0, first_shell_);
  dispatch(cmd, 0, &p, workgroups(capacity_));
}

void HizPass::record_commands(VkCommandBuffer cmd, uint32_t phase) const {
  HizPush p{};
  p.counts = glm::uvec4(capacity_, groups_, phase, levels_);
  p.image = glm::uvec4(width_, height_, 0, first_shell_);
  dispatch(cmd, 1, &p, workgroups(groups_));
}

void HizPass::record_pyramid(VkCommandBuffer cmd, uint32_t level) const {
  HizPush p{};
  p.counts = glm::uvec4(capacity_, groups_, 0, levels_);
  p.image = glm::uvec4(width_, height_, level, first_shell_);
  const uint64_t w = (width_ + (2u << level) - 1) >> (level + 1), h = (height_ + (2u << level) - 1) >> (level + 1);
  dispatch(cmd, 2, &p, workgroups(w * h));
}

void HizPass::record_late(VkCommandBuffer cmd, const FrameContext& frame) const {
  HizPush p{};
  p.view_proj = frame.view_proj;
  p.counts = glm::uvec4(capacity_, groups_, 0, levels_);
  p.image = glm::uvec4(width_, height_, 0, first_shell_);
  dispatch(cmd, 3, &p, workgroups(capacity_));
}

}  // namespace lintel::render
