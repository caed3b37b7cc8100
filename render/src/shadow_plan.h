// The shadow atlas planned against the device before anything is created: how many layers
// ("slots") it gets and at what resolution, from maxImageArrayLayers, the format's limits,
// maxMemoryAllocationSize, the device-local heap and the renderer's own shadow memory budget.
// Frames then give slots to their active lights only (shadow_slots_for_frame).
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/render/render_shared.h>
#include <lintel/status.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::render {

// What the device allows for a D32_SFLOAT sampled + depth-attachment 2D array.
struct ShadowDeviceLimits {
  uint32_t max_layers = 0;            // min(maxImageArrayLayers, the format's maxArrayLayers)
  uint32_t max_extent = 0;            // min(maxImageDimension2D, the format's max extent)
  uint64_t max_allocation_bytes = 0;  // maxMemoryAllocationSize (Vulkan 1.1 maintenance3)
  uint64_t max_resource_bytes = 0;    // the format's maxResourceSize
  uint64_t heap_bytes = 0;            // budget (VK_EXT_memory_budget) or size of the device-local heap
};

Status query_shadow_device_limits(const gpu::Context& ctx, ShadowDeviceLimits& out);

struct ShadowPlan {
  uint32_t resolution = 0;  // per layer, square
  uint32_t slots = 0;       // layers of the atlas (>= 1)
  uint64_t bytes = 0;       // resolution^2 x 4 x slots
  std::string note;         // non-empty when the request was reduced (why, in one line)
};

// requested_resolution: RenderOptions::shadow_resolution; views_wanted: upper bound of the shadow
// views the scene's lights have (one slot each when all are active at once); budget_bytes: the
// renderer's cap (RenderOptions::shadow_memory_budget_mib). The atlas never exceeds any device
// limit, nor budget_bytes, nor a quarter of the heap. The resolution is halved (down to 16) until
// at least min(views_wanted, kMinShadowSlots) slots fit; then slots = min(views_wanted, what fits).
// Errors (Unsupported): not even one 16 x 16 slot fits.
inline constexpr uint32_t kMinShadowSlots = 24;  // 4 point lights (6 faces each) at full resolution
Status plan_shadow_atlas(const ShadowDeviceLimits& limits, uint32_t requested_resolution, uint32_t views_wanted,
                         uint64_t budget_bytes, ShadowPlan& out);

// Per frame: the slots of `frame_lights` (already ordered by priority, most important first),
// consecutive per light, first come first served. A light whose views do not all fit gets
// kNoShadowSlot (render_shared.h): it lights unshadowed (documented degradation; cell masks still keep it inside the
// cells its portal visibility reaches). Returns how many lights got no slot.
uint32_t shadow_slots_for_frame(const std::vector<uint32_t>& frame_lights, const std::vector<uint32_t>& view_count,
                                uint32_t slots, std::vector<uint32_t>& first_slot);

// The same, but keeping layers where they were: when every frame light's views fit at once, a
// light keeps `held[light]` (its first slot in an earlier frame, kNoShadowSlot if none) while that
// range is free, and the others take the first free range that fits, in priority order; so a
// static light's cached layers stay valid from frame to frame. When not all fit, or the free
// ranges are too fragmented, it is shadow_slots_for_frame. `held` is updated (per light; a light
// not in the frame keeps its entry). Returns how many lights got no slot. `used` is scratch.
uint32_t shadow_slots_stable(const std::vector<uint32_t>& frame_lights, const std::vector<uint32_t>& view_count,
                             uint32_t slots, std::vector<uint32_t>& held, std::vector<uint8_t>& used,
                             std::vector<uint32_t>& first_slot);

}  // namespace lintel::render
