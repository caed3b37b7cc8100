// Context::wrap: Lintel on a device the caller (a game) created and owns. The test plays the game:
// its own instance with the validation layers and its own messenger, its own device created with
// DeviceFeatures' chain. Lintel must run the cull on it cleanly, leave the device usable after
// its objects are gone, and refuse a device created without a feature it needs.
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_pass.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace lintel::gpu {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL collect(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                       VkDebugUtilsMessageTypeFlagsEXT types,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  const bool finding =
      types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT);
  if (finding || severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
    static_cast<std::vector<std::string>*>(user)->push_back(data->pMessage ? data->pMessage : "");
  return VK_FALSE;
}

// What a game sets up before it ever calls Lintel.
struct GameDevice {
  std::vector<std::string> messages;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = UINT32_MAX;
  DeviceFeatures enabled;

  // `drop` names a feature the game "forgets" to enable.
  void create(const char* drop = nullptr) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = &collect;
    messenger_info.pUserData = &messages;
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    features.pNext = &messenger_info;
    const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = &features;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
    ASSERT_EQ(vkCreateInstance(&info, nullptr, &instance), VK_SUCCESS);
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    ASSERT_NE(create_messenger, nullptr);
    ASSERT_EQ(create_messenger(instance, &messenger_info, nullptr, &messenger), VK_SUCCESS);

    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    const char* wanted = std::getenv("LINTEL_VK_DEVICE");  // a device name substring, as the CLI
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(d, &props);
      if (wanted && !std::strstr(props.deviceName, wanted)) continue;
      if (DeviceFeatures::for_device(d, enabled).ok()) {
        physical = d;
        break;
      }
    }
    ASSERT_NE(physical, VK_NULL_HANDLE) << "no device Lintel can use";
    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, families.data());
    for (uint32_t i = 0; i < family_count && family == UINT32_MAX; ++i)
      if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
          (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
        family = i;
    ASSERT_NE(family, UINT32_MAX);
    if (drop && std::strcmp(drop, "drawIndirectFirstInstance") == 0)
      enabled.core.features.drawIndirectFirstInstance = VK_FALSE;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.pNext = enabled.link();
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    ASSERT_EQ(vkCreateDevice(physical, &device_info, nullptr, &device), VK_SUCCESS);
    vkGetDeviceQueue(device, family, 0, &queue);
  }

  ExternalDevice external() const { return {instance, physical, device, family, queue, enabled}; }

  ~GameDevice() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

TEST(BorrowedDevice, CullRunsOnTheGamesDeviceAndLeavesItUsable) {
  GameDevice game;
  ASSERT_NO_FATAL_FAILURE(game.create());
  {
    std::unique_ptr<Context> ctx;
    Status s = Context::wrap(game.external(), ctx);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(ctx->borrowed());
    EXPECT_EQ(ctx->device(), game.device);
    EXPECT_EQ(ctx->queue(), game.queue);
    EXPECT_EQ(ctx->info().draw_indirect_count, game.enabled.v12.drawIndirectCount == VK_TRUE);

    // Three instances in two groups, one cell visible: the answer is known by hand.
    CullScene scene;
    scene.cell_count = 2;
    scene.groups.push_back({36, 0, 0, 0, 2});
    scene.groups.push_back({36, 0, 0, 2, 1});
    scene.id_capacity = 3;
    scene.instances.push_back({{-0.1f, -0.1f, 0.4f}, 0, {0.1f, 0.1f, 0.6f}, 0});
    scene.instances.push_back({{0.2f, 0.2f, 0.4f}, 1, {0.3f, 0.3f, 0.6f}, 0});
    scene.instances.push_back({{-0.3f, 0.2f, 0.4f}, 0, {-0.2f, 0.3f, 0.6f}, 1});
    CullFrame frame;
    frame.clear(2, glm::dmat4(1.0));
    frame.add_region(0, {-1, -1, 1, 1}, {});
    std::unique_ptr<CullPass> pass;
    ASSERT_TRUE(CullPass::create(*ctx, {}, pass).ok());
    ASSERT_TRUE(pass->set_scene(scene).ok());
    ASSERT_TRUE(pass->set_frame(frame).ok());
    CullReadback rb;
    ASSERT_TRUE(pass->run(&rb).ok());
    EXPECT_EQ(rb.stats.visible_instances, 2u);
    ASSERT_EQ(rb.commands.size(), 2u);
    EXPECT_EQ(rb.commands[0].instance_count, 1u);
    EXPECT_EQ(rb.commands[1].instance_count, 1u);
    EXPECT_EQ(rb.commands[1].first_instance, 2u);
  }
  // Lintel is gone; the game's device and queue are not.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 256;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  EXPECT_EQ(vkCreateBuffer(game.device, &info, nullptr, &buffer), VK_SUCCESS);
  vkDestroyBuffer(game.device, buffer, nullptr);
  EXPECT_EQ(vkQueueWaitIdle(game.queue), VK_SUCCESS);
  for (const std::string& m : game.messages) ADD_FAILURE() << "validation: " << m;
}

// The lesson of silently dropped draws, on a borrowed device: a game that did not enable
// drawIndirectFirstInstance is told so, naming the feature, instead of getting empty frames.
TEST(BorrowedDevice, DeviceWithoutARequiredFeatureIsRefused) {
  GameDevice game;
  ASSERT_NO_FATAL_FAILURE(game.create("drawIndirectFirstInstance"));
  std::unique_ptr<Context> ctx;
  Status s = Context::wrap(game.external(), ctx);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::Unsupported);
  EXPECT_EQ(ctx, nullptr);
  EXPECT_NE(s.message().find("drawIndirectFirstInstance"), std::string::npos) << s.message();
}

TEST(BorrowedDevice, MissingHandlesAreAnError) {
  std::unique_ptr<Context> ctx;
  Status s = Context::wrap(ExternalDevice{}, ctx);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("must all be given"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace lintel::gpu
