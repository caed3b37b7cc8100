// What the cull pass's source files share: the descriptor bindings, the one barrier helper, and
// the checks of scene, frame and updated instance data (each error names the element at fault).
#pragma once

#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_shared.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace lintel::gpu::detail {

// Must match cull_bindings.glsl.
enum Binding : uint32_t {
  kInstances = 0,  // dynamic: the dispatch's window
  kGroups,
  kCellRegion,
  kRegions,
  kPolygons,
  kVertices,
  kCounters,
  kIds,
  kCommands,
  kCompactCommands,
  kCompactGroups,
  kReach,
  kPositionIds,
  kWork,
  kMoved,
  kStraddlers,
  kBindingCount
};

inline constexpr VkDeviceSize kMinBufferBytes = 256;  // Vulkan has no empty buffers

inline VkDeviceSize at_least(VkDeviceSize bytes) { return std::max(bytes, kMinBufferBytes); }

inline uint32_t div_up(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

inline std::string mib(VkDeviceSize bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

inline void barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = src_stage;
  mb.srcAccessMask = src_access;
  mb.dstStageMask = dst_stage;
  mb.dstAccessMask = dst_access;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd, &dep);
}

Status check_scene(const CullScene& scene);
Status check_frame(const CullFrame& frame, uint32_t cell_count);
// Instance `i` of `scene` as update_instances uploads it: its group among `group_count`, its reach
// list (if any) inside scene.reach and within kMaxReachCells.
Status check_instance(const CullScene& scene, size_t i, uint32_t group_count);

}  // namespace lintel::gpu::detail
