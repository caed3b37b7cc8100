// Shader modules and compute pipelines from embedded SPIR-V, with specialization constants
// (niagara's way to make variants of one shader instead of copies).
#pragma once

#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

namespace lintel::gpu {

struct SpecConstant {
  uint32_t id;
  uint32_t value;  // bools as 0/1
};

Status create_shader_module(VkDevice device, std::span<const uint32_t> spirv, const char* label, VkShaderModule& out);

Status create_compute_pipeline(VkDevice device, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                               std::span<const SpecConstant> constants, const char* label, VkPipeline& out);

}  // namespace lintel::gpu
