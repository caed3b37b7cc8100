// The GPU cull pass: the instances of every visible cell against the frustum and that cell's clip
// region, survivors appended to their draw group's id range, one VkDrawIndexedIndirectCommand per
// group (firstInstance = the group's base). set_scene stores the instances cell by cell, so a frame
// dispatches work only for its visible cells. docs/gpu_cull.md has the data layout and the barriers.
//
// Per frame: set_frame(), then record() into the frame's command buffer (or run() to submit, wait
// and read back). With frames_in_flight = N, the caller cycles N slots: set_frame(frame, slot) and
// record(cmd, slot) for frame k use slot k % N, once the caller's fence says that slot's previous
// frame finished. Nothing on the per-frame path submits or waits. The renderer then draws with
// draw_commands() (group order, drawCount = group count, stride 20) or, where
// Context::info().draw_indirect_count, with compact_commands() and the count at counters() offset
// 0; its vertex shader reads instance_ids()[gl_InstanceIndex].
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_shared.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

namespace lintel::gpu {

// How survivors take their slots in their draw group's id range (cull.comp): one atomicAdd each;
// one per group per subgroup (needs subgroup ballot; without it: Atomic); or one per group per
// workgroup, through shared memory. Auto: Atomic on CPU devices (lavapipe: the subgroup loop and
// the workgroup variant's barriers cost more there than the atomics they save), Subgroup elsewhere
// (measured: docs/perf.md).
enum class CullAppend : uint32_t {
  Atomic = kAppendAtomic,
  Subgroup = kAppendSubgroup,
  Workgroup = kAppendWorkgroup,
  Auto,
};

// Boxes that straddle the near or far plane need their 12 edges clipped. Inline: every thread has
// the clipping code. Deferred: the cell items leave such boxes to a list that a second, indirect
// dispatch after each cell dispatch tests with it (a few per frame), so the cell items' pipeline
// compiles without it: lavapipe runs both sides of every branch, so inline it costs every box.
// Auto: Deferred on CPU devices, Inline elsewhere.
enum class CullStraddlers : uint32_t { Inline, Deferred, Auto };

struct CullPassOptions {
  CullAppend append = CullAppend::Auto;
  CullStraddlers straddlers = CullStraddlers::Auto;
  // Within a cell's range, store instances by draw group (then id): a workgroup's survivors then
  // share few groups, so CullAppend::Workgroup takes few global atomics. False: by id (tests).
  bool sort_by_group = true;
  // Work items (workgroups) per cull dispatch, <= kMaxWorkPerDispatch (benchmarks lower it to
  // measure what a dispatch and its barrier cost).
  uint32_t work_per_dispatch = kMaxWorkPerDispatch;
  // Test the per-cell clip regions (false: visible cell + frustum only, a coarser variant).
  bool test_regions = true;
  // Instances per window of the cell-ordered instance buffer and most threads per dispatch,
  // <= kMaxInstancesPerDispatch, a multiple of kCullWorkgroupSize (tests lower it to exercise the
  // split on small scenes).
  uint32_t instances_per_dispatch = kMaxInstancesPerDispatch;
  // Record timestamps around the cull where the device supports them (run() reports them).
  bool timestamps = false;
  // Frames the caller may have in flight at once (1..kMaxFramesInFlight): each slot has its own
  // host-written buffers (frame staging, region buffers, instance-update staging, readback), so
  // filling slot k+1 never touches what the GPU still reads for slot k. The outputs are shared;
  // record() orders each frame's writes after the previous frame's reads (docs/gpu_cull.md).
  uint32_t frames_in_flight = 1;
  // Whether record() ends with the barrier that makes the outputs visible to the draws. False: the
  // caller's render graph places it, from output_barrier_info().
  bool output_barrier = true;
};

inline constexpr uint32_t kMaxFramesInFlight = 8;
// Reach-list entries set aside after the scene's for update_instances (an instance that moves to
// reach several cells gets its new list there): 256 KiB. Reset by set_scene.
inline constexpr uint32_t kReachSpareEntries = 1u << 16;

// What a render graph needs to order its draws after record() when CullPassOptions::output_barrier
// is false: the pass's last writes (src) and the reads the draws make (dst), on these buffers.
// memory_barrier() is the one global barrier record() would have placed.
struct CullOutputBarrier {
  VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  VkAccessFlags2 src_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
  VkAccessFlags2 dst_access = VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
  // Written by the pass: draw commands, compacted commands, compacted group ids, counters (draw
  // count at 0), instance ids. Whole buffers (offset 0, VK_WHOLE_SIZE).
  VkBuffer buffers[5] = {VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkMemoryBarrier2 memory_barrier() const {
    VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    return b;
  }
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

  // Uploads a scene (blocking: a one-shot submit and wait, outside the frame loop). Errors: a scene
  // over the limits or over the device's maxStorageBufferRange. Precondition: no recorded work of
  // this pass in flight (every slot's fence waited).
  Status set_scene(const CullScene& scene);
  // Writes a frame's camera and regions into `slot`'s staging (host memory only: no submit, no
  // wait); record(cmd, slot) copies them to the GPU. Grows the slot's buffers when a frame needs
  // more (geometrically, so a walk settles quickly). Precondition: slot < frames_in_flight, and
  // the slot's previous frame finished on the GPU. Errors: frame.cell_region.size() != the scene's
  // cell_count, indices out of range.
  Status set_frame(const CullFrame& frame, uint32_t slot);
  Status set_frame(const CullFrame& frame) { return set_frame(frame, 0); }
  // Moved objects: re-uploads the records of instances `ids` from `scene` (the world re-packed
  // with pack_scene after the move; same instance and group counts as set_scene's) through `slot`'s
  // small staging buffer; the next record(cmd, slot) copies them (32 B each, plus the reach list
  // of an instance that now reaches several cells). An instance whose record now names another
  // cell than the one whose range holds it joins the moved list, which every record() dispatches
  // (until set_scene sorts it into its new cell). No submit, no wait; same slot precondition as
  // set_frame. Errors: counts that differ from the uploaded scene, an id out of range, a record
  // with a bad group or reach list; Unsupported: the spare room for re-uploaded reach lists
  // (kReachSpareEntries) or the moved list (kMaxMovedInstances) is used up -- call set_scene to
  // start afresh.
  Status update_instances(std::span<const uint32_t> ids, const CullScene& scene, uint32_t slot = 0);

  // Records the whole pass for `slot`'s frame: a barrier after the previous frame's users of the
  // shared buffers, the frame upload, pending instance updates, counter reset, cull dispatches,
  // finalize, and (with output_barrier) the barrier that makes commands, ids and the draw count
  // visible to DRAW_INDIRECT and VERTEX_SHADER reads. Pending instance updates are recorded once,
  // into this command buffer (submit it); calls for different slots must not run concurrently.
  void record(VkCommandBuffer cmd, uint32_t slot) const;
  void record(VkCommandBuffer cmd) const { record(cmd, 0); }
  // Records copies of commands, counters and ids (only the GpuCullStats with `stats_only`) into
  // `slot`'s host-visible readback buffer, after record(cmd, slot); read_back() reads it once the
  // submission finished.
  void record_readback(VkCommandBuffer cmd, uint32_t slot, bool stats_only) const;
  void record_readback(VkCommandBuffer cmd, bool stats_only = false) const { record_readback(cmd, 0, stats_only); }
  // What record_readback(cmd, slot, stats_only) copied (the stats alone when `stats_only` was
  // set; then out->commands and instance_ids are left empty). Precondition: that submission
  // finished. Errors: capacity overflow, as run().
  Status read_back(uint32_t slot, bool stats_only, CullReadback& out) const;

  // The barrier the caller must place after record() when output_barrier is false.
  CullOutputBarrier output_barrier_info() const;

  // record() + record_readback() of slot 0 in a one-shot submit (a tool's and a test's call, not a
  // frame loop's); waits; reads back (the stats alone when `out` is null, e.g. for timing). `timings->wall_ms` spans recording to fence. Errors:
  // Vulkan failures, and capacity overflow (stats.overflow_instances > 0; the ids stay in bounds).
  Status run(CullReadback* out, CullTimings* timings = nullptr);

  VkBuffer draw_commands() const { return commands_.handle(); }
  VkBuffer compact_commands() const { return compact_commands_.handle(); }
  VkBuffer compact_groups() const { return compact_groups_.handle(); }
  VkBuffer counters() const { return counters_.handle(); }  // GpuCullStats at 0, draw_count first
  VkBuffer instance_ids() const { return ids_.handle(); }
  uint32_t group_count() const { return group_count_; }
  uint32_t frames_in_flight() const { return options_.frames_in_flight; }
  // The append mode in use: options.append resolved (Auto; Subgroup without ballot is Atomic).
  CullAppend append_mode() const { return append_; }
  bool defers_straddlers() const { return defer_straddlers_; }
  // Workgroups (of kCullWorkgroupSize threads) that `slot`'s frame dispatches over the ranges of
  // its visible cells and the loose range (instances reaching several cells); the moved list
  // comes on top. What the pass's work is proportional to: not the scene's instances.
  uint32_t work_items(uint32_t slot = 0) const { return uint32_t(slots_[slot].work_items.size()); }

 private:
  // What one frame in flight owns: everything the host writes per frame, and its descriptor set
  // (which points at its own region buffers and the shared scene and output buffers).
  // One cull dispatch: `count` work items from `first` (kWorkItems: cells' items, kWorkLoose: the
  // loose range's) or moved entries (kWorkMoved) in window `window`.
  struct Dispatch {
    uint32_t window = 0, first = 0, count = 0, kind = kWorkItems;
  };
  struct Slot {
    Buffer cell_region, regions, polygons, vertices, work, staging, readback;
    Buffer moved;           // host-visible: the moved list as record() last wrote it
    Buffer update_staging;  // instance records, then reach lists, of update_instances()
    VkDescriptorSet set = VK_NULL_HANDLE;
    GpuCullConstants constants{};
    // Bytes of cell_region, regions, polygons, vertices and work items this frame.
    VkDeviceSize frame_bytes[5] = {0, 0, 0, 0, 0};
    std::vector<GpuCullWork> work_items;       // scratch of set_frame (keeps its capacity)
    mutable std::vector<Dispatch> dispatches;  // set_frame's item dispatches, then record()'s moved ones
    size_t item_dispatches = 0;
    // Copies out of update_staging that the next record() makes, then forgets (so an older update
    // never overwrites a newer one staged in another slot).
    mutable std::vector<VkBufferCopy> instance_copies, reach_copies;
    mutable std::unordered_map<uint32_t, VkDeviceSize> staged_instance;  // id -> its record in update_staging
  };

  CullPass(Context& ctx, const CullPassOptions& options) : ctx_(ctx), options_(options) {}
  Status create_pipelines();
  Status ensure_frame_capacity(const CullFrame& frame, Slot& slot);
  void write_descriptors(const Slot& slot);
  // The work items of a frame whose cells have regions `cell_region`: chunks of the visible cells'
  // ranges and of the loose range, none crossing a window, and the dispatches that run them.
  void plan_work(std::span<const uint32_t> cell_region, Slot& slot) const;
  // Writes the moved list into slot.moved and appends its dispatches (record(): always current).
  void plan_moved(const Slot& slot) const;
  // The cell whose range holds `position`, or kLooseWork.
  uint32_t home_cell(uint32_t position) const;

  Context& ctx_;
  CullPassOptions options_;
  CullAppend append_ = CullAppend::Atomic;
  bool defer_straddlers_ = false;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline cull_pipeline_ = VK_NULL_HANDLE;      // cell items: the item's region in shared memory
  VkPipeline cull_own_pipeline_ = VK_NULL_HANDLE;  // loose items and the moved list: each its own region
  VkPipeline straddle_pipeline_ = VK_NULL_HANDLE;  // the straddler list (defer_straddlers_ only)
  VkPipeline finalize_pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;  // two queries per slot

  // Scene buffers (set_scene), shared by the slots.
  Buffer instances_, groups_, ids_, counters_, commands_, compact_commands_, compact_groups_, reach_;
  Buffer straddlers_;  // GpuStraddleHeader + a window's worth of entries (defer_straddlers_), else minimal
  uint32_t instance_count_ = 0, group_count_ = 0, cell_count_ = 0, id_capacity_ = 0;
  uint32_t window_instances_ = 0;  // instances bound per dispatch
  uint32_t reach_used_ = 0;        // reach entries in use: the scene's, then re-uploaded lists
  uint32_t reach_capacity_ = 0;    // the scene's + kReachSpareEntries
  // The cell-ordered layout (set_scene): cell c's instances at positions [cell_begin_[c],
  // cell_begin_[c + 1]), then the loose range (reach lists, empty bounds) up to instance_count_.
  Buffer position_ids_;                   // id of each position
  std::vector<uint32_t> cell_begin_;      // cell_count_ + 1
  std::vector<uint32_t> position_of_id_;  // where update_instances writes a record
  // The moved list, per window: {position in the window, home cell}; a position is listed once.
  std::vector<std::vector<glm::uvec2>> moved_by_window_;
  std::vector<uint8_t> position_listed_;
  uint32_t moved_count_ = 0;
  std::vector<Slot> slots_;
};

}  // namespace lintel::gpu
