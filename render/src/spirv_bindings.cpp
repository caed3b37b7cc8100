// A minimal SPIR-V reader for descriptor declarations (the SPIR-V 1.6 specification, sections 2.3
// "Physical Layout" and 3.32 "Instructions"): OpDecorate DescriptorSet/Binding/Block/BufferBlock,
// OpVariable, and the types a variable points to. Enough for the check, nothing more.
#include "spirv_bindings.h"

#include "binding_tables.h"

#include <string>
#include <unordered_map>

namespace lintel::render {
namespace {

constexpr uint32_t kMagic = 0x07230203u;
// Opcodes and enumerants used here (SPIR-V specification, section 3).
constexpr uint32_t kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypeArray = 28,
                   kOpTypeRuntimeArray = 29, kOpTypeStruct = 30, kOpTypePointer = 32, kOpVariable = 59,
                   kOpDecorate = 71;
constexpr uint32_t kDecorationBlock = 2, kDecorationBufferBlock = 3, kDecorationBinding = 33,
                   kDecorationDescriptorSet = 34;
constexpr uint32_t kStorageUniformConstant = 0, kStorageUniform = 2, kStorageStorageBuffer = 12;

struct TypeInfo {
  uint32_t opcode = 0;
  uint32_t element = 0;  // arrays and pointers: the type they hold
  uint32_t sampled = 0;  // OpTypeImage: 1 = sampled, 2 = storage
  uint32_t dim = 0;      // OpTypeImage: 5 = buffer
};

const char* type_name(VkDescriptorType t) {
  switch (t) {
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
      return "a storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return "a uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return "a storage image";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
      return "a sampled image";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
      return "a combined image sampler";
    case VK_DESCRIPTOR_TYPE_SAMPLER:
      return "a sampler";
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
      return "a uniform texel buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
      return "a storage texel buffer";
    default:
      return "an unknown kind of descriptor";
  }
}

}  // namespace

Status reflect_bindings(std::span<const uint32_t> spirv, std::vector<ShaderBinding>& out) {
  out.clear();
  if (spirv.size() < 5 || spirv[0] != kMagic) return Status::internal("SPIR-V: not a module (bad magic number)");
  std::unordered_map<uint32_t, TypeInfo> types;
  std::unordered_map<uint32_t, uint32_t> set_of, binding_of;
  std::unordered_map<uint32_t, uint32_t> block_kind;  // struct id -> Block or BufferBlock
  struct Variable {
    uint32_t id, pointer_type, storage;
  };
  std::vector<Variable> variables;
  for (size_t i = 5; i < spirv.size();) {
    const uint32_t words = spirv[i] >> 16, op = spirv[i] & 0xffffu;
    if (words == 0 || i + words > spirv.size()) return Status::internal("SPIR-V: truncated instruction");
    const uint32_t* w = &spirv[i];
    switch (op) {
      case kOpDecorate:
        if (words >= 4 && w[2] == kDecorationDescriptorSet) set_of[w[1]] = w[3];
        if (words >= 4 && w[2] == kDecorationBinding) binding_of[w[1]] = w[3];
        if (words >= 3 && (w[2] == kDecorationBlock || w[2] == kDecorationBufferBlock)) block_kind[w[1]] = w[2];
        break;
      case kOpTypeImage:
        if (words >= 9) types[w[1]] = {op, 0, w[7], w[3]};
        break;
      case kOpTypeSampler:
      case kOpTypeStruct:
        types[w[1]] = {op, 0, 0, 0};
        break;
      case kOpTypeSampledImage:
      case kOpTypeArray:
      case kOpTypeRuntimeArray:
        if (words >= 3) types[w[1]] = {op, w[2], 0, 0};
        break;
      case kOpTypePointer:
        if (words >= 4) types[w[1]] = {op, w[3], 0, 0};  // result, storage class, pointee
        break;
      case kOpVariable:
        if (words >= 4) variables.push_back({w[2], w[1], w[3]});
        break;
      default:
        break;
    }
    i += words;
  }
  for (const Variable& v : variables) {
    if (v.storage != kStorageUniformConstant && v.storage != kStorageUniform && v.storage != kStorageStorageBuffer)
      continue;
    const auto binding = binding_of.find(v.id);
    if (binding == binding_of.end()) continue;  // not a descriptor (e.g. a push-constant block is not Uniform)
    ShaderBinding b;
    b.binding = binding->second;
    const auto set = set_of.find(v.id);
    b.set = set == set_of.end() ? 0 : set->second;
    // Pointer -> (array ->)* the resource type.
    uint32_t t = types[v.pointer_type].element;
    while (types[t].opcode == kOpTypeArray || types[t].opcode == kOpTypeRuntimeArray) t = types[t].element;
    const TypeInfo& ti = types[t];
    if (v.storage == kStorageStorageBuffer) {
      b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    } else if (v.storage == kStorageUniform) {
      b.type = block_kind[t] == kDecorationBufferBlock ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                                       : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    } else if (ti.opcode == kOpTypeSampledImage) {
      b.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    } else if (ti.opcode == kOpTypeSampler) {
      b.type = VK_DESCRIPTOR_TYPE_SAMPLER;
    } else if (ti.opcode == kOpTypeImage) {
      const bool texel_buffer = ti.dim == 5;
      if (ti.sampled == 2)
        b.type = texel_buffer ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      else
        b.type = texel_buffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    }
    out.push_back(b);
  }
  return {};
}

Status check_shader_bindings(std::span<const uint32_t> spirv, VkShaderStageFlagBits stage,
                             std::span<const BindingDesc> layout, const char* shader) {
  std::vector<ShaderBinding> declared;
  if (Status s = reflect_bindings(spirv, declared); !s)
    return Status::internal(std::string(shader) + ": " + s.message());
  for (const ShaderBinding& d : declared) {
    std::string which = "binding " + std::to_string(d.binding);
    if (const char* name = binding_name(layout, d.binding)) which += std::string(" (") + name + ")";
    if (d.set != 0)
      return Status::internal(std::string(shader) + " declares " + which + " in set " + std::to_string(d.set) +
                              "; the renderer binds set 0 only");
    const BindingDesc* match = nullptr;
    for (const BindingDesc& l : layout)
      if (l.binding == d.binding) match = &l;
    if (!match)
      return Status::internal(std::string(shader) + " declares " + which + "; the set layout has no such binding");
    if (match->type != d.type)
      return Status::internal(std::string(shader) + " declares " + which + " as " + type_name(d.type) +
                              "; the set layout has " + type_name(match->type));
    if (!(match->stages & stage))
      return Status::internal(std::string(shader) + " uses " + which +
                              ", which the set layout does not make visible to its stage");
  }
  return {};
}

}  // namespace lintel::render
