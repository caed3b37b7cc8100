// A small render graph: named resources, passes that declare how they use them, and the barriers
// derived from those declarations — so the g-buffer pass declares what the lighting pass reads,
// and no pass hand-writes a barrier for a resource the graph knows (Granite's and Frostbite's
// idea, reduced to what one frame of Lintel needs: a fixed pass order, no aliasing, no culling of
// passes). record() also brackets every pass with timestamps where the device has them, which is
// where the per-pass frame-time breakdown (`lintel bench render`) comes from.
#pragma once

#include <lintel/render/gpu_image.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lintel::render {

// How a pass touches a resource. Each use fixes the pipeline stage, the access and, for images,
// the layout.
enum class Use {
  ColorWrite,     // color attachment (fragment output)
  DepthWrite,     // depth attachment, tested and written
  SampledRead,    // sampled in compute shaders (texelFetch)
  StorageRead,    // imageLoad / storage buffer read in compute shaders
  StorageWrite,   // imageStore / storage buffer write in compute shaders
  FragmentStorageWrite,  // storage buffer atomics in fragment shaders
  VertexRead,     // storage buffer read by vertex shaders
  IndirectRead,   // indirect draw arguments
  TransferSrc,    // copied out
  TransferDst,    // filled or copied into
};

struct ResourceId {
  uint32_t index = UINT32_MAX;
};

struct ResourceUse {
  ResourceId resource;
  Use use;
};

class RenderGraph {
 public:
  // Resources the renderer owns; the graph tracks their state across passes (and frames).
  ResourceId import_image(std::string name, const GpuImage* image);
  ResourceId import_buffer(std::string name, VkBuffer buffer);
  // Passes run in the order they are added. `record` is called between the pass's barriers and
  // its closing timestamp.
  void add_pass(std::string name, std::vector<ResourceUse> uses, std::function<void(VkCommandBuffer)> record);
  // Checks the declarations: every resource a pass reads was written by an earlier pass (or is
  // marked `preloaded`, e.g. static scene buffers). Errors name the pass and the resource.
  Status validate(const std::vector<ResourceId>& preloaded) const;

  // Records every pass with its barriers. Image contents do not carry over between frames
  // (first use in a frame starts from UNDEFINED); `timestamps` (2 per pass) may be null.
  void record(VkCommandBuffer cmd, VkQueryPool timestamps);

  size_t pass_count() const { return passes_.size(); }
  const std::string& pass_name(size_t i) const { return passes_[i].name; }
  // A one-line-per-pass description (reads/writes), for docs and `lintel render --graph`.
  std::string describe() const;

 private:
  struct Resource {
    std::string name;
    const GpuImage* image = nullptr;  // null for buffers
    VkBuffer buffer = VK_NULL_HANDLE;
    // State after the last recorded use.
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool last_was_write = false;
  };
  struct Pass {
    std::string name;
    std::vector<ResourceUse> uses;
    std::function<void(VkCommandBuffer)> record;
  };
  std::vector<Resource> resources_;
  std::vector<Pass> passes_;
  // record()'s scratch, kept so that recording a frame does not allocate after the first.
  std::vector<VkImageMemoryBarrier2> image_barriers_;
  std::vector<VkBufferMemoryBarrier2> buffer_barriers_;
};

}  // namespace lintel::render
