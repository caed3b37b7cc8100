// Moving objects without a scene re-upload: the records of the instances that moved go through a
// small per-slot staging buffer and are copied by the slot's next record(). An instance whose
// bounds now reach several cells gets its new reach list in the spare room after the scene's lists
// (its old list stays: another frame in flight may still read it).
#include <lintel/gpu/cull_pass.h>

#include "cull_pass_internal.h"

#include <cassert>
#include <cstring>
#include <string>
#include <utility>

namespace lintel::gpu {

Status CullPass::update_instances(std::span<const uint32_t> ids, const CullScene& scene, uint32_t slot_index) {
  assert(instances_ && "set_scene before update_instances");
  assert(slot_index < slots_.size());
  Slot& slot = slots_[slot_index];
  if (scene.instances.size() != instance_count_ || scene.groups.size() != group_count_ ||
      scene.cell_count != cell_count_)
    return Status::error("GPU cull: update_instances: the scene has " + std::to_string(scene.instances.size()) +
                         " instances, " + std::to_string(scene.groups.size()) + " groups and " +
                         std::to_string(scene.cell_count) + " cells; the uploaded one " +
                         std::to_string(instance_count_) + ", " + std::to_string(group_count_) + " and " +
                         std::to_string(cell_count_) + " (call set_scene)");
  uint64_t reach_entries = 0, newly_moved = 0;
  for (uint32_t id : ids) {
    if (id >= instance_count_)
      return Status::error("GPU cull: update_instances: instance " + std::to_string(id) + " of " +
                           std::to_string(instance_count_));
    if (Status s = detail::check_instance(scene, id, group_count_); !s) return s;
    const uint32_t cell = scene.instances[id].cell;
    if (cell != kNoRegion && (cell & kReachListBit)) reach_entries += 1 + scene.reach[cell & ~kReachListBit];
    const uint32_t position = position_of_id_[id];
    newly_moved += !position_listed_[position] && home_cell(position) != kLooseWork && cell != home_cell(position);
  }
  if (reach_used_ + reach_entries > reach_capacity_)
    return Status::unsupported("GPU cull: update_instances: the spare room for re-uploaded reach lists (" +
                               std::to_string(kReachSpareEntries) + " entries) is used up; call set_scene");
  // (Counted with repeats in `ids`: conservative.)
  if (moved_count_ + newly_moved > kMaxMovedInstances)
    return Status::unsupported("GPU cull: update_instances: over " + std::to_string(kMaxMovedInstances) +
                               " instances moved out of the cell they were uploaded in; call set_scene");
  // An instance leaving the range it is stored in joins the moved list for good (the shader skips
  // it there while it is back home, and skips it in its home range while it is away).
  for (uint32_t id : ids) {
    const uint32_t position = position_of_id_[id];
    const uint32_t home = home_cell(position);
    if (position_listed_[position] || home == kLooseWork || scene.instances[id].cell == home) continue;
    position_listed_[position] = 1;
    const uint32_t window = position / window_instances_;
    moved_by_window_[window].push_back({position - window * window_instances_, home});
    ++moved_count_;
  }

  // Staged after whatever this slot already holds for its next record (two updates before one
  // frame both land).
  VkDeviceSize held = slot.instance_copies.size() * sizeof(GpuInstance);
  for (const VkBufferCopy& c : slot.reach_copies) held += c.size;
  const VkDeviceSize need = held + VkDeviceSize(ids.size()) * sizeof(GpuInstance) + reach_entries * 4;
  if (need == held) return {};
  if (!slot.update_staging || slot.update_staging.size() < need) {
    Buffer bigger;
    const VkDeviceSize bytes =
        detail::at_least(std::max(need, slot.update_staging ? 2 * slot.update_staging.size() : 0));
    if (Status s = Buffer::create(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload,
                                  "cull instance update staging", bigger);
        !s)
      return s;
    // The slot's previous frame finished (precondition), so its staging may go; what is held moves.
    if (held) std::memcpy(bigger.mapped(), slot.update_staging.mapped(), held);
    slot.update_staging = std::move(bigger);
  }
  char* staging = static_cast<char*>(slot.update_staging.mapped());
  VkDeviceSize at = held;
  for (uint32_t id : ids) {
    GpuInstance record = scene.instances[id];
    if (record.cell != kNoRegion && (record.cell & kReachListBit)) {
      const uint32_t from = record.cell & ~kReachListBit;
      const uint32_t entries = 1 + scene.reach[from];
      std::memcpy(staging + at, scene.reach.data() + from, VkDeviceSize(entries) * 4);
      slot.reach_copies.push_back({at, VkDeviceSize(reach_used_) * 4, VkDeviceSize(entries) * 4});
      record.cell = kReachListBit | reach_used_;
      reach_used_ += entries;
      at += VkDeviceSize(entries) * 4;
    }
    // One copy per instance: copies with the same destination would race within vkCmdCopyBuffer,
    // so an instance staged again (twice in `ids`, or in two calls before a record) is overwritten.
    if (auto [it, added] = slot.staged_instance.try_emplace(id, at); !added) {
      std::memcpy(staging + it->second, &record, sizeof(record));
      continue;
    }
    std::memcpy(staging + at, &record, sizeof(record));
    slot.instance_copies.push_back({at, VkDeviceSize(position_of_id_[id]) * sizeof(GpuInstance), sizeof(GpuInstance)});
    at += sizeof(GpuInstance);
  }
  return {};
}

}  // namespace lintel::gpu
