// A game's frame loop with Lintel inside, the way an engine embeds it: the game owns the Vulkan
// instance, device, queue, command buffers, fences and render target; Lintel borrows the device
// (Context::wrap) and, per frame, builds visibility on the CPU and records the GPU cull into the
// game's command buffer. The game then draws the culled instances depth-only with one
// vkCmdDrawIndexedIndirect. Two frames in flight: the CPU prepares frame k+1 while the GPU runs k.
// Usage: engine_loop <scene.gltf|.glb> [--validate] [--frames N] [--device NAME]
// Exit: 0 ok; 2 bad arguments or scene; 1 Vulkan failure, a validation message (with --validate),
// or a frame whose GPU-drawn instance count differs from Lintel's CPU visible set.
#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_pass.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/view.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "depth_only_vert.h"  // generated: the SPIR-V of depth_only.vert
#include "game_device.h"

namespace {

constexpr uint32_t kFramesInFlight = 2;
constexpr uint32_t kTargetSize = 256;  // the depth target's width and height
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct Args {
  std::string scene;
  bool validate = false;
  size_t frames = 0;  // 0: the whole first timeline
  std::string device;
};

// What the game keeps per frame in flight.
struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence done = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkDeviceMemory depth_memory = VK_NULL_HANDLE;
  VkImageView depth_view = VK_NULL_HANDLE;
  size_t frame = SIZE_MAX;   // the frame last submitted in this slot
  size_t cpu_instances = 0;  // what Lintel's CPU visible set holds for that frame
};

// The game's draw: geometry, per-instance transforms, a depth-only pipeline.
struct DepthDraw {
  lintel::gpu::Buffer vertices, indices, mesh_to_world;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--validate")
      a.validate = true;
    else if (arg == "--frames" && i + 1 < argc)
      a.frames = std::strtoull(argv[++i], nullptr, 10);
    else if (arg == "--device" && i + 1 < argc)
      a.device = argv[++i];
    else if (a.scene.empty() && arg[0] != '-')
      a.scene = arg;
    else
      return false;
  }
  return !a.scene.empty();
}

bool ok(VkResult r, const char* what) {
  if (r == VK_SUCCESS) return true;
  std::fprintf(stderr, "engine_loop: %s failed (VkResult %d)\n", what, int(r));
  return false;
}

// Host-visible buffer the GPU reads directly (small scenes; a real engine would stage to device memory).
bool upload(lintel::gpu::Context& ctx, const void* data, size_t bytes, VkBufferUsageFlags usage, const char* label,
            lintel::gpu::Buffer& out) {
  if (lintel::Status s = lintel::gpu::Buffer::create(ctx, std::max<size_t>(bytes, 16), usage,
                                                     lintel::gpu::MemoryUse::Upload, label, out);
      !s) {
    std::fprintf(stderr, "engine_loop: %s\n", s.message().c_str());
    return false;
  }
  if (bytes) std::memcpy(out.mapped(), data, bytes);
  return true;
}

bool create_draw(lintel::gpu::Context& ctx, const lintel::World& world, const lintel::gpu::CullPass& pass,
                 DepthDraw& d) {
  // Meshes concatenated in World order: the layout pack_scene assumes without mesh ranges.
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  for (const lintel::Mesh& m : world.meshes) {
    positions.insert(positions.end(), m.positions.begin(), m.positions.end());
    indices.insert(indices.end(), m.indices.begin(), m.indices.end());
  }
  std::vector<glm::mat4> transforms;
  for (const lintel::Instance& inst : world.instances) transforms.push_back(inst.mesh_to_world);
  if (!upload(ctx, positions.data(), positions.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
              "vertices", d.vertices) ||
      !upload(ctx, indices.data(), indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "indices", d.indices) ||
      !upload(ctx, transforms.data(), transforms.size() * sizeof(glm::mat4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
              "instance transforms", d.mesh_to_world))
    return false;

  VkDevice device = ctx.device();
  VkDescriptorSetLayoutBinding bindings[2] = {};
  for (uint32_t b = 0; b < 2; ++b) {
    bindings[b].binding = b;
    bindings[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[b].descriptorCount = 1;
    bindings[b].stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = 2;
  set_info.pBindings = bindings;
  if (!ok(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &d.set_layout), "vkCreateDescriptorSetLayout"))
    return false;
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &d.set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  if (!ok(vkCreatePipelineLayout(device, &layout_info, nullptr, &d.layout), "vkCreatePipelineLayout")) return false;

  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = sizeof(depth_only_vert_spirv);
  module_info.pCode = depth_only_vert_spirv;
  VkShaderModule module = VK_NULL_HANDLE;
  if (!ok(vkCreateShaderModule(device, &module_info, nullptr, &module), "vkCreateShaderModule")) return false;
  VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.module = module;
  stage.pName = "main";
  VkVertexInputBindingDescription vertex_binding{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &vertex_binding;
  vertex_input.vertexAttributeDescriptionCount = 1;
  vertex_input.pVertexAttributeDescriptions = &position;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;  // Lintel's clip space: z = 0 near, z = w far
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.depthAttachmentFormat = kDepthFormat;
  VkGraphicsPipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  pipeline_info.pNext = &rendering;
  pipeline_info.stageCount = 1;
  pipeline_info.pStages = &stage;
  pipeline_info.pVertexInputState = &vertex_input;
  pipeline_info.pInputAssemblyState = &assembly;
  pipeline_info.pViewportState = &viewport;
  pipeline_info.pRasterizationState = &raster;
  pipeline_info.pMultisampleState = &multisample;
  pipeline_info.pDepthStencilState = &depth;
  pipeline_info.pDynamicState = &dynamic;
  pipeline_info.layout = d.layout;
  const bool made = ok(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &d.pipeline),
                       "vkCreateGraphicsPipelines");
  vkDestroyShaderModule(device, module, nullptr);
  if (!made) return false;

  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  if (!ok(vkCreateDescriptorPool(device, &pool_info, nullptr, &d.pool), "vkCreateDescriptorPool")) return false;
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = d.pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &d.set_layout;
  if (!ok(vkAllocateDescriptorSets(device, &alloc, &d.set), "vkAllocateDescriptorSets")) return false;
  // The id buffer is shared by all frames in flight: Lintel's record() orders each frame's writes
  // after the previous frame's reads, so one set serves every slot.
  VkDescriptorBufferInfo infos[2] = {{pass.instance_ids(), 0, VK_WHOLE_SIZE},
                                     {d.mesh_to_world.handle(), 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2] = {};
  for (uint32_t b = 0; b < 2; ++b) {
    writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = d.set;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
  return true;
}

bool create_slot(lintel::gpu::Context& ctx, VkCommandPool pool, FrameSlot& s) {
  VkDevice device = ctx.device();
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  if (!ok(vkAllocateCommandBuffers(device, &alloc, &s.cmd), "vkAllocateCommandBuffers")) return false;
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  if (!ok(vkCreateFence(device, &fence_info, nullptr, &s.done), "vkCreateFence")) return false;
  VkImageCreateInfo image{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  image.imageType = VK_IMAGE_TYPE_2D;
  image.format = kDepthFormat;
  image.extent = {kTargetSize, kTargetSize, 1};
  image.mipLevels = 1;
  image.arrayLayers = 1;
  image.samples = VK_SAMPLE_COUNT_1_BIT;
  image.tiling = VK_IMAGE_TILING_OPTIMAL;
  image.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (!ok(vkCreateImage(device, &image, nullptr, &s.depth), "vkCreateImage")) return false;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, s.depth, &req);
  VkMemoryAllocateInfo memory{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  memory.allocationSize = req.size;
  memory.memoryTypeIndex = ctx.find_memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!ok(vkAllocateMemory(device, &memory, nullptr, &s.depth_memory), "vkAllocateMemory") ||
      !ok(vkBindImageMemory(device, s.depth, s.depth_memory, 0), "vkBindImageMemory"))
    return false;
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = s.depth;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = kDepthFormat;
  view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
  return ok(vkCreateImageView(device, &view, nullptr, &s.depth_view), "vkCreateImageView");
}

// The frame's commands: Lintel's cull, then the game's barrier (its render graph's: the cull's
// outputs to the indirect draw, and the depth target to attachment), the draw, and a copy of the
// cull's stats for the CPU to check once the slot's fence signals.
void record_frame(const lintel::gpu::CullPass& pass, const DepthDraw& d, uint32_t slot_index, const FrameSlot& s,
                  const glm::mat4& world_to_clip) {
  pass.record(s.cmd, slot_index);
  const VkMemoryBarrier2 cull_outputs = pass.output_barrier_info().memory_barrier();
  VkImageMemoryBarrier2 to_depth{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  // The previous frame in this slot finished (fence), but its depth writes still need ordering.
  to_depth.srcStageMask = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  to_depth.srcAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  to_depth.dstStageMask = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  to_depth.dstAccessMask =
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  to_depth.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  to_depth.newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  to_depth.srcQueueFamilyIndex = to_depth.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_depth.image = s.depth;
  to_depth.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &cull_outputs;
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &to_depth;
  vkCmdPipelineBarrier2(s.cmd, &dep);

  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = s.depth_view;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {kTargetSize, kTargetSize}};
  rendering.layerCount = 1;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(s.cmd, &rendering);
  const VkViewport viewport{0.0f, 0.0f, float(kTargetSize), float(kTargetSize), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {kTargetSize, kTargetSize}};
  vkCmdSetViewport(s.cmd, 0, 1, &viewport);
  vkCmdSetScissor(s.cmd, 0, 1, &scissor);
  vkCmdBindPipeline(s.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
  vkCmdBindDescriptorSets(s.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.layout, 0, 1, &d.set, 0, nullptr);
  vkCmdPushConstants(s.cmd, d.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4), &world_to_clip);
  const VkDeviceSize zero = 0;
  const VkBuffer vertices = d.vertices.handle();
  vkCmdBindVertexBuffers(s.cmd, 0, 1, &vertices, &zero);
  vkCmdBindIndexBuffer(s.cmd, d.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  // One command per draw group, firstInstance = the group's base in the id buffer.
  if (pass.group_count())
    vkCmdDrawIndexedIndirect(s.cmd, pass.draw_commands(), 0, pass.group_count(),
                             sizeof(lintel::gpu::DrawIndexedCommand));
  vkCmdEndRendering(s.cmd);
  pass.record_readback(s.cmd, slot_index, true);
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, args)) {
    std::fprintf(stderr, "usage: %s <scene.gltf|.glb> [--validate] [--frames N] [--device NAME]\n", argv[0]);
    return 2;
  }
  // A game may pick its GPU however it likes; this one honours the variable Lintel's tests use.
  if (const char* selector = std::getenv("LINTEL_VK_DEVICE"); selector && args.device.empty()) args.device = selector;
  lintel::World world;
  if (lintel::Status s = lintel::load_world(args.scene, world); !s) {
    std::fprintf(stderr, "engine_loop: %s\n", s.message().c_str());
    return 2;
  }
  if (world.timelines.empty()) {
    std::fprintf(stderr, "engine_loop: %s: the scene has no timeline to walk\n", args.scene.c_str());
    return 2;
  }

  GameDevice game;
  if (std::string e = game.create(args.validate, args.device); !e.empty()) {
    std::fprintf(stderr, "engine_loop: %s\n", e.c_str());
    game.destroy();
    return 1;
  }
  int rc = 0;
  size_t mismatches = 0, frames_run = 0, drawn_total = 0;
  {
    // Lintel on the game's device: it creates pipelines and buffers, and for set_scene's upload
    // one command pool and fence; nothing per frame.
    std::unique_ptr<lintel::gpu::Context> ctx;
    std::unique_ptr<lintel::gpu::CullPass> pass;
    lintel::gpu::CullPassOptions options;
    options.frames_in_flight = kFramesInFlight;
    options.output_barrier = false;  // the game's barrier below places it
    lintel::gpu::CullScene scene;
    lintel::Status s = lintel::gpu::Context::wrap(game.external(), ctx);
    if (s) s = lintel::gpu::CullPass::create(*ctx, options, pass);
    if (s) s = lintel::gpu::pack_scene(world, {}, scene);
    if (s) s = pass->set_scene(scene);
    DepthDraw draw;
    FrameSlot slots[kFramesInFlight];
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = game.queue_family;
    bool ready = s && ok(vkCreateCommandPool(game.device, &pool_info, nullptr, &pool), "vkCreateCommandPool") &&
                 create_draw(*ctx, world, *pass, draw);
    for (FrameSlot& slot : slots) ready = ready && create_slot(*ctx, pool, slot);
    if (!s) std::fprintf(stderr, "engine_loop: %s\n", s.message().c_str());
    if (!ready) rc = 1;

    const lintel::Timeline& timeline = world.timelines.front();
    const size_t frames = args.frames ? std::min(args.frames, lintel::timeline_frame_count(timeline))
                                      : lintel::timeline_frame_count(timeline);
    lintel::ViewerTracker tracker;
    lintel::VisibilityBuilder builder;
    lintel::VisibleSet visible;
    builder.prepare(world, {}, visible);  // at load: no frame allocates, the first included
    lintel::gpu::CullFrame cull_frame;
    lintel::gpu::CullReadback stats;
    // The slot's previous frame is done: check what the GPU drew against Lintel's CPU visible set.
    auto retire = [&](FrameSlot& slot, uint32_t index) {
      if (!ok(vkWaitForFences(game.device, 1, &slot.done, VK_TRUE, UINT64_MAX), "vkWaitForFences")) return false;
      if (slot.frame == SIZE_MAX) return true;
      if (lintel::Status r = pass->read_back(index, true, stats); !r) {
        std::fprintf(stderr, "engine_loop: frame %zu: %s\n", slot.frame, r.message().c_str());
        return false;
      }
      drawn_total += stats.stats.visible_instances;
      if (stats.stats.visible_instances != slot.cpu_instances) {
        ++mismatches;
        std::fprintf(stderr, "engine_loop: frame %zu: the GPU drew %u instances, Lintel's CPU visible set has %zu\n",
                     slot.frame, stats.stats.visible_instances, slot.cpu_instances);
      }
      slot.frame = SIZE_MAX;
      return true;
    };
    for (size_t f = 0; rc == 0 && f < frames; ++f) {
      const uint32_t index = uint32_t(f % kFramesInFlight);
      FrameSlot& slot = slots[index];
      if (!retire(slot, index)) {
        rc = 1;
        break;
      }
      // Lintel visibility on the CPU, then its cull of this frame into the game's command buffer.
      const lintel::View view = lintel::timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
      s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world);
      if (s) s = builder.build(world, view, tracker.cell(), {}, visible);
      if (s) {
        lintel::gpu::pack_visible_set(visible, view, uint32_t(world.cells.size()), cull_frame);
        s = pass->set_frame(cull_frame, index);
      }
      if (!s) {
        std::fprintf(stderr, "engine_loop: frame %zu: %s\n", f, s.message().c_str());
        rc = 1;
        break;
      }
      vkResetFences(game.device, 1, &slot.done);
      vkResetCommandBuffer(slot.cmd, 0);
      VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
      begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
      vkBeginCommandBuffer(slot.cmd, &begin);
      record_frame(*pass, draw, index, slot, lintel::view_projection(view));
      VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
      submit.commandBufferCount = 1;
      submit.pCommandBuffers = &slot.cmd;
      if (!ok(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer") ||
          !ok(vkQueueSubmit(game.queue, 1, &submit, slot.done), "vkQueueSubmit")) {
        rc = 1;
        break;
      }
      slot.frame = f;
      slot.cpu_instances = visible.instances.size();
      ++frames_run;
    }
    for (uint32_t i = 0; i < kFramesInFlight; ++i)
      if (slots[i].done && !retire(slots[i], i)) rc = 1;
    vkDeviceWaitIdle(game.device);
    for (FrameSlot& slot : slots) {
      if (slot.depth_view) vkDestroyImageView(game.device, slot.depth_view, nullptr);
      if (slot.depth) vkDestroyImage(game.device, slot.depth, nullptr);
      if (slot.depth_memory) vkFreeMemory(game.device, slot.depth_memory, nullptr);
      if (slot.done) vkDestroyFence(game.device, slot.done, nullptr);
    }
    if (pool) vkDestroyCommandPool(game.device, pool, nullptr);
    if (draw.pool) vkDestroyDescriptorPool(game.device, draw.pool, nullptr);
    if (draw.pipeline) vkDestroyPipeline(game.device, draw.pipeline, nullptr);
    if (draw.layout) vkDestroyPipelineLayout(game.device, draw.layout, nullptr);
    if (draw.set_layout) vkDestroyDescriptorSetLayout(game.device, draw.set_layout, nullptr);
  }  // Lintel's objects (draw buffers, pass, context) go before the device
  game.destroy();
  const std::vector<std::string> messages = game.take_messages();
  for (size_t i = 0; i < messages.size() && i < 5; ++i)
    std::fprintf(stderr, "engine_loop: validation: %s\n", messages[i].c_str());
  if (!messages.empty()) rc = 1;
  if (mismatches) rc = 1;
  std::printf("engine_loop: %zu frames, %u in flight, %zu instances drawn, %zu mismatches, %zu validation messages%s\n",
              frames_run, kFramesInFlight, drawn_total, mismatches, messages.size(),
              args.validate ? "" : " (not validating)");
  return rc;
}
