// The GPU cull pass: every instance against the frustum and its cell's clip region, survivors
// appended to their draw group's id range, one VkDrawIndexedIndirectCommand per group
// (firstInstance = the group's base). docs/gpu_cull.md has the data layout and the barriers.
//
// Per frame: set_frame(), then record() into the frame's command buffer (or run() to submit, wait
// and read back). The renderer then draws with draw_commands() (group order, drawCount = group
// count, stride 20) or, where Context::info().draw_indirect_count, with compact_commands() and the
// count at counters() offset 0; its vertex shader reads instance_ids()[gl_InstanceIndex].
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_shared.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <memory>
#include <span>
#include <vector>

namespace lintel::gpu {

struct CullPassOptions {
  // Aggregate the id-append atomics per subgroup (one atomicAdd per group per subgroup instead of
  // one per survivor). Used only where the device has subgroup ballot in compute shaders.
  bool subgroup_aggregate = true;
  // Test the per-cell clip regions (false: visible cell + frustum only, a coarser variant).
  bool test_regions = true;
  // Instances per dispatch, <= kMaxInstancesPerDispatch, a multiple of kCullWorkgroupSize
  // (tests lower it to exercise the split on small scenes).
  uint32_t instances_per_dispatch = kMaxInstancesPerDispatch;
  // Record timestamps around the cull where the device supports them (run() reports them).
  bool timestamps = false;
};

// What run() reads back.
struct CullReadback {
  std::vector<DrawIndexedCommand> commands;  // one per group, group order
  std::vector<uint32_t> instance_ids;        // the whole id buffer (CullScene::id_capacity)
  GpuCullStats stats{};
  // Ids drawn by group g: instance_ids[cmd.first_instance .. + cmd.instance_count).
  std::span<const uint32_t> group_ids(uint32_t g) const {
    const DrawIndexedCommand& c = commands[g];
    return {instance_ids.data() + c.first_instance, c.instance_count};
  }
};

struct CullTimings {
  double wall_ms = 0.0;  // record + submit + wait of run() (frame copy, cull, finalize, readback)
  double gpu_ms = -1.0;  // timestamps around the cull; -1 where not recorded
};

class CullPass {
 public:
  static Status create(Context& ctx, const CullPassOptions& options, std::unique_ptr<CullPass>& out);
  ~CullPass();
  CullPass(const CullPass&) = delete;
  CullPass& operator=(const CullPass&) = delete;

  // Uploads a scene (blocking). Errors: a scene over the limits or over the device's
  // maxStorageBufferRange. Precondition for this and set_frame: no recorded work in flight.
  Status set_scene(const CullScene& scene);
  // Uploads a frame's camera and regions into staging; record() copies them to the GPU.
  // Precondition: frame.cell_region.size() == the scene's cell_count.
  Status set_frame(const CullFrame& frame);

  // Records the whole pass: frame upload, counter reset, cull dispatches, finalize, and the
  // barriers that make commands, ids and the draw count visible to DRAW_INDIRECT and
  // VERTEX_SHADER reads.
  void record(VkCommandBuffer cmd) const;
  // Records copies of commands, counters and ids (only the GpuCullStats with `stats_only`) into
  // host memory, after record().
  void record_readback(VkCommandBuffer cmd, bool stats_only = false) const;

  // record() + record_readback() in a one-shot submit; waits; reads back (the stats alone when
  // `out` is null, e.g. for timing). `timings->wall_ms` spans recording to fence. Errors:
  // Vulkan failures, and capacity overflow (stats.overflow_instances > 0; the ids stay in bounds).
  Status run(CullReadback* out, CullTimings* timings = nullptr);

  VkBuffer draw_commands() const { return commands_.handle(); }
  VkBuffer compact_commands() const { return compact_commands_.handle(); }
  VkBuffer compact_groups() const { return compact_groups_.handle(); }
  VkBuffer counters() const { return counters_.handle(); }  // GpuCullStats at 0, draw_count first
  VkBuffer instance_ids() const { return ids_.handle(); }
  uint32_t group_count() const { return group_count_; }
  bool uses_subgroup_aggregate() const { return subgroup_aggregate_; }

 private:
  CullPass(Context& ctx, const CullPassOptions& options) : ctx_(ctx), options_(options) {}
  Status create_pipelines();
  Status ensure_frame_capacity(const CullFrame& frame);
  void write_descriptors();

  Context& ctx_;
  CullPassOptions options_;
  bool subgroup_aggregate_ = false;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline cull_pipeline_ = VK_NULL_HANDLE;
  VkPipeline finalize_pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;

  // Scene buffers (set_scene).
  Buffer instances_, groups_, ids_, counters_, commands_, compact_commands_, compact_groups_, reach_;
  uint32_t instance_count_ = 0, group_count_ = 0, cell_count_ = 0, id_capacity_ = 0;
  uint32_t window_instances_ = 0;  // instances bound per dispatch
  // Frame buffers (set_frame): device copies and one staging buffer holding all four.
  Buffer cell_region_, regions_, polygons_, vertices_, frame_staging_;
  GpuCullConstants constants_{};
  VkDeviceSize frame_bytes_[4] = {0, 0, 0, 0};  // bytes of cell_region, regions, polygons, vertices this frame
  Buffer readback_;
};

}  // namespace lintel::gpu
