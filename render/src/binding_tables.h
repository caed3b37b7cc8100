// The renderer's descriptor set layouts as (binding, type, stages) tables built from the named
// numbers of render_bindings.h: the set layouts are created from them and every shader is checked
// against them (spirv_bindings.h).
#pragma once

#include "vk_helpers.h"

#include <span>

namespace lintel::render {

// Set 0 of the g-buffer and shadow pipelines.
std::span<const BindingDesc> draw_set_bindings();
// Set 0 of every compute pass.
std::span<const BindingDesc> compute_set_bindings();
// Set 0 of the hiz pass's four pipelines.
std::span<const BindingDesc> hiz_set_bindings();
// "kBindShadowAtlas" for a compute binding, "kDrawBindIds" for a draw binding, "binding N" otherwise.
const char* binding_name(std::span<const BindingDesc> table, uint32_t binding);

}  // namespace lintel::render
