// Physical device evaluation and logical device creation. Required: Vulkan 1.3, a graphics+compute
// queue, multiDrawIndirect and drawIndirectFirstInstance. Used where present: drawIndirectCount,
// shaderDrawParameters, subgroup ballot in compute, timestamps, and the store/atomic features
// GPU-assisted validation instruments shaders with.
#include <lintel/gpu/context.h>

#include "device_select.h"
#include <lintel/gpu/vk_status.h>

#include <algorithm>
#include <cstdlib>

namespace lintel::gpu {
namespace {

struct DeviceFacts {
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  VkPhysicalDeviceVulkan11Properties props11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features features11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  uint32_t queue_family = UINT32_MAX;
  bool queue_timestamps = false;
};

void query(VkPhysicalDevice device, DeviceFacts& f) {
  f.props.pNext = &f.props11;
  vkGetPhysicalDeviceProperties2(device, &f.props);
  f.features.pNext = &f.features11;
  f.features11.pNext = &f.features12;
  vkGetPhysicalDeviceFeatures2(device, &f.features);
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & need) == need) {
      f.queue_family = i;
      f.queue_timestamps = families[i].timestampValidBits > 0;
      break;
    }
  }
}

bool pretended_missing(const ContextOptions& options, const char* feature) {
  return std::find(options.pretend_missing.begin(), options.pretend_missing.end(), feature) !=
         options.pretend_missing.end();
}

bool has(const ContextOptions& options, VkBool32 supported, const char* feature) {
  return supported && !pretended_missing(options, feature);
}

DeviceCandidate evaluate(const DeviceFacts& f, const ContextOptions& options) {
  DeviceCandidate c;
  c.name = f.props.properties.deviceName;
  c.type = f.props.properties.deviceType;
  const uint32_t api = f.props.properties.apiVersion;
  if (api < VK_API_VERSION_1_3)
    c.missing.push_back("supports Vulkan " + std::to_string(VK_API_VERSION_MAJOR(api)) + "." +
                        std::to_string(VK_API_VERSION_MINOR(api)) + "; Lintel's GPU cull needs Vulkan 1.3");
  if (f.queue_family == UINT32_MAX) c.missing.push_back("has no queue family with both graphics and compute");
  if (!has(options, f.features.features.multiDrawIndirect, "multiDrawIndirect"))
    c.missing.push_back("lacks multiDrawIndirect: one indirect call could not draw every draw group");
  if (!has(options, f.features.features.drawIndirectFirstInstance, "drawIndirectFirstInstance"))
    c.missing.push_back("lacks drawIndirectFirstInstance: every draw group but the one at instance 0 "
                        "would be silently dropped");
  return c;
}

}  // namespace

Status Context::create_device(const ContextOptions& options) {
  uint32_t count = 0;
  if (Status s = vk_check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices", "devices"); !s)
    return s;
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  std::vector<DeviceFacts> facts(count);
  std::vector<DeviceCandidate> candidates;
  for (uint32_t i = 0; i < count; ++i) {
    query(devices[i], facts[i]);
    candidates.push_back(evaluate(facts[i], options));
  }
  std::string selector = options.device;
  if (selector.empty()) {
    if (const char* env = std::getenv("LINTEL_VK_DEVICE")) selector = env;
  }
  uint32_t chosen = 0;
  if (Status s = choose_device(candidates, selector, chosen); !s) return s;
  const DeviceFacts& f = facts[chosen];
  physical_device_ = devices[chosen];
  queue_family_ = f.queue_family;
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_);

  info_.name = candidates[chosen].name;
  info_.index = chosen;
  info_.type = f.props.properties.deviceType;
  info_.api_version = f.props.properties.apiVersion;
  info_.draw_indirect_count = has(options, f.features12.drawIndirectCount, "drawIndirectCount");
  const VkSubgroupFeatureFlags ballot = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
  info_.subgroup_ballot = (f.props11.subgroupSupportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                          (f.props11.subgroupSupportedOperations & ballot) == ballot &&
                          !pretended_missing(options, "subgroupBallot");
  info_.subgroup_size = f.props11.subgroupSize;
  info_.timestamps = f.queue_timestamps && f.props.properties.limits.timestampPeriod > 0.0f;
  info_.timestamp_period_ns = f.props.properties.limits.timestampPeriod;
  info_.max_storage_buffer_range = f.props.properties.limits.maxStorageBufferRange;
  info_.min_storage_buffer_offset_alignment = f.props.properties.limits.minStorageBufferOffsetAlignment;

  // Enable exactly what is used; the optional features only where present.
  VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  enable13.synchronization2 = VK_TRUE;  // mandatory in 1.3; the pass records vkCmdPipelineBarrier2
  enable13.maintenance4 = VK_TRUE;      // mandatory in 1.3; SPIR-V 1.6 sizes workgroups by LocalSizeId
  enable13.dynamicRendering = VK_TRUE;  // mandatory in 1.3; draws need no VkRenderPass objects
  VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  enable12.drawIndirectCount = info_.draw_indirect_count;
  enable12.pNext = &enable13;
  VkPhysicalDeviceVulkan11Features enable11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  enable11.shaderDrawParameters = f.features11.shaderDrawParameters;
  enable11.pNext = &enable12;
  VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  enable.features.multiDrawIndirect = VK_TRUE;
  enable.features.drawIndirectFirstInstance = VK_TRUE;
  // GPU-assisted validation writes its findings from every stage; enabling these where present
  // keeps it from warning that it cannot instrument the vertex and fragment shaders.
  enable.features.vertexPipelineStoresAndAtomics = f.features.features.vertexPipelineStoresAndAtomics;
  enable.features.fragmentStoresAndAtomics = f.features.features.fragmentStoresAndAtomics;
  enable.pNext = &enable11;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &enable;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  if (Status s = vk_check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice", info_.name); !s)
    return s;
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  if (Status s = vk_check(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_), "vkCreateCommandPool", "one-shot submits"); !s)
    return s;
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  return vk_check(vkCreateFence(device_, &fence_info, nullptr, &fence_), "vkCreateFence", "one-shot submits");
}

}  // namespace lintel::gpu
