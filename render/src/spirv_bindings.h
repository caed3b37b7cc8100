// What a SPIR-V module declares in its descriptor sets (set, binding, descriptor type), read from
// the module's decorations, and the check that a pipeline's set layout agrees with it: the C++
// layout and the GLSL declarations share names (render_bindings.h), this catches the rest (a
// buffer declared as an image, a binding missing from the layout, a stage left out).
#pragma once

#include "vk_helpers.h"

#include <lintel/status.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::render {

struct ShaderBinding {
  uint32_t set = 0, binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;  // MAX_ENUM: a kind this reader does not know
};

// The module's descriptor variables. Errors (Internal): not a SPIR-V module, truncated instructions.
Status reflect_bindings(std::span<const uint32_t> spirv, std::vector<ShaderBinding>& out);

// Every binding of set 0 that `spirv` (a `stage` shader called `shader`) declares must be in
// `layout` with the same descriptor type and with `stage` among its stages; a set other than 0 is
// refused. Errors (Internal) name the shader and the binding (by its render_bindings.h name where
// the layout is one of binding_tables.h's), e.g. "gtao.comp declares binding 4 (kBindShadowAtlas)
// as a storage buffer; the set layout has a combined image sampler".
Status check_shader_bindings(std::span<const uint32_t> spirv, VkShaderStageFlagBits stage,
                             std::span<const BindingDesc> layout, const char* shader);

}  // namespace lintel::render
