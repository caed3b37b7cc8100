// Readback (Renderer::render only, PassKind::Readback): the final image and, on request, the HDR
// image, the g-buffer's cell ids and the fragment counts, copied into host-visible buffers. The
// render graph makes the copies visible to the host (Use::HostRead); render() reads them after
// its fence.
#pragma once

#include "pass_common.h"

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include "gpu_image.h"
#include <lintel/render/renderer.h>

namespace lintel::render {

struct ReadbackSources {
  const GpuImage* ldr = nullptr;
  const GpuImage* hdr = nullptr;                 // null: not read back
  const GpuImage* cell_ids = nullptr;            // null: not read back
  const gpu::Buffer* fragment_counts = nullptr;  // null: not read back
  uint32_t fragment_count_entries = 0;           // drawables (the buffer may be padded)
};

class ReadbackPass {
 public:
  static Status create(gpu::Context& ctx, const ReadbackSources& sources, ReadbackPass& out);
  void record(VkCommandBuffer cmd) const;
  // The host-side buffers, for the graph's HostRead declaration (null where not read back).
  VkBuffer ldr() const { return ldr_.handle(); }
  VkBuffer hdr() const { return hdr_.handle(); }
  VkBuffer cells() const { return cells_.handle(); }
  VkBuffer counts() const { return counts_.handle(); }
  // Copies what was read back into `out` (after the submission's fence).
  void read(uint32_t width, uint32_t height, RenderedFrame& out) const;

 private:
  ReadbackSources sources_;
  gpu::Buffer ldr_, hdr_, cells_, counts_;
};

}  // namespace lintel::render
