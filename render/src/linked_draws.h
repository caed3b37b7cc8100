// What a frame draws through linked portals (mirrors, teleports): each linked view of the
// VisibleSet (a transform >= 1) draws the drawables of its linked cells -- their shells, their own
// instances and the instances the CPU cull found reaching them (VisibleSet::linked_instances) --
// with the view's transform applied, kept inside its portal's pyramid (the eye's view through the
// portal polygon, beyond its plane) and the rect of its regions, while the view it is seen from
// drops what lies in that pyramid (the wall the mirror hangs on). The plain view stays on the GPU
// cull; linked views are few (at most kMaxViewTransforms - 1 views and kMaxLinkedNodes cells a
// frame), so their draw lists are built here on the CPU and drawn with one indirect multi-draw per
// view from host-written buffers.
// Lighting: the records carry the view in their cell bits (kCellLinkShift) and link_views() maps a
// pixel back to where its surface really is (docs/rendering.md, "Mirrors and teleports").
#pragma once

#include "texel_view.h"
#include "passes/pass_common.h"
#include "render_scene.h"

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/render/render_shared.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace lintel::render {

// One linked view's draws in its slot's command buffer.
struct LinkedViewDraw {
  GBufferPush push;  // the camera, the view's pixel rect, link = (view, 1)
  uint32_t first_command = 0, command_count = 0;
};

// A slot's linked draws as the g-buffer pass records them.
struct LinkedFrame {
  VkDescriptorSet set = VK_NULL_HANDLE;  // a draw set: ids and records of the slot
  VkBuffer commands = VK_NULL_HANDLE;
  std::span<const LinkedViewDraw> views;
};

class LinkedDraws {
 public:
  // `sets`: one draw set per frame slot (written here, and again when a slot's buffers grow).
  Status create(gpu::Context& ctx, const DrawShared& shared, std::vector<VkDescriptorSet> sets);
  // Builds slot `slot`'s linked draws from `visible` (whose cells index scene.drawables) for a
  // `width` x `height` frame of `view`, and its link views (identity first). Precondition: the
  // slot's previous frame finished. Errors: a linked entry out of range, linked entries not in
  // ascending transform order (VisibleSet's contract) or naming a transform the set lacks; buffer
  // creation.
  Status prepare(const RenderScene& scene, const VisibleSet& visible, const View& view, uint32_t width, uint32_t height,
                 uint32_t slot);
  LinkedFrame frame(uint32_t slot) const;
  const gpu::Buffer& link_views(uint32_t slot) const { return slots_[slot].link_views; }
  VkBufferView link_clip(uint32_t slot) const { return slots_[slot].link_clip_texels.handle(); }
  // Records drawn through linked views in `slot`'s last prepare().
  uint32_t record_count(uint32_t slot) const { return slots_[slot].record_count; }

 private:
  struct Slot {
    gpu::Buffer records, ids, commands, link_views, link_clip;
    TexelView link_clip_texels, record_texels;  // link_clip as the g-buffer's fragment shader reads it
    uint32_t record_capacity = 0, command_capacity = 0, record_count = 0;
    std::vector<LinkedViewDraw> views;
  };
  Status grow(Slot& slot, uint32_t records, uint32_t commands, uint32_t index);

  gpu::Context* ctx_ = nullptr;
  DrawShared shared_;
  std::vector<VkDescriptorSet> sets_;
  std::vector<Slot> slots_;
  // prepare()'s scratch (kept, so a steady walk does not allocate).
  std::vector<uint32_t> members_, ids_;
  std::vector<glm::dvec3> polygon_;
  std::vector<GpuLinkClip> clip_views_;
  std::vector<glm::vec4> keep_planes_, cut_planes_, planes_;  // per view runs; the uploaded array
  std::vector<uint32_t> keep_first_, cut_first_;              // per view: run starts (or ~0u)
  std::vector<uint8_t> view_drawn_;
  std::vector<gpu::DrawIndexedCommand> commands_;
  std::vector<GpuDrawInstance> records_;
};

// The draw record of `plain` seen through a view that maps world space by `seen_from_world`: its
// transform and normals mapped, its faces flipped when the view mirrors, the view in its cell bits.
GpuDrawInstance linked_record(const GpuDrawInstance& plain, const glm::dmat4& seen_from_world, uint32_t transform);

// The pyramid of a linked portal whose polygon the eye at `eye` sees at `polygon_seen` (drawn
// space), as GpuLinkClip runs: `keep` widened and `cut` narrowed by `margin` metres (header, the
// portal's plane, one plane per edge). False, nothing written, when the eye is within `margin` of
// the portal's plane (the portal is seen edge-on) or the polygon is degenerate.
bool linked_pyramid(std::span<const glm::dvec3> polygon_seen, const glm::dvec3& eye, std::vector<glm::vec4>& keep,
                    std::vector<glm::vec4>& cut);
// Plane count of a run's header.
inline uint32_t pyramid_planes(const glm::vec4& header) {
  uint32_t n;
  std::memcpy(&n, &header.x, 4);
  return n;
}

// An NDC rect (min x, min y, max x, max y) in framebuffer pixels of a `width` x `height` target
// with Lintel's flipped viewport, widened by a pixel on each side (conservative).
glm::vec4 ndc_rect_to_pixels(const NdcRect& rect, uint32_t width, uint32_t height);

}  // namespace lintel::render
