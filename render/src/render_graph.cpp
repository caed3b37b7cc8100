// Barriers from declared uses: a barrier wherever the previous use wrote, the layout changes, a
// write follows reads (write-after-read needs an execution dependency), or a read comes in a
// stage or with an access the last write has not been made visible to (a read after other reads
// of that write, in a new stage: from the write, not from those reads). Reads after reads in
// stages the write is already visible to, in the same layout, need nothing.
#include "render_graph.h"

#include <sstream>

namespace lintel::render {
namespace {

struct UseState {
  VkPipelineStageFlags2 stage;
  VkAccessFlags2 access;
  VkImageLayout layout;
  bool write;
};

UseState state_of(Use use, bool image) {
  switch (use) {
    case Use::ColorWrite:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true};
    case Use::DepthWrite:
      return {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true};
    case Use::SampledRead:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
    case Use::StorageRead:  // a buffer may be read as storage or as texels (render_bindings.h)
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              image ? VK_ACCESS_2_SHADER_STORAGE_READ_BIT
                    : VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              image ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_UNDEFINED, false};
    case Use::StorageWrite:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
              image ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_UNDEFINED, true};
    case Use::FragmentStorageWrite:
      return {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
              true};
    case Use::VertexRead:  // ids as storage, draw records as texels
      return {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
              false};
    case Use::IndirectRead:
      return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
              false};
    case Use::TransferSrc:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              image ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED, false};
    case Use::TransferDst:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              image ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED, true};
    case Use::CopyAndComputeWrite:
      return {
          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
          VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
          image ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_UNDEFINED, true};
    case Use::HostRead:
      return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, false};
  }
  return {};
}

const char* use_name(Use use) {
  switch (use) {
    case Use::ColorWrite:
      return "color";
    case Use::DepthWrite:
      return "depth";
    case Use::SampledRead:
      return "sampled";
    case Use::StorageRead:
      return "read";
    case Use::StorageWrite:
      return "write";
    case Use::FragmentStorageWrite:
      return "fragment-write";
    case Use::VertexRead:
      return "vertex";
    case Use::IndirectRead:
      return "indirect";
    case Use::TransferSrc:
      return "copy-out";
    case Use::TransferDst:
      return "copy-in";
    case Use::CopyAndComputeWrite:
      return "copy+write";
    case Use::HostRead:
      return "host";
  }
  return "?";
}

}  // namespace

ResourceId RenderGraph::import_image(std::string name, const GpuImage* image, bool keep) {
  Resource r;
  r.name = std::move(name);
  r.image = image;
  r.keep = keep;
  r.states.resize(1);
  resources_.push_back(std::move(r));
  return {uint32_t(resources_.size() - 1)};
}

ResourceId RenderGraph::import_buffer(std::string name, VkBuffer buffer) {
  return import_buffers(std::move(name), {buffer});
}

ResourceId RenderGraph::import_buffers(std::string name, std::vector<VkBuffer> per_slot) {
  Resource r;
  r.name = std::move(name);
  r.states.resize(per_slot.size());
  r.buffers = std::move(per_slot);
  resources_.push_back(std::move(r));
  return {uint32_t(resources_.size() - 1)};
}

void RenderGraph::add_pass(std::string name, std::vector<ResourceUse> uses,
                           std::function<void(VkCommandBuffer, uint32_t)> record, PassKind kind) {
  passes_.push_back({std::move(name), std::move(uses), std::move(record), kind});
}

ResourceState RenderGraph::state_after_frame(ResourceId resource) const {
  ResourceState out;
  const bool image = resources_[resource.index].image != nullptr;
  for (const Pass& p : passes_) {
    if (p.kind != PassKind::Frame) continue;
    for (const ResourceUse& u : p.uses) {
      if (u.resource.index != resource.index) continue;
      const UseState st = state_of(u.use, image);
      out = {st.stage, st.access, st.layout};
    }
  }
  return out;
}

Status RenderGraph::validate(const std::vector<ResourceId>& preloaded) const {
  std::vector<uint8_t> written(resources_.size(), 0);
  for (ResourceId id : preloaded) written[id.index] = 1;
  for (const Pass& p : passes_) {
    for (const ResourceUse& u : p.uses)
      if (!state_of(u.use, true).write && !written[u.resource.index])
        return Status::internal("render graph: pass '" + p.name + "' reads '" + resources_[u.resource.index].name +
                                "' before any pass writes it");
    for (const ResourceUse& u : p.uses)
      if (state_of(u.use, true).write) written[u.resource.index] = 1;
  }
  return {};
}

void RenderGraph::record(VkCommandBuffer cmd, const RecordOptions& options) {
  // A new frame: images start undefined (their contents are rewritten) after whatever came before
  // them on the queue, the caller's own uses between frames included; a kept image starts from the
  // layout its last use left (its contents survive); buffers keep their contents and their
  // tracked state.
  for (Resource& r : resources_) {
    if (r.image)
      r.states[0] = {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                     VK_ACCESS_2_MEMORY_WRITE_BIT,
                     r.keep ? r.states[0].layout : VK_IMAGE_LAYOUT_UNDEFINED,
                     true,
                     VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                     VK_ACCESS_2_MEMORY_WRITE_BIT};
  }
  const uint32_t queries = uint32_t(2 * passes_.size());
  if (options.timestamps) vkCmdResetQueryPool(cmd, options.timestamps, options.first_query, queries);
  for (size_t pi = 0; pi < passes_.size(); ++pi) {
    Pass& p = passes_[pi];
    if (p.kind == PassKind::Readback && !options.readback) continue;
    std::vector<VkImageMemoryBarrier2>& images = image_barriers_;
    std::vector<VkBufferMemoryBarrier2>& buffers = buffer_barriers_;
    images.clear();
    buffers.clear();
    for (const ResourceUse& u : p.uses) {
      Resource& res = resources_[u.resource.index];
      const size_t which = res.image ? 0 : options.slot % res.buffers.size();
      Resource::State& r = res.states[which];
      const UseState next = state_of(u.use, res.image != nullptr);
      const bool layout_change = res.image && r.layout != next.layout;
      // A read after reads: the write they read is not yet visible to this stage or access.
      const bool unseen_write = !next.write && !r.last_was_write && r.write_stage != VK_PIPELINE_STAGE_2_NONE &&
                                ((next.stage & ~r.visible_stage) != 0 || (next.access & ~r.visible_access) != 0);
      const bool needed =
          r.last_was_write || layout_change || unseen_write || (next.write && r.stage != VK_PIPELINE_STAGE_2_NONE);
      // Where the barrier waits from: the write itself for an unseen write (the reads in between
      // neither wrote nor made it visible here), else the last use(s).
      const VkPipelineStageFlags2 src_stage = unseen_write ? (r.stage | r.write_stage) : r.stage;
      const VkAccessFlags2 src_access = r.last_was_write ? r.access : unseen_write ? r.write_access : VK_ACCESS_2_NONE;
      if (needed) {
        if (res.image) {
          VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
          b.srcStageMask = src_stage;
          b.srcAccessMask = src_access;
          b.dstStageMask = next.stage;
          b.dstAccessMask = next.access;
          b.oldLayout = r.layout;
          b.newLayout = next.layout;
          b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
          b.image = res.image->handle();
          b.subresourceRange = {res.image->aspect(), 0, 1, 0, res.image->desc().layers};
          images.push_back(b);
        } else {
          VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
          b.srcStageMask = src_stage == VK_PIPELINE_STAGE_2_NONE ? VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT : src_stage;
          b.srcAccessMask = src_access;
          b.dstStageMask = next.stage;
          b.dstAccessMask = next.access;
          b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
          b.buffer = res.buffers[which];
          b.size = VK_WHOLE_SIZE;
          buffers.push_back(b);
        }
      }
      // Several reads in a row accumulate their stages, so a later write waits for all of them.
      if (needed || next.write) {
        r.stage = next.stage;
        r.access = next.access;
      } else {
        r.stage |= next.stage;
        r.access |= next.access;
      }
      if (res.image) r.layout = next.layout;
      r.last_was_write = next.write;
      if (next.write) {
        r.write_stage = next.stage;
        r.write_access = next.access;
        r.visible_stage = VK_PIPELINE_STAGE_2_NONE;
        r.visible_access = VK_ACCESS_2_NONE;
      } else if (needed) {
        r.visible_stage |= next.stage;
        r.visible_access |= next.access;
      }
    }
    if (!images.empty() || !buffers.empty()) {
      VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dep.imageMemoryBarrierCount = uint32_t(images.size());
      dep.pImageMemoryBarriers = images.data();
      dep.bufferMemoryBarrierCount = uint32_t(buffers.size());
      dep.pBufferMemoryBarriers = buffers.data();
      vkCmdPipelineBarrier2(cmd, &dep);
    }
    const uint32_t q = options.first_query + uint32_t(2 * pi);
    if (options.timestamps) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, options.timestamps, q);
    p.record(cmd, options.slot);
    if (options.timestamps) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, options.timestamps, q + 1);
  }
}

std::string RenderGraph::describe() const {
  std::ostringstream out;
  for (const Pass& p : passes_) {
    out << p.name << ":";
    for (const ResourceUse& u : p.uses)
      out << " " << resources_[u.resource.index].name << "(" << use_name(u.use) << ")";
    out << "\n";
  }
  return out.str();
}

}  // namespace lintel::render
