// Property: a renderer shader and its C++ set layout cannot disagree silently. Every committed
// shader passes the check against the table it is created with; a shader whose binding was
// renumbered (edited here in the SPIR-V, as a GLSL edit would), moved out of the layout, or
// checked for a stage the layout does not serve fails pipeline creation with Status::internal
// naming the binding. No GPU: the check runs before any Vulkan call.
#include "binding_tables.h"
#include "passes/pass_common.h"
#include "render_bindings.h"
#include "spirv_bindings.h"

#include "lintel_render_spirv.h"

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

namespace lintel::render {
namespace {

// The SPIR-V with the Binding decoration `from` changed to `to` (asserts it was there).
std::vector<uint32_t> renumbered(std::span<const uint32_t> spirv, uint32_t from, uint32_t to) {
  std::vector<uint32_t> out(spirv.begin(), spirv.end());
  bool found = false;
  for (size_t i = 5; i < out.size();) {
    const uint32_t words = out[i] >> 16, op = out[i] & 0xffffu;
    if (op == 71 /* OpDecorate */ && words >= 4 && out[i + 2] == 33 /* Binding */ && out[i + 3] == from) {
      out[i + 3] = to;
      found = true;
    }
    i += words;
  }
  EXPECT_TRUE(found) << "no binding " << from << " in the module";
  return out;
}

TEST(BindingCheck, EveryShaderMatchesItsTable) {
  const struct {
    std::span<const uint32_t> spirv;
    VkShaderStageFlagBits stage;
    std::span<const BindingDesc> table;
    const char* name;
  } shaders[] = {
      {gpu::spirv::gbuffer_vert(), VK_SHADER_STAGE_VERTEX_BIT, draw_set_bindings(), "gbuffer.vert"},
      {gpu::spirv::gbuffer_frag(), VK_SHADER_STAGE_FRAGMENT_BIT, draw_set_bindings(), "gbuffer.frag"},
      {gpu::spirv::gtao_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "gtao.comp"},
      {gpu::spirv::ao_upsample_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "ao_upsample.comp"},
      {gpu::spirv::surfel_light_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "surfel_light.comp"},
      {gpu::spirv::probe_gather_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "probe_gather.comp"},
      {gpu::spirv::lighting_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "lighting.comp"},
      {gpu::spirv::exposure_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "exposure.comp"},
      {gpu::spirv::tonemap_comp(), VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), "tonemap.comp"},
      {gpu::spirv::hiz_early_comp(), VK_SHADER_STAGE_COMPUTE_BIT, hiz_set_bindings(), "hiz_early.comp"},
      {gpu::spirv::hiz_commands_comp(), VK_SHADER_STAGE_COMPUTE_BIT, hiz_set_bindings(), "hiz_commands.comp"},
      {gpu::spirv::hiz_pyramid_comp(), VK_SHADER_STAGE_COMPUTE_BIT, hiz_set_bindings(), "hiz_pyramid.comp"},
      {gpu::spirv::hiz_late_comp(), VK_SHADER_STAGE_COMPUTE_BIT, hiz_set_bindings(), "hiz_late.comp"},
  };
  for (const auto& s : shaders) {
    const Status st = check_shader_bindings(s.spirv, s.stage, s.table, s.name);
    EXPECT_TRUE(st.ok()) << st.message();
  }
}

// The reader sees what the GLSL declares: the compute shaders include every compute binding.
TEST(BindingCheck, ReflectionFindsTheDeclaredKinds) {
  std::vector<ShaderBinding> found;
  ASSERT_TRUE(reflect_bindings(gpu::spirv::lighting_comp(), found).ok());
  auto type_of = [&](uint32_t binding) {
    for (const ShaderBinding& b : found)
      if (b.binding == binding) return b.type;
    return VK_DESCRIPTOR_TYPE_MAX_ENUM;
  };
  EXPECT_EQ(type_of(kBindLights), VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
  EXPECT_EQ(type_of(kBindProbes), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(type_of(kBindShadowAtlas), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_EQ(type_of(kBindHdr), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  EXPECT_EQ(type_of(kBindDepth), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
}

TEST(BindingCheck, RenumberedBindingFailsPipelineCreationNamingIt) {
  // The shadow atlas (a sampler) moved onto kBindLights (a storage buffer in the layout).
  const std::vector<uint32_t> bad = renumbered(gpu::spirv::gtao_comp(), kBindShadowAtlas, kBindLights);
  ComputeBinding binding;  // no device needed: the check comes first
  Pipeline pipeline;
  const Status s = create_compute_pass_pipeline(VK_NULL_HANDLE, binding, bad, "gtao.comp", pipeline);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::Internal);
  EXPECT_NE(s.message().find("kBindLights"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("gtao.comp"), std::string::npos) << s.message();
  EXPECT_EQ(pipeline.handle(), VkPipeline(VK_NULL_HANDLE));
}

TEST(BindingCheck, BindingMissingFromTheLayoutIsReported) {
  const std::vector<uint32_t> bad = renumbered(gpu::spirv::gbuffer_frag(), kDrawBindTextures, 40);
  const Status s = check_shader_bindings(bad, VK_SHADER_STAGE_FRAGMENT_BIT, draw_set_bindings(), "gbuffer.frag");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::Internal);
  EXPECT_NE(s.message().find("binding 40"), std::string::npos) << s.message();
}

TEST(BindingCheck, StageTheLayoutDoesNotServeIsReported) {
  // The vertex shader's ids and records bindings are vertex-only; checked as a fragment shader it
  // must fail, naming one of them.
  const Status s = check_shader_bindings(gpu::spirv::gbuffer_vert(), VK_SHADER_STAGE_FRAGMENT_BIT, draw_set_bindings(),
                                         "gbuffer.vert");
  ASSERT_FALSE(s.ok());
  EXPECT_TRUE(s.message().find("kDrawBindIds") != std::string::npos ||
              s.message().find("kDrawBindInstances") != std::string::npos)
      << s.message();
}

TEST(BindingCheck, NotSpirvIsAnInternalError) {
  const std::vector<uint32_t> junk = {1, 2, 3, 4, 5, 6};
  std::vector<ShaderBinding> out;
  const Status s = reflect_bindings(junk, out);
  EXPECT_EQ(s.kind(), StatusKind::Internal);
}

}  // namespace
}  // namespace lintel::render
