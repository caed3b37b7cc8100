// What a frame dispatches: work items (one workgroup each) over the ranges of the visible cells in
// the cell-ordered instance buffer, plus the loose range (instances reaching several cells), and
// the moved list (instances update_instances moved out of their range). Work is proportional to
// what the visible cells hold, not to the scene; each dispatch stays within one window (so it tests
// at most kMaxInstancesPerDispatch instances) and runs at most kMaxWorkPerDispatch workgroups.
#include <lintel/gpu/cull_pass.h>

#include "cull_pass_internal.h"

#include <algorithm>
#include <cstring>

namespace lintel::gpu {

void CullPass::plan_work(std::span<const uint32_t> cell_region, Slot& slot) const {
  slot.work_items.clear();
  slot.dispatches.clear();
  // The TDR-safe bound: a dispatch stays in one window, so it tests at most a window's instances
  // (<= instances_per_dispatch <= kMaxInstancesPerDispatch), in at most kMaxWorkPerDispatch groups.
  const uint32_t per_dispatch = options_.work_per_dispatch;
  // Chunks of [begin, end) of at most one workgroup, none crossing a window boundary. Items come
  // in ascending positions (cells in order, then the loose range), so windows never go back.
  auto add_range = [&](uint32_t begin, uint32_t end, uint32_t cell, uint32_t region, uint32_t kind) {
    while (begin < end) {
      const uint32_t window = begin / window_instances_;
      const uint32_t window_end = std::min(end, (window + 1) * window_instances_);
      const uint32_t count = std::min(kCullWorkgroupSize, window_end - begin);
      Dispatch* last = slot.dispatches.empty() ? nullptr : &slot.dispatches.back();
      if (!last || last->window != window || last->count == per_dispatch || last->kind != kind)
        slot.dispatches.push_back({window, uint32_t(slot.work_items.size()), 0, kind});
      ++slot.dispatches.back().count;
      slot.work_items.push_back({begin - window * window_instances_, count, cell, region});
      begin += count;
    }
  };
  for (uint32_t c = 0; c < cell_count_; ++c)
    if (cell_region[c] != kNoRegion) add_range(cell_begin_[c], cell_begin_[c + 1], c, cell_region[c], kWorkItems);
  // The loose range's items test each instance by its own record: the own-region pipeline.
  add_range(cell_begin_[cell_count_], instance_count_, kLooseWork, 0, kWorkLoose);
  slot.item_dispatches = slot.dispatches.size();
}

void CullPass::plan_moved(const Slot& slot) const {
  slot.dispatches.resize(slot.item_dispatches);
  if (moved_count_ == 0) return;
  glm::uvec2* out = static_cast<glm::uvec2*>(slot.moved.mapped());
  uint32_t at = 0;
  for (uint32_t w = 0; w < moved_by_window_.size(); ++w) {
    const std::vector<glm::uvec2>& entries = moved_by_window_[w];
    if (entries.empty()) continue;
    std::memcpy(out + at, entries.data(), entries.size() * sizeof(glm::uvec2));
    // At most kMaxMovedInstances threads: within the bound of one dispatch.
    slot.dispatches.push_back({w, at, uint32_t(entries.size()), kWorkMoved});
    at += uint32_t(entries.size());
  }
}

uint32_t CullPass::home_cell(uint32_t position) const {
  if (position >= cell_begin_[cell_count_]) return kLooseWork;
  // The last cell whose range begins at or before `position` (empty ranges share a begin).
  return uint32_t(std::upper_bound(cell_begin_.begin(), cell_begin_.end(), position) - cell_begin_.begin()) - 1;
}

}  // namespace lintel::gpu
