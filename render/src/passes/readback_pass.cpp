// The readback pass's copies and the host side of them.
#include "readback_pass.h"

#include <cstring>

namespace lintel::render {

Status ReadbackPass::create(gpu::Context& ctx, const ReadbackSources& sources, ReadbackPass& out) {
  out.sources_ = sources;
  const VkDeviceSize pixels = VkDeviceSize(sources.ldr->desc().width) * sources.ldr->desc().height;
  const VkBufferUsageFlags dst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  using gpu::MemoryUse;
  Status s = gpu::Buffer::create(ctx, pixels * 4, dst, MemoryUse::Readback, "ldr readback", out.ldr_);
  if (s && sources.hdr) s = gpu::Buffer::create(ctx, pixels * 16, dst, MemoryUse::Readback, "hdr readback", out.hdr_);
  if (s && sources.cell_ids)
    s = gpu::Buffer::create(ctx, pixels * 4, dst, MemoryUse::Readback, "cell readback", out.cells_);
  if (s && sources.fragment_counts)
    s = gpu::Buffer::create(ctx, sources.fragment_counts->size(), dst, MemoryUse::Readback, "counts readback",
                            out.counts_);
  return s;
}

void ReadbackPass::record(VkCommandBuffer cmd) const {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {sources_.ldr->desc().width, sources_.ldr->desc().height, 1};
  const VkImageLayout src = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  vkCmdCopyImageToBuffer(cmd, sources_.ldr->handle(), src, ldr_.handle(), 1, &copy);
  if (sources_.hdr) vkCmdCopyImageToBuffer(cmd, sources_.hdr->handle(), src, hdr_.handle(), 1, &copy);
  if (sources_.cell_ids) vkCmdCopyImageToBuffer(cmd, sources_.cell_ids->handle(), src, cells_.handle(), 1, &copy);
  if (sources_.fragment_counts) {
    VkBufferCopy bc{0, 0, sources_.fragment_counts->size()};
    vkCmdCopyBuffer(cmd, sources_.fragment_counts->handle(), counts_.handle(), 1, &bc);
  }
}

void ReadbackPass::read(uint32_t width, uint32_t height, RenderedFrame& out) const {
  const size_t pixels = size_t(width) * height;
  out.width = width;
  out.height = height;
  out.rgba8.resize(pixels * 4);
  std::memcpy(out.rgba8.data(), ldr_.mapped(), pixels * 4);
  if (sources_.hdr) {
    out.hdr.resize(pixels);
    std::memcpy(out.hdr.data(), hdr_.mapped(), pixels * 16);
  }
  if (sources_.cell_ids) {
    out.cell_ids.resize(pixels);
    std::memcpy(out.cell_ids.data(), cells_.mapped(), pixels * 4);
  }
  if (sources_.fragment_counts) {
    out.fragment_counts.resize(sources_.fragment_count_entries);
    std::memcpy(out.fragment_counts.data(), counts_.mapped(), out.fragment_counts.size() * 4);
  }
}

}  // namespace lintel::render
