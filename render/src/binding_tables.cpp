// The set layouts' tables. Each entry names its constant, so a mismatch found at pipeline creation
// says which binding it is in the words of render_bindings.h.
#include "binding_tables.h"

#include "render_bindings.h"

#include <array>

namespace lintel::render {
namespace {

constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kTexels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT;
constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

struct Named {
  BindingDesc desc;
  const char* name;
};

#define LINTEL_BINDING(constant, type, stages) \
  Named { {constant, type, stages}, #constant }

constexpr std::array<Named, kDrawBindingCount> kDraw = {
    LINTEL_BINDING(kDrawBindIds, kBuffer, kVertex),        LINTEL_BINDING(kDrawBindInstances, kTexels, kVertex),
    LINTEL_BINDING(kDrawBindCounts, kBuffer, kFragment),   LINTEL_BINDING(kDrawBindTextures, kSampled, kFragment),
    LINTEL_BINDING(kDrawBindLinkClip, kTexels, kFragment),
};

constexpr std::array<Named, kComputeBindingCount> kComputeSet = {
    LINTEL_BINDING(kBindLights, kTexels, kCompute),
    LINTEL_BINDING(kBindActiveLights, kTexels, kCompute),
    LINTEL_BINDING(kBindShadowViews, kTexels, kCompute),
    LINTEL_BINDING(kBindLightMasks, kBuffer, kCompute),
    LINTEL_BINDING(kBindShadowAtlas, kSampled, kCompute),
    LINTEL_BINDING(kBindCellProbes, kTexels, kCompute),
    LINTEL_BINDING(kBindProbes, kBuffer, kCompute),
    LINTEL_BINDING(kBindSurfels, kTexels, kCompute),
    LINTEL_BINDING(kBindSurfelRadiance, kBuffer, kCompute),
    LINTEL_BINDING(kBindActiveCells, kBuffer, kCompute),
    LINTEL_BINDING(kBindAlbedo, kImage, kCompute),
    LINTEL_BINDING(kBindNormal, kImage, kCompute),
    LINTEL_BINDING(kBindCell, kImage, kCompute),
    LINTEL_BINDING(kBindDepth, kSampled, kCompute),
    LINTEL_BINDING(kBindAo, kImage, kCompute),
    LINTEL_BINDING(kBindHdr, kImage, kCompute),
    LINTEL_BINDING(kBindLdr, kImage, kCompute),
    LINTEL_BINDING(kBindExposure, kBuffer, kCompute),
    LINTEL_BINDING(kBindAoHalf, kImage, kCompute),
    LINTEL_BINDING(kBindLinkViews, kTexels, kCompute),
    LINTEL_BINDING(kBindProbeTexels, kTexels, kCompute),
    LINTEL_BINDING(kBindSurfelRadianceTexels, kTexels, kCompute),
    LINTEL_BINDING(kBindProbeVisibility, kTexels, kCompute),
    LINTEL_BINDING(kBindEmission, kImage, kCompute),
};

constexpr std::array<Named, kHizBindingCount> kHizSet = {
    LINTEL_BINDING(kHizBindCullCommands, kBuffer, kCompute), LINTEL_BINDING(kHizBindCullIds, kBuffer, kCompute),
    LINTEL_BINDING(kHizBindCommands, kBuffer, kCompute),     LINTEL_BINDING(kHizBindIds, kBuffer, kCompute),
    LINTEL_BINDING(kHizBindCounters, kBuffer, kCompute),     LINTEL_BINDING(kHizBindVisibility, kBuffer, kCompute),
    LINTEL_BINDING(kHizBindPyramid, kBuffer, kCompute),      LINTEL_BINDING(kHizBindInstances, kBuffer, kCompute),
    LINTEL_BINDING(kHizBindSlotGroups, kBuffer, kCompute),   LINTEL_BINDING(kHizBindDepth, kSampled, kCompute),
};

#undef LINTEL_BINDING

// The tables list bindings in order, so an entry's index is its binding (checked at compile time).
template <size_t N>
constexpr bool dense(const std::array<Named, N>& table) {
  for (size_t i = 0; i < N; ++i)
    if (table[i].desc.binding != i) return false;
  return true;
}
static_assert(dense(kDraw) && dense(kComputeSet) && dense(kHizSet),
              "binding tables must list bindings 0..N-1 in order");

template <size_t N>
constexpr std::array<BindingDesc, N> descs(const std::array<Named, N>& table) {
  std::array<BindingDesc, N> out{};
  for (size_t i = 0; i < N; ++i) out[i] = table[i].desc;
  return out;
}

constexpr std::array<BindingDesc, kDraw.size()> kDrawDescs = descs(kDraw);
constexpr std::array<BindingDesc, kComputeSet.size()> kComputeDescs = descs(kComputeSet);
constexpr std::array<BindingDesc, kHizSet.size()> kHizDescs = descs(kHizSet);

}  // namespace

std::span<const BindingDesc> draw_set_bindings() { return kDrawDescs; }
std::span<const BindingDesc> compute_set_bindings() { return kComputeDescs; }
std::span<const BindingDesc> hiz_set_bindings() { return kHizDescs; }

const char* binding_name(std::span<const BindingDesc> table, uint32_t binding) {
  if (table.data() == kDrawDescs.data() && binding < kDraw.size()) return kDraw[binding].name;
  if (table.data() == kComputeDescs.data() && binding < kComputeSet.size()) return kComputeSet[binding].name;
  if (table.data() == kHizDescs.data() && binding < kHizSet.size()) return kHizSet[binding].name;
  return nullptr;
}

}  // namespace lintel::render
