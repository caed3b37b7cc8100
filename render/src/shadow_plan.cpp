// Planning the shadow atlas against the device's limits, and giving its slots to a frame's
// lights. Nothing here creates Vulkan objects: the plan is checked before the atlas exists.
#include "shadow_plan.h"

#include <algorithm>
#include <cstring>

namespace lintel::render {
namespace {

constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;
constexpr uint64_t kBytesPerTexel = 4;
constexpr uint32_t kMinResolution = 16;

bool has_memory_budget(VkPhysicalDevice pd) {
  uint32_t n = 0;
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> ext(n);
  if (vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, ext.data()) != VK_SUCCESS) return false;
  for (const VkExtensionProperties& e : ext)
    if (std::strcmp(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME) == 0) return true;
  return false;
}

std::string mib(uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

}  // namespace

Status query_shadow_device_limits(const gpu::Context& ctx, ShadowDeviceLimits& out) {
  VkPhysicalDevice pd = ctx.physical_device();
  VkPhysicalDeviceMaintenance3Properties m3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &m3;
  vkGetPhysicalDeviceProperties2(pd, &props);
  VkImageFormatProperties fp{};
  const VkResult r = vkGetPhysicalDeviceImageFormatProperties(
      pd, kShadowFormat, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, 0, &fp);
  if (r != VK_SUCCESS)
    return Status::unsupported("Vulkan device '" + ctx.info().name +
                               "' cannot make a sampled D32_SFLOAT depth image (shadow maps)");
  out.max_layers = std::min(props.properties.limits.maxImageArrayLayers, fp.maxArrayLayers);
  out.max_extent = std::min({props.properties.limits.maxImageDimension2D, fp.maxExtent.width, fp.maxExtent.height});
  out.max_allocation_bytes = m3.maxMemoryAllocationSize;
  out.max_resource_bytes = fp.maxResourceSize;

  VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
  VkPhysicalDeviceMemoryProperties2 mem{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
  const bool with_budget = has_memory_budget(pd);
  if (with_budget) mem.pNext = &budget;
  vkGetPhysicalDeviceMemoryProperties2(pd, &mem);
  uint64_t heap = 0;
  for (uint32_t h = 0; h < mem.memoryProperties.memoryHeapCount; ++h) {
    if (!(mem.memoryProperties.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)) continue;
    const uint64_t size = with_budget ? budget.heapBudget[h] : mem.memoryProperties.memoryHeaps[h].size;
    heap = std::max<uint64_t>(heap, size);
  }
  out.heap_bytes = heap;
  return {};
}

Status plan_shadow_atlas(const ShadowDeviceLimits& limits, uint32_t requested_resolution, uint32_t views_wanted,
                         uint64_t budget_bytes, ShadowPlan& out) {
  out = ShadowPlan{};
  const uint32_t wanted = std::max(1u, views_wanted);
  // One image, one allocation: it must fit every byte cap at once.
  uint64_t cap = std::min({limits.max_allocation_bytes, budget_bytes, limits.heap_bytes / 4});
  if (limits.max_resource_bytes) cap = std::min(cap, limits.max_resource_bytes);
  const uint32_t need = std::min(wanted, kMinShadowSlots);
  auto layers_that_fit = [&](uint32_t res) {
    const uint64_t per_layer = uint64_t(res) * res * kBytesPerTexel;
    return uint32_t(std::min<uint64_t>(limits.max_layers, cap / per_layer));
  };
  uint32_t res = std::min(requested_resolution, limits.max_extent);
  while (res > kMinResolution && layers_that_fit(res) < need) res /= 2;
  res = std::max(res, kMinResolution);
  const uint32_t fit = layers_that_fit(res);
  if (fit == 0 || res > limits.max_extent)
    return Status::unsupported("shadow maps: not even one " + std::to_string(res) + "x" + std::to_string(res) +
                               " layer fits the device (" + mib(cap) + " for the atlas)");
  out.resolution = res;
  out.slots = std::min(wanted, fit);
  out.bytes = uint64_t(res) * res * kBytesPerTexel * out.slots;
  std::string why;
  if (res != requested_resolution)
    why = "shadow resolution " + std::to_string(requested_resolution) + " reduced to " + std::to_string(res);
  if (out.slots < wanted) {
    if (!why.empty()) why += "; ";
    why += std::to_string(out.slots) + " of " + std::to_string(wanted) +
           " shadow views fit at once (lights past that light unshadowed in a frame)";
  }
  if (!why.empty())
    out.note = why + ": atlas limited to " + mib(cap) + " and " + std::to_string(limits.max_layers) + " layers";
  return {};
}

uint32_t shadow_slots_for_frame(const std::vector<uint32_t>& frame_lights, const std::vector<uint32_t>& view_count,
                                uint32_t slots, std::vector<uint32_t>& first_slot) {
  first_slot.assign(frame_lights.size(), kNoShadowSlot);
  uint32_t next = 0, unshadowed = 0;
  for (size_t i = 0; i < frame_lights.size(); ++i) {
    const uint32_t n = view_count[frame_lights[i]];
    if (n <= slots - next) {
      first_slot[i] = next;
      next += n;
    } else {
      ++unshadowed;
    }
  }
  return unshadowed;
}

uint32_t shadow_slots_stable(const std::vector<uint32_t>& frame_lights, const std::vector<uint32_t>& view_count,
                             uint32_t slots, std::vector<uint32_t>& held, std::vector<uint8_t>& used,
                             std::vector<uint32_t>& first_slot) {
  uint64_t total = 0;
  for (uint32_t l : frame_lights) total += view_count[l];
  auto packed = [&] {
    const uint32_t unshadowed = shadow_slots_for_frame(frame_lights, view_count, slots, first_slot);
    for (size_t i = 0; i < frame_lights.size(); ++i) held[frame_lights[i]] = first_slot[i];
    return unshadowed;
  };
  if (total > slots) return packed();
  first_slot.assign(frame_lights.size(), kNoShadowSlot);
  used.assign(slots, 0);
  auto range_free = [&](uint32_t first, uint32_t n) {
    if (first > slots || n > slots - first) return false;
    for (uint32_t k = 0; k < n; ++k)
      if (used[first + k]) return false;
    return true;
  };
  auto take = [&](size_t i, uint32_t first) {
    first_slot[i] = first;
    for (uint32_t k = 0; k < view_count[frame_lights[i]]; ++k) used[first + k] = 1;
  };
  for (size_t i = 0; i < frame_lights.size(); ++i) {  // keep what was held, by priority
    const uint32_t h = held[frame_lights[i]];
    if (h != kNoShadowSlot && range_free(h, view_count[frame_lights[i]])) take(i, h);
  }
  for (size_t i = 0; i < frame_lights.size(); ++i) {  // the rest: first free range that fits
    if (first_slot[i] != kNoShadowSlot) continue;
    const uint32_t n = view_count[frame_lights[i]];
    uint32_t first = 0;
    while (first < slots && !range_free(first, n)) ++first;
    if (first >= slots && n > 0) return packed();  // fragmented: pack them all again
    take(i, first);
  }
  for (size_t i = 0; i < frame_lights.size(); ++i) held[frame_lights[i]] = first_slot[i];
  return 0;
}

}  // namespace lintel::render
