// A minimal indirect renderer for the raster test: one graphics pipeline that draws the cull's
// commands into an R32_UINT image (instance id + 1 per pixel), its vertex shader reading the
// cull's id buffer at gl_InstanceIndex. Dynamic rendering, no window.
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_pass.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::gpu::test {

class IdRaster {
 public:
  static constexpr uint32_t kSize = 256;  // square target, pixels

  // Geometry: all meshes' vertices and indices concatenated (concatenated_mesh_ranges order);
  // offsets_ndc: per instance, the NDC translation of its mesh.
  Status init(Context& ctx, const std::vector<glm::vec3>& vertices, const std::vector<uint32_t>& indices,
              const std::vector<glm::vec2>& offsets_ndc);
  ~IdRaster();

  // Records pass.record() and the draws in one submission, then reads the image back
  // (row-major, kSize x kSize). use_count: vkCmdDrawIndexedIndirectCount on the compacted list
  // instead of vkCmdDrawIndexedIndirect on every group's command.
  Status cull_and_draw(const CullPass& pass, bool use_count, std::vector<uint32_t>& pixels);

  // The pixel holding NDC point p (viewport with positive height: NDC y = -1 is row 0).
  static uint32_t pixel_index(glm::vec2 p_ndc);

 private:
  Context* ctx_ = nullptr;
  Buffer vertices_, indices_, offsets_, readback_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory image_memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkBuffer bound_ids_ = VK_NULL_HANDLE;
};

}  // namespace lintel::gpu::test
