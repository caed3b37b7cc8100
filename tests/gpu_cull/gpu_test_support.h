// Shared by the gpu_cull tests: a Vulkan context with Khronos validation (synchronization
// validation + GPU-assisted validation) whose every message fails the test, and small builders
// for hand-made cull scenes.
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_pass.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace lintel::gpu::test {

// Creates a validated context (fails the test if none). Check messages with expect_clean().
inline std::unique_ptr<Context> make_validated_context(ContextOptions options = {}) {
  options.validation = true;
  // The library reads no environment; the tests honour LINTEL_VK_DEVICE like the CLI.
  if (const char* selector = std::getenv("LINTEL_VK_DEVICE"); selector && options.device.empty())
    options.device = selector;
  std::unique_ptr<Context> ctx;
  Status s = Context::create(options, ctx);
  EXPECT_TRUE(s.ok()) << s.message();
  return ctx;
}

// Fails the test on any validation message since the last call.
inline void expect_clean(Context& ctx) {
  std::vector<std::string> messages = ctx.take_validation_messages();
  for (const std::string& m : messages) ADD_FAILURE() << "validation: " << m;
}

// A fixture holding one validated context for the whole suite (context creation with GPU-AV
// costs ~0.1 s on lavapipe) and checking for validation messages after every test.
class ValidatedGpu : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { ctx_ = make_validated_context().release(); }
  static void TearDownTestSuite() {
    delete ctx_;
    ctx_ = nullptr;
  }
  void SetUp() override {
    ASSERT_NE(ctx_, nullptr);
    expect_clean(*ctx_);
  }
  void TearDown() override {
    if (ctx_) expect_clean(*ctx_);
  }
  static Context& ctx() { return *ctx_; }

 private:
  static inline Context* ctx_ = nullptr;
};

// A hand-made cull scene for an identity camera (clip = world, w = 1): a box's NDC rect is its
// x/y extent.
struct HandScene {
  CullScene scene;
  void add_group(uint32_t capacity) {
    scene.groups.push_back({36, 0, 0, scene.id_capacity, capacity});
    scene.id_capacity += capacity;
  }
  // A box around (x, y) of half size h at depth z (in [0, 1] to pass the frustum).
  void add(uint32_t cell, uint32_t group, float x, float y, float h = 0.01f, float z = 0.5f) {
    scene.instances.push_back({{x - h, y - h, z - 0.01f}, cell, {x + h, y + h, z + 0.01f}, group});
  }
};

// Per group, the ids a readback drew, sorted (the append order is unspecified).
inline std::vector<std::vector<uint32_t>> ids_by_group(const CullReadback& rb) {
  std::vector<std::vector<uint32_t>> out(rb.commands.size());
  for (uint32_t g = 0; g < rb.commands.size(); ++g) {
    std::span<const uint32_t> ids = rb.group_ids(g);
    out[g].assign(ids.begin(), ids.end());
    std::sort(out[g].begin(), out[g].end());
  }
  return out;
}

}  // namespace lintel::gpu::test
