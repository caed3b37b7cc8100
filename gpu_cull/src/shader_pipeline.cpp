// Compute pipeline creation: the module lives only as long as pipeline creation needs it.
#include "shader_pipeline.h"

#include "vk_status.h"

#include <vector>

namespace lintel::gpu {

Status create_shader_module(VkDevice device, std::span<const uint32_t> spirv, const char* label, VkShaderModule& out) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  return vk_check(vkCreateShaderModule(device, &info, nullptr, &out), "vkCreateShaderModule", label);
}

Status create_compute_pipeline(VkDevice device, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                               std::span<const SpecConstant> constants, const char* label, VkPipeline& out) {
  VkShaderModule module = VK_NULL_HANDLE;
  if (Status s = create_shader_module(device, spirv, label, module); !s) return s;
  std::vector<VkSpecializationMapEntry> entries;
  for (size_t i = 0; i < constants.size(); ++i)
    entries.push_back(
        {constants[i].id, uint32_t(i * sizeof(SpecConstant) + offsetof(SpecConstant, value)), sizeof(uint32_t)});
  VkSpecializationInfo spec{};
  spec.mapEntryCount = uint32_t(entries.size());
  spec.pMapEntries = entries.data();
  spec.dataSize = constants.size_bytes();
  spec.pData = constants.data();

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = constants.empty() ? nullptr : &spec;
  info.layout = layout;
  Status s = vk_check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &out),
                      "vkCreateComputePipelines", label);
  vkDestroyShaderModule(device, module, nullptr);
  return s;
}

}  // namespace lintel::gpu
