// Device choice: a selector (index or name substring, from ContextOptions::device) wins; otherwise prefer real GPUs over
// lavapipe. A device that lacks a required feature is refused with the feature named, never used
// on a degraded path (LESSONS.md: firstInstance silently dropped).
#include "device_select.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace lintel::gpu {
namespace {

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_OTHER:
      return 3;
    default:
      return 4;  // CPU
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string device_list(const std::vector<DeviceCandidate>& candidates) {
  std::string out;
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (i) out += ", ";
    out += std::to_string(i) + ": '" + candidates[i].name + "'";
  }
  return out.empty() ? "none" : out;
}

Status refuse(const DeviceCandidate& c) {
  std::string message = "Vulkan device '" + c.name + "' " + c.missing.front();
  for (size_t i = 1; i < c.missing.size(); ++i) message += "; it also " + c.missing[i];
  return Status::unsupported(message);
}

}  // namespace

Status choose_device(const std::vector<DeviceCandidate>& candidates, const std::string& selector, uint32_t& chosen) {
  if (candidates.empty())
    return Status::unsupported("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
  if (!selector.empty()) {
    uint32_t index = 0;
    const char* end = selector.data() + selector.size();
    auto [ptr, ec] = std::from_chars(selector.data(), end, index);
    bool by_index = ec == std::errc() && ptr == end;
    if (by_index && index >= candidates.size())
      return Status::error("Vulkan device index " + selector + " out of range; devices: " + device_list(candidates));
    if (!by_index) {
      index = UINT32_MAX;
      for (uint32_t i = 0; i < candidates.size() && index == UINT32_MAX; ++i)
        if (lower(candidates[i].name).find(lower(selector)) != std::string::npos) index = i;
      if (index == UINT32_MAX)
        return Status::error("no Vulkan device matches '" + selector + "'; devices: " + device_list(candidates));
    }
    if (!candidates[index].missing.empty()) return refuse(candidates[index]);
    chosen = index;
    return {};
  }
  uint32_t best = UINT32_MAX;
  for (uint32_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].missing.empty()) continue;
    if (best == UINT32_MAX || type_rank(candidates[i].type) < type_rank(candidates[best].type)) best = i;
  }
  if (best != UINT32_MAX) {
    chosen = best;
    return {};
  }
  // None usable: name what the most preferred device lacks.
  uint32_t first = 0;
  for (uint32_t i = 1; i < candidates.size(); ++i)
    if (type_rank(candidates[i].type) < type_rank(candidates[first].type)) first = i;
  return refuse(candidates[first]);
}

}  // namespace lintel::gpu
