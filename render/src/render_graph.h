// A small render graph: named resources, passes that declare how they use them, and the barriers
// derived from those declarations — so the g-buffer pass declares what the lighting pass reads,
// and no pass hand-writes a barrier for a resource the graph knows (Granite's and Frostbite's
// idea, reduced to what one frame of Lintel needs: a fixed pass order, no aliasing, no culling of
// passes). record() also brackets every pass with timestamps where the device has them, which is
// where the per-pass frame-time breakdown (`lintel bench render`) comes from.
//
// The graph owns every barrier between passes, including those around the GPU cull's outputs
// (declared as written by the cull pass, read as indirect arguments and by vertex shaders) and
// the one that makes readback copies visible to the host. With several frames in flight, a
// resource may have one buffer per frame slot (host-written data, the cull's outputs); its state
// is then tracked per slot. Frames must be submitted in the order they were recorded: a frame's
// first use of a resource waits on the previous frame's last use in submission order.
#pragma once

#include "gpu_image.h"
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
  ColorWrite,            // color attachment (fragment output)
  DepthWrite,            // depth attachment, tested and written
  SampledRead,           // sampled in compute shaders (texelFetch)
  StorageRead,           // imageLoad / storage buffer read in compute shaders
  StorageWrite,          // imageStore / storage buffer write in compute shaders
  FragmentStorageWrite,  // storage buffer atomics in fragment shaders
  VertexRead,            // storage buffer read by vertex shaders
  IndirectRead,          // indirect draw arguments
  TransferSrc,           // copied out
  TransferDst,           // filled or copied into
  CopyAndComputeWrite,   // filled by transfers, then written by compute shaders (the GPU cull's outputs)
  HostRead,              // read by the host after the submission's fence (readback buffers)
};

// When a pass runs: every frame, or only when the frame is read back (Renderer::render).
enum class PassKind { Frame, Readback };

struct RecordOptions {
  uint32_t slot = 0;                        // frame slot: which buffer of a per-slot resource
  VkQueryPool timestamps = VK_NULL_HANDLE;  // 2 per pass from `first_query`; may be null
  uint32_t first_query = 0;
  bool readback = false;  // also record the PassKind::Readback passes
};

// A resource's state as a pass leaves it: what the next user must wait for and, for images,
// the layout it is in.
struct ResourceState {
  VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
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
  // `keep`: the image's contents carry over to the next frame (its first use there transitions
  // from the layout the previous frame left, after all earlier work) instead of being discarded;
  // the shadow atlas keeps its cached layers so.
  ResourceId import_image(std::string name, const GpuImage* image, bool keep = false);
  ResourceId import_buffer(std::string name, VkBuffer buffer);
  // One buffer per frame slot (slot k uses per_slot[k % size]).
  ResourceId import_buffers(std::string name, std::vector<VkBuffer> per_slot);
  // Passes run in the order they are added. `record` is called between the pass's barriers and
  // its closing timestamp, with the frame slot being recorded.
  void add_pass(std::string name, std::vector<ResourceUse> uses,
                std::function<void(VkCommandBuffer, uint32_t slot)> record, PassKind kind = PassKind::Frame);
  // Checks the declarations: every resource a pass reads was written by an earlier pass (or is
  // marked `preloaded`, e.g. static scene buffers). Errors name the pass and the resource.
  Status validate(const std::vector<ResourceId>& preloaded) const;

  // Records every pass with its barriers. Image contents do not carry over between frames (except
  // an image imported with `keep`): an image's first use in a frame starts from UNDEFINED after
  // everything submitted before (ALL_COMMANDS, MEMORY_WRITE), so whatever a caller did with an
  // image between frames is safe.
  void record(VkCommandBuffer cmd, const RecordOptions& options);

  // The state `resource` is left in by its last use among the PassKind::Frame passes: what a
  // caller that reads it after the graph must wait for. Fixed once the passes are added.
  ResourceState state_after_frame(ResourceId resource) const;

  size_t pass_count() const { return passes_.size(); }
  const std::string& pass_name(size_t i) const { return passes_[i].name; }
  // A one-line-per-pass description (reads/writes), for docs and `lintel render --graph`.
  std::string describe() const;

 private:
  struct Resource {
    std::string name;
    const GpuImage* image = nullptr;  // null for buffers
    bool keep = false;                // an image whose contents carry over between frames
    std::vector<VkBuffer> buffers;    // buffers: one, or one per frame slot
    // State after the last recorded use, per buffer (images: one).
    struct State {
      VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
      VkAccessFlags2 access = VK_ACCESS_2_NONE;
      VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
      bool last_was_write = false;
      // The last write, and the stages and accesses it has been made visible to since: a read in
      // a stage outside them needs its own barrier from the write, even after other reads.
      VkPipelineStageFlags2 write_stage = VK_PIPELINE_STAGE_2_NONE;
      VkAccessFlags2 write_access = VK_ACCESS_2_NONE;
      VkPipelineStageFlags2 visible_stage = VK_PIPELINE_STAGE_2_NONE;
      VkAccessFlags2 visible_access = VK_ACCESS_2_NONE;
    };
    std::vector<State> states;
  };
  struct Pass {
    std::string name;
    std::vector<ResourceUse> uses;
    std::function<void(VkCommandBuffer, uint32_t)> record;
    PassKind kind = PassKind::Frame;
  };
  std::vector<Resource> resources_;
  std::vector<Pass> passes_;
  // record()'s scratch, kept so that recording a frame does not allocate after the first.
  std::vector<VkImageMemoryBarrier2> image_barriers_;
  std::vector<VkBufferMemoryBarrier2> buffer_barriers_;
};

}  // namespace lintel::render
