// Choosing the physical device: a pure function over what each device offers, so the rules
// (selector, type preference, refusing a device that lacks a required feature) are unit-tested
// without needing such a device.
#pragma once

#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::gpu {

struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  // Requirements it fails, each a one-line reason naming the feature, e.g.
  // "lacks drawIndirectFirstInstance: ...". Empty: usable.
  std::vector<std::string> missing;
};

// Picks a device. `selector` empty: the usable device of the most preferred type (discrete,
// integrated, virtual, other, CPU; first in order on ties). Otherwise an index ("0") or a
// case-insensitive name substring, and that device must be usable: no fallback to another one.
// Errors name the device and what it lacks, or list the devices when the selector matches none.
Status choose_device(const std::vector<DeviceCandidate>& candidates, const std::string& selector, uint32_t& chosen);

}  // namespace lintel::gpu
