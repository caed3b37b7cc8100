// Base-colour textures to the GPU with a mip chain: level 0 copied from the packed layers, the
// other levels blitted 2:1 with a linear filter from the level above (an sRGB format is decoded
// to linear for the filter and encoded again, Vulkan's blit rule), or computed on the CPU
// (downsample_layers, same rule) where the format cannot be blitted or linearly filtered.
#include "texture_upload.h"

#include <lintel/gpu/buffer.h>
#include "vk_status.h"

#include <algorithm>
#include <cstring>

namespace lintel::render {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_SRGB;

bool can_blit_mips(VkPhysicalDevice physical) {
  VkFormatProperties p;
  vkGetPhysicalDeviceFormatProperties(physical, kFormat, &p);
  const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                    VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  return (p.optimalTilingFeatures & need) == need;
}

// One image barrier over `levels` levels from `base` of every layer.
void transition(VkCommandBuffer cmd, VkImage image, uint32_t layers, uint32_t base, uint32_t levels, VkImageLayout from,
                VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = src_stage;
  b.srcAccessMask = src_access;
  b.dstStageMask = dst_stage;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, base, levels, 0, layers};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

uint32_t mip_level_count(uint32_t size) {
  uint32_t levels = 1;
  while (size > 1) {
    size /= 2;
    ++levels;
  }
  return levels;
}

Status upload_base_color_textures(gpu::Context& ctx, const TextureLayers& t, bool force_cpu_mips, GpuImage& out,
                                  bool* used_blit) {
  const uint32_t levels = mip_level_count(t.size);
  const bool blit = !force_cpu_mips && can_blit_mips(ctx.physical_device());
  if (used_blit) *used_blit = blit;
  // Staging: level 0 for the blit path; every level, one after another, for the CPU path.
  std::vector<uint8_t> bytes = t.rgba8;
  std::vector<VkBufferImageCopy> copies;
  {
    VkBufferImageCopy c{};
    c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, t.count};
    c.imageExtent = {t.size, t.size, 1};
    copies.push_back(c);
  }
  if (!blit) {
    std::vector<uint8_t> level = t.rgba8;
    uint32_t size = t.size;
    for (uint32_t l = 1; l < levels; ++l) {
      level = downsample_layers(level, size, t.count);
      size = std::max(1u, size / 2);
      VkBufferImageCopy c{};
      c.bufferOffset = bytes.size();
      c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, t.count};
      c.imageExtent = {size, size, 1};
      copies.push_back(c);
      bytes.insert(bytes.end(), level.begin(), level.end());
    }
  }
  VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (blit) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  ImageDesc desc{kFormat, t.size, t.size, t.count, usage, false, true};
  desc.mip_levels = levels;
  Status s = GpuImage::create(ctx, desc, "base-colour textures", out);
  gpu::Buffer staging;
  if (s)
    s = gpu::Buffer::create(ctx, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload,
                            "texture staging", staging);
  if (!s) return s;
  std::memcpy(staging.mapped(), bytes.data(), bytes.size());
  const VkImage image = out.handle();
  const uint32_t layers = t.count;
  return ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        constexpr VkImageLayout kDst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                kSrc = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        transition(cmd, image, layers, 0, levels, VK_IMAGE_LAYOUT_UNDEFINED, kDst, VK_PIPELINE_STAGE_2_NONE, 0,
                   kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(cmd, staging.handle(), image, kDst, uint32_t(copies.size()), copies.data());
        if (!blit) {
          transition(cmd, image, layers, 0, levels, kDst, kRead, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kFragment,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
          return;
        }
        int32_t size = int32_t(t.size);
        for (uint32_t l = 1; l < levels; ++l) {
          // Level l - 1 is complete (copied or blitted): read it into level l.
          transition(cmd, image, layers, l - 1, 1, kDst, kSrc, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer,
                     VK_ACCESS_2_TRANSFER_READ_BIT);
          const int32_t half = std::max(1, size / 2);
          VkImageBlit region{};
          region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l - 1, 0, layers};
          region.srcOffsets[1] = {size, size, 1};
          region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, layers};
          region.dstOffsets[1] = {half, half, 1};
          vkCmdBlitImage(cmd, image, kSrc, image, kDst, 1, &region, VK_FILTER_LINEAR);
          size = half;
        }
        if (levels > 1)
          transition(cmd, image, layers, 0, levels - 1, kSrc, kRead, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT,
                     kFragment, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        transition(cmd, image, layers, levels - 1, 1, kDst, kRead, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kFragment,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
      },
      "base-colour textures");
}

Status create_base_color_sampler(VkDevice device, VkSampler& out) {
  VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  si.magFilter = si.minFilter = VK_FILTER_LINEAR;
  si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  si.maxLod = VK_LOD_CLAMP_NONE;
  return gpu::vk_check(vkCreateSampler(device, &si, nullptr, &out), "vkCreateSampler", "textures");
}

}  // namespace lintel::render
