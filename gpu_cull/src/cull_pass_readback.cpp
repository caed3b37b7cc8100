// Getting the cull's results to the host (tests, tools, `lintel walk --gpu-cull`): per-slot
// readback copies, their parsing, the one-shot run(), and the output barrier a render graph places
// in the pass's stead.
#include <lintel/gpu/cull_pass.h>

#include "cull_pass_internal.h"

#include <cassert>
#include <chrono>
#include <cstring>
#include <string>

namespace lintel::gpu {

CullOutputBarrier CullPass::output_barrier_info() const {
  CullOutputBarrier out;
  out.buffers[0] = commands_.handle();
  out.buffers[1] = compact_commands_.handle();
  out.buffers[2] = compact_groups_.handle();
  out.buffers[3] = counters_.handle();
  out.buffers[4] = ids_.handle();
  return out;
}

void CullPass::record_readback(VkCommandBuffer cmd, uint32_t slot, bool stats_only) const {
  assert(slot < slots_.size());
  const VkBuffer readback = slots_[slot].readback.handle();
  // After the cull's writes whether or not record() placed its output barrier.
  detail::barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkDeviceSize command_bytes = VkDeviceSize(group_count_) * sizeof(DrawIndexedCommand);
  const VkDeviceSize counter_bytes = sizeof(GpuCullStats) + VkDeviceSize(group_count_) * 4;
  const VkDeviceSize id_bytes = stats_only ? 0 : VkDeviceSize(id_capacity_) * 4;
  if (stats_only) {
    VkBufferCopy stats{0, command_bytes, sizeof(GpuCullStats)};
    vkCmdCopyBuffer(cmd, counters_.handle(), readback, 1, &stats);
  } else if (command_bytes) {
    VkBufferCopy copy{0, 0, command_bytes};
    vkCmdCopyBuffer(cmd, commands_.handle(), readback, 1, &copy);
  }
  if (!stats_only) {
    VkBufferCopy counters{0, command_bytes, counter_bytes};
    vkCmdCopyBuffer(cmd, counters_.handle(), readback, 1, &counters);
  }
  if (id_bytes) {
    VkBufferCopy copy{0, command_bytes + counter_bytes, id_bytes};
    vkCmdCopyBuffer(cmd, ids_.handle(), readback, 1, &copy);
  }
  detail::barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
}

Status CullPass::read_back(uint32_t slot, bool stats_only, CullReadback& out) const {
  assert(slot < slots_.size());
  const char* base = static_cast<const char*>(slots_[slot].readback.mapped());
  const VkDeviceSize command_bytes = VkDeviceSize(group_count_) * sizeof(DrawIndexedCommand);
  std::memcpy(&out.stats, base + command_bytes, sizeof(out.stats));
  if (stats_only) {
    out.commands.clear();
    out.instance_ids.clear();
  } else {
    out.commands.resize(group_count_);
    out.instance_ids.resize(id_capacity_);
    if (command_bytes) std::memcpy(out.commands.data(), base, command_bytes);
    if (id_capacity_)
      std::memcpy(out.instance_ids.data(), base + command_bytes + sizeof(GpuCullStats) + VkDeviceSize(group_count_) * 4,
                  VkDeviceSize(id_capacity_) * 4);
  }
  if (out.stats.overflow_instances)
    return Status::error("GPU cull: " + std::to_string(out.stats.overflow_instances) +
                         " visible instances overflowed the id capacity of " +
                         std::to_string(out.stats.overflow_groups) +
                         " draw groups and were not drawn (ids stayed in bounds)");
  return {};
}

Status CullPass::run(CullReadback* out, CullTimings* timings) {
  const auto start = std::chrono::steady_clock::now();
  Status s = ctx_.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        record(cmd, 0);
        record_readback(cmd, 0, out == nullptr);
      },
      "GPU cull");
  const auto end = std::chrono::steady_clock::now();
  if (!s) return s;
  if (timings) {
    timings->wall_ms = std::chrono::duration<double, std::milli>(end - start).count();
    timings->gpu_ms = -1.0;
    uint64_t ticks[2] = {0, 0};
    if (timestamps_ && vkGetQueryPoolResults(ctx_.device(), timestamps_, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                                             VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS)
      timings->gpu_ms = double(ticks[1] - ticks[0]) * ctx_.info().timestamp_period_ns * 1e-6;
  }
  CullReadback stats_only;
  return read_back(0, out == nullptr, out ? *out : stats_only);
}

}  // namespace lintel::gpu
