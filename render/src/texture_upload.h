// The base-colour texture array on the GPU: every layer with a full mip chain (generated at upload
// with linear blits where the device can blit and filter the format, else on the CPU, both
// averaging in linear light), and the sampler the g-buffer reads it with (trilinear; the glTF
// wrap and filter modes are applied per material in gbuffer.frag).
#pragma once

#include <lintel/gpu/context.h>
#include "base_color.h"
#include "gpu_image.h"
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>

namespace lintel::render {

// Levels of a full mip chain of a `size` x `size` image: floor(log2(size)) + 1.
uint32_t mip_level_count(uint32_t size);

// Uploads `layers` into `out` (R8G8B8A8_SRGB, 2D array view with every level) and leaves it in
// SHADER_READ_ONLY_OPTIMAL for fragment shaders. `force_cpu_mips` takes the CPU path even where
// blits are supported (tests). `used_blit` (optional) says which path ran.
Status upload_base_color_textures(gpu::Context& ctx, const TextureLayers& layers, bool force_cpu_mips, GpuImage& out,
                                  bool* used_blit = nullptr);

// The sampler of the base-colour array: linear min/mag, linear between mip levels, REPEAT.
Status create_base_color_sampler(VkDevice device, VkSampler& out);

}  // namespace lintel::render
