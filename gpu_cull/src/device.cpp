// Physical device evaluation and logical device creation. Required: Vulkan 1.3, a graphics+compute
// queue, multiDrawIndirect and drawIndirectFirstInstance. Used where present: drawIndirectCount,
// shaderDrawParameters, subgroup ballot in compute, timestamps, and the store/atomic features
// GPU-assisted validation instruments shaders with.
#include <lintel/gpu/context.h>

#include "device_select.h"
#include "vk_status.h"

#include <algorithm>

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

bool pretended_missing(const std::vector<std::string>& pretend_missing, const char* feature) {
  return std::find(pretend_missing.begin(), pretend_missing.end(), feature) != pretend_missing.end();
}

bool has(const std::vector<std::string>& pretend_missing, VkBool32 supported, const char* feature) {
  return supported && !pretended_missing(pretend_missing, feature);
}

DeviceCandidate evaluate(const DeviceFacts& f, const std::vector<std::string>& pretend_missing) {
  DeviceCandidate c;
  c.name = f.props.properties.deviceName;
  c.type = f.props.properties.deviceType;
  const uint32_t api = f.props.properties.apiVersion;
  if (api < VK_API_VERSION_1_3)
    c.missing.push_back("supports Vulkan " + std::to_string(VK_API_VERSION_MAJOR(api)) + "." +
                        std::to_string(VK_API_VERSION_MINOR(api)) + "; Lintel's GPU cull needs Vulkan 1.3");
  if (f.queue_family == UINT32_MAX) c.missing.push_back("has no queue family with both graphics and compute");
  if (!has(pretend_missing, f.features.features.multiDrawIndirect, "multiDrawIndirect"))
    c.missing.push_back("lacks multiDrawIndirect: one indirect call could not draw every draw group");
  if (!has(pretend_missing, f.features.features.drawIndirectFirstInstance, "drawIndirectFirstInstance"))
    c.missing.push_back(
        "lacks drawIndirectFirstInstance: every draw group but the one at instance 0 "
        "would be silently dropped");
  return c;
}

// The flags Lintel enables, from what `f` supports (the optional ones only where present).
void fill_features(const DeviceFacts& f, DeviceFeatures& out) {
  out = DeviceFeatures{};
  out.core.features.multiDrawIndirect = VK_TRUE;
  out.core.features.drawIndirectFirstInstance = VK_TRUE;
  // GPU-assisted validation writes its findings from every stage; enabling these where present
  // keeps it from warning that it cannot instrument the vertex and fragment shaders.
  out.core.features.vertexPipelineStoresAndAtomics = f.features.features.vertexPipelineStoresAndAtomics;
  out.core.features.fragmentStoresAndAtomics = f.features.features.fragmentStoresAndAtomics;
  out.v11.shaderDrawParameters = f.features11.shaderDrawParameters;
  out.v12.drawIndirectCount = f.features12.drawIndirectCount;
  out.v13.synchronization2 = VK_TRUE;  // mandatory in 1.3; the passes record vkCmdPipelineBarrier2
  out.v13.maintenance4 = VK_TRUE;      // mandatory in 1.3; SPIR-V 1.6 sizes workgroups by LocalSizeId
  out.v13.dynamicRendering = VK_TRUE;  // mandatory in 1.3; draws need no VkRenderPass objects
}

std::string first_missing_required(const DeviceFeatures& enabled) {
  if (!enabled.core.features.multiDrawIndirect) return "multiDrawIndirect";
  if (!enabled.core.features.drawIndirectFirstInstance) return "drawIndirectFirstInstance";
  if (!enabled.v13.synchronization2) return "synchronization2";
  if (!enabled.v13.dynamicRendering) return "dynamicRendering";
  if (!enabled.v13.maintenance4) return "maintenance4";
  return {};
}

}  // namespace

VkPhysicalDeviceFeatures2* DeviceFeatures::link(void* next) {
  core.pNext = &v11;
  v11.pNext = &v12;
  v12.pNext = &v13;
  v13.pNext = next;
  return &core;
}

Status DeviceFeatures::for_device(VkPhysicalDevice device, DeviceFeatures& out) {
  DeviceFacts f;
  query(device, f);
  const DeviceCandidate c = evaluate(f, {});
  if (!c.missing.empty()) return Status::unsupported("Vulkan device '" + c.name + "' " + c.missing.front());
  fill_features(f, out);
  out.link();
  return {};
}

void Context::describe_device(uint32_t index, const DeviceFeatures& enabled, bool subgroup_ballot_allowed) {
  DeviceFacts f;
  query(physical_device_, f);
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_);
  info_.name = f.props.properties.deviceName;
  info_.index = index;
  info_.type = f.props.properties.deviceType;
  info_.api_version = f.props.properties.apiVersion;
  info_.draw_indirect_count = enabled.v12.drawIndirectCount == VK_TRUE;
  const VkSubgroupFeatureFlags ballot = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
  info_.subgroup_ballot = (f.props11.subgroupSupportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                          (f.props11.subgroupSupportedOperations & ballot) == ballot && subgroup_ballot_allowed;
  info_.subgroup_size = f.props11.subgroupSize;
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
  const bool queue_timestamps = queue_family_ < family_count && families[queue_family_].timestampValidBits > 0;
  info_.timestamps = queue_timestamps && f.props.properties.limits.timestampPeriod > 0.0f;
  info_.timestamp_period_ns = f.props.properties.limits.timestampPeriod;
  info_.max_storage_buffer_range = f.props.properties.limits.maxStorageBufferRange;
  info_.min_storage_buffer_offset_alignment = f.props.properties.limits.minStorageBufferOffsetAlignment;
}

Status Context::create_device(const ContextOptions& options, const std::vector<std::string>& pretend_missing) {
  uint32_t count = 0;
  if (Status s =
          vk_check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices", "devices");
      !s)
    return s;
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  std::vector<DeviceFacts> facts(count);
  std::vector<DeviceCandidate> candidates;
  for (uint32_t i = 0; i < count; ++i) {
    query(devices[i], facts[i]);
    candidates.push_back(evaluate(facts[i], pretend_missing));
  }
  uint32_t chosen = 0;
  if (Status s = choose_device(candidates, options.device, chosen); !s) return s;
  physical_device_ = devices[chosen];
  queue_family_ = facts[chosen].queue_family;

  // Enable exactly what is used; the optional features only where present.
  DeviceFeatures enable;
  fill_features(facts[chosen], enable);
  if (pretended_missing(pretend_missing, "drawIndirectCount")) enable.v12.drawIndirectCount = VK_FALSE;
  describe_device(chosen, enable, !pretended_missing(pretend_missing, "subgroupBallot"));

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = enable.link();
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  if (Status s = vk_check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice", info_.name); !s)
    return s;
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
  return create_submit_objects();
}

Status Context::create_submit_objects() {
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  if (Status s = vk_check(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_), "vkCreateCommandPool",
                          "one-shot submits");
      !s)
    return s;
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  return vk_check(vkCreateFence(device_, &fence_info, nullptr, &fence_), "vkCreateFence", "one-shot submits");
}

Status Context::wrap(const ExternalDevice& external, std::unique_ptr<Context>& out) {
  out.reset();
  if (!external.instance || !external.physical_device || !external.device || !external.queue)
    return Status::error("Context::wrap: instance, physical device, device and queue must all be given");
  std::unique_ptr<Context> ctx(new Context());
  ctx->borrowed_ = true;
  ctx->instance_ = external.instance;
  ctx->physical_device_ = external.physical_device;
  ctx->device_ = external.device;
  ctx->queue_ = external.queue;
  ctx->queue_family_ = external.queue_family;

  DeviceFacts f;
  query(external.physical_device, f);
  const std::string name = f.props.properties.deviceName;
  if (f.props.properties.apiVersion < VK_API_VERSION_1_3)
    return Status::unsupported("Vulkan device '" + name + "' supports less than Vulkan 1.3; Lintel needs 1.3");
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(external.physical_device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(external.physical_device, &family_count, families.data());
  const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (external.queue_family >= family_count || (families[external.queue_family].queueFlags & need) != need)
    return Status::error("Context::wrap: queue family " + std::to_string(external.queue_family) + " of '" + name +
                         "' lacks graphics and compute");
  if (std::string missing = first_missing_required(external.enabled); !missing.empty())
    return Status::unsupported("Context::wrap: the device '" + name + "' was created without " + missing +
                               ", which Lintel requires (enable DeviceFeatures::for_device's chain)");

  uint32_t count = 0;
  vkEnumeratePhysicalDevices(external.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(external.instance, &count, devices.data());
  const uint32_t index =
      uint32_t(std::find(devices.begin(), devices.end(), external.physical_device) - devices.begin());
  ctx->describe_device(index, external.enabled, true);
  ctx->set_allocator(external.allocator);
  if (Status s = ctx->create_submit_objects(); !s) return s;
  out = std::move(ctx);
  return {};
}

}  // namespace lintel::gpu
