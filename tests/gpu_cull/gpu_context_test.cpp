// The headless context: device choice by LINTEL_VK_DEVICE-style selectors, refusal of devices
// without the features GPU-driven draws need (by name), and a clean validation run.
#include <lintel/gpu/context.h>

#include "context_testing.h"
#include "device_select.h"
#include "gpu_test_support.h"

#include <gtest/gtest.h>

namespace lintel::gpu {
namespace {

std::vector<DeviceCandidate> three_devices() {
  return {{"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, {}},
          {"NVIDIA H100 PCIe", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, {}},
          {"Intel(R) UHD Graphics", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, {}}};
}

TEST(DeviceSelect, PrefersDiscreteThenIntegratedThenCpu) {
  std::vector<DeviceCandidate> devices = three_devices();
  uint32_t chosen = 99;
  ASSERT_TRUE(choose_device(devices, "", chosen).ok());
  EXPECT_EQ(chosen, 1u);
  devices[1].missing.push_back("lacks drawIndirectFirstInstance: ...");
  ASSERT_TRUE(choose_device(devices, "", chosen).ok());
  EXPECT_EQ(chosen, 2u);
  devices[2].missing.push_back("lacks multiDrawIndirect: ...");
  ASSERT_TRUE(choose_device(devices, "", chosen).ok());
  EXPECT_EQ(chosen, 0u);
}

TEST(DeviceSelect, SelectorByIndexOrNameSubstring) {
  std::vector<DeviceCandidate> devices = three_devices();
  uint32_t chosen = 99;
  ASSERT_TRUE(choose_device(devices, "0", chosen).ok());
  EXPECT_EQ(chosen, 0u);
  ASSERT_TRUE(choose_device(devices, "intel", chosen).ok());
  EXPECT_EQ(chosen, 2u);
  ASSERT_TRUE(choose_device(devices, "LLVMPIPE", chosen).ok());
  EXPECT_EQ(chosen, 0u);
  Status s = choose_device(devices, "7", chosen);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("out of range"), std::string::npos) << s.message();
  s = choose_device(devices, "radeon", chosen);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("NVIDIA H100"), std::string::npos) << "lists the devices: " << s.message();
}

TEST(DeviceSelect, SelectedDeviceWithoutFeatureIsRefusedNotReplaced) {
  std::vector<DeviceCandidate> devices = three_devices();
  devices[1].missing.push_back(
      "lacks drawIndirectFirstInstance: every draw group but the one at instance 0 would be silently dropped");
  uint32_t chosen = 99;
  Status s = choose_device(devices, "h100", chosen);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(chosen, 99u);
  EXPECT_NE(s.message().find("'NVIDIA H100 PCIe' lacks drawIndirectFirstInstance"), std::string::npos) << s.message();
}

TEST(DeviceSelect, NoUsableDeviceNamesTheFeature) {
  std::vector<DeviceCandidate> devices = {{"llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU, {"lacks multiDrawIndirect: x"}}};
  uint32_t chosen = 99;
  Status s = choose_device(devices, "", chosen);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("multiDrawIndirect"), std::string::npos) << s.message();
  EXPECT_FALSE(choose_device({}, "", chosen).ok());
}

TEST(Context, CreatesHeadlessWithValidationAndRequiredFeatures) {
  std::unique_ptr<Context> ctx = test::make_validated_context();
  ASSERT_NE(ctx, nullptr);
  EXPECT_TRUE(ctx->validation());
  EXPECT_FALSE(ctx->info().name.empty());
  EXPECT_GE(ctx->info().api_version, VK_API_VERSION_1_3);
  test::expect_clean(*ctx);
}

// The lesson: without drawIndirectFirstInstance every group with a non-zero base draws nothing.
// A device lacking it (simulated: the feature is treated as absent and not enabled) is refused
// with the feature named -- not given a fallback that drops draws.
TEST(Context, DeviceWithoutDrawIndirectFirstInstanceIsRefused) {
  ContextOptions options;
  options.validation = true;
  std::unique_ptr<Context> ctx;
  Status s = ContextTesting::create_pretending_missing(options, {"drawIndirectFirstInstance"}, ctx);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(ctx, nullptr);
  EXPECT_NE(s.message().find("lacks drawIndirectFirstInstance"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("silently dropped"), std::string::npos) << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << "one line";
}

TEST(Context, DeviceWithoutMultiDrawIndirectIsRefused) {
  ContextOptions options;
  std::unique_ptr<Context> ctx;
  Status s = ContextTesting::create_pretending_missing(options, {"multiDrawIndirect"}, ctx);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("lacks multiDrawIndirect"), std::string::npos) << s.message();
}

TEST(Context, MissingDrawIndirectCountIsOptional) {
  ContextOptions options;
  std::unique_ptr<Context> ctx;
  Status s = ContextTesting::create_pretending_missing(options, {"drawIndirectCount"}, ctx);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_FALSE(ctx->info().draw_indirect_count);
}

TEST(Context, UnknownDeviceSelectorIsAnError) {
  ContextOptions options;
  options.device = "no-such-gpu-xyz";
  std::unique_ptr<Context> ctx;
  Status s = Context::create(options, ctx);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("no-such-gpu-xyz"), std::string::npos) << s.message();
}

TEST(Context, ListsDevices) {
  std::vector<std::string> names;
  ASSERT_TRUE(list_devices(names).ok());
  EXPECT_FALSE(names.empty());
}

}  // namespace
}  // namespace lintel::gpu
