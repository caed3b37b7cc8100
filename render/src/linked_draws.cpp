// Linked views' draw lists, built on the CPU per frame slot (linked_draws.h says why).
#include "linked_draws.h"

#include <lintel/visibility_builder.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lintel::render {

static_assert(kMaxLinkViews == kMaxViewTransforms, "the lighting pass's link views hold every transform");

namespace {

float uint_bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}
uint32_t bits_of(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
// Per view a keep run and (as a child of its parent) a cut run, each a header, the portal's plane
// and one plane per edge.
constexpr size_t kPlanesPerRun = 2 + kMaxPortalVertices;
constexpr VkDeviceSize kLinkClipBytes =
    sizeof(GpuLinkClip) * kMaxLinkViews + sizeof(glm::vec4) * 2 * kMaxLinkViews * kPlanesPerRun;

}  // namespace

GpuDrawInstance linked_record(const GpuDrawInstance& plain, const glm::dmat4& seen_from_world, uint32_t transform) {
  GpuDrawInstance r = plain;
  r.mesh_to_world = glm::mat4(seen_from_world * glm::dmat4(plain.mesh_to_world));
  // Rigid or a reflection: the 3x3 is orthogonal, so it maps normals as it maps directions.
  const glm::mat3 turn(seen_from_world);
  const glm::vec3 c0 = turn * glm::vec3(plain.normal_to_world_c0), c1 = turn * glm::vec3(plain.normal_to_world_c1),
                  c2 = turn * glm::vec3(plain.normal_to_world_c2);
  r.normal_to_world_c0 = glm::vec4(c0, plain.normal_to_world_c0.w);
  uint32_t faces = bits_of(plain.normal_to_world_c1.w);
  if (glm::determinant(glm::dmat3(seen_from_world)) < 0.0) faces ^= kFaceMirrored;
  r.normal_to_world_c1 = glm::vec4(c1, uint_bits(faces));
  r.normal_to_world_c2 = glm::vec4(c2, plain.normal_to_world_c2.w);
  r.albedo.w = uint_bits((bits_of(plain.albedo.w) & kCellIdMask) | transform << kCellLinkShift);
  return r;
}

bool linked_pyramid(std::span<const glm::dvec3> polygon_seen, const glm::dvec3& eye, std::vector<glm::vec4>& keep,
                    std::vector<glm::vec4>& cut) {
  const size_t n_vertices = polygon_seen.size();
  if (n_vertices < 3) return false;
  // Newell's normal: robust for any convex polygon, whatever its first vertices.
  glm::dvec3 n(0.0), centroid(0.0);
  for (size_t i = 0; i < n_vertices; ++i) {
    const glm::dvec3& a = polygon_seen[i];
    const glm::dvec3& b = polygon_seen[(i + 1) % n_vertices];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    centroid += a;
  }
  const double len = glm::length(n);
  if (!(len > 0.0)) return false;
  n /= len;
  centroid /= double(n_vertices);
  // 1 mm plus what float loses at these coordinates (the shader tests in float).
  const double margin = 1e-3 + 1e-6 * (glm::length(centroid) + glm::length(eye));
  const double eye_side = glm::dot(n, eye - centroid);
  if (std::abs(eye_side) <= margin) return false;
  if (eye_side > 0.0) n = -n;  // the far side is where the normal points
  const size_t keep_header = keep.size(), cut_header = cut.size();
  keep.emplace_back(0.0f);
  cut.emplace_back(0.0f);
  const double d = -glm::dot(n, centroid);
  keep.emplace_back(glm::vec3(n), float(d - margin));  // strictly beyond: not the mirror's own wall
  cut.emplace_back(glm::vec3(n), float(d + margin));   // the wall face on the plane included
  for (size_t i = 0; i < n_vertices; ++i) {
    glm::dvec3 m = glm::cross(polygon_seen[i] - eye, polygon_seen[(i + 1) % n_vertices] - eye);
    const double ml = glm::length(m);
    if (!(ml > 0.0)) continue;  // a repeated vertex: no edge
    m /= ml;
    if (glm::dot(m, centroid - eye) < 0.0) m = -m;
    const double w = -glm::dot(m, eye);
    keep.emplace_back(glm::vec3(m), float(w + margin));
    cut.emplace_back(glm::vec3(m), float(w - margin));
  }
  const uint32_t keep_n = uint32_t(keep.size() - keep_header - 1), cut_n = uint32_t(cut.size() - cut_header - 1);
  std::memcpy(&keep[keep_header].x, &keep_n, 4);
  std::memcpy(&cut[cut_header].x, &cut_n, 4);
  return true;
}

glm::vec4 ndc_rect_to_pixels(const NdcRect& rect, uint32_t width, uint32_t height) {
  const double w = width, h = height;
  return {float(std::floor((rect.min.x + 1.0) * 0.5 * w) - 1.0), float(std::floor((1.0 - rect.max.y) * 0.5 * h) - 1.0),
          float(std::ceil((rect.max.x + 1.0) * 0.5 * w) + 1.0), float(std::ceil((1.0 - rect.min.y) * 0.5 * h) + 1.0)};
}

Status LinkedDraws::create(gpu::Context& ctx, const DrawShared& shared, std::vector<VkDescriptorSet> sets) {
  ctx_ = &ctx;
  shared_ = shared;
  sets_ = std::move(sets);
  slots_.clear();
  slots_.resize(sets_.size());
  for (uint32_t k = 0; k < slots_.size(); ++k) {
    Slot& slot = slots_[k];
    if (Status s = gpu::Buffer::create(ctx, sizeof(GpuLinkView) * kMaxLinkViews, kStorage, gpu::MemoryUse::Upload,
                                       "link views", slot.link_views);
        !s)
      return s;
    auto* views = static_cast<GpuLinkView*>(slot.link_views.mapped());
    for (uint32_t t = 0; t < kMaxLinkViews; ++t) views[t].world_from_seen = glm::mat4(1.0f);
    if (Status s =
            gpu::Buffer::create(ctx, kLinkClipBytes, kStorage, gpu::MemoryUse::Upload, "link clip", slot.link_clip);
        !s)
      return s;
    std::memset(slot.link_clip.mapped(), 0, kLinkClipBytes);  // no pyramids: everything kept
    if (Status s = TexelView::create(ctx, slot.link_clip, "link clip pyramids", slot.link_clip_texels); !s) return s;
    if (Status s = grow(slot, 64, 16, k); !s) return s;
  }
  return {};
}

Status LinkedDraws::grow(Slot& slot, uint32_t records, uint32_t commands, uint32_t index) {
  if (records > slot.record_capacity) {
    const uint32_t cap = std::max(records, slot.record_capacity * 2);
    if (Status s = gpu::Buffer::create(*ctx_, VkDeviceSize(cap) * sizeof(GpuDrawInstance), kStorage,
                                       gpu::MemoryUse::Upload, "linked draw records", slot.records);
        !s)
      return s;
    if (Status s = gpu::Buffer::create(*ctx_, VkDeviceSize(cap) * 4, kStorage, gpu::MemoryUse::Upload,
                                       "linked draw ids", slot.ids);
        !s)
      return s;
    slot.record_capacity = cap;
    DrawShared mine = shared_;
    if (Status s = TexelView::create(*ctx_, slot.records, "linked draw records", slot.record_texels); !s) return s;
    mine.draw_instances = slot.record_texels.handle();
    write_draw_set(ctx_->device(), sets_[index], mine, slot.ids.handle(), slot.link_clip_texels.handle());
  }
  if (commands > slot.command_capacity) {
    const uint32_t cap = std::max(commands, slot.command_capacity * 2);
    if (Status s = gpu::Buffer::create(*ctx_, VkDeviceSize(cap) * sizeof(gpu::DrawIndexedCommand),
                                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUse::Upload,
                                       "linked draw commands", slot.commands);
        !s)
      return s;
    slot.command_capacity = cap;
  }
  return {};
}

Status LinkedDraws::prepare(const RenderScene& scene, const VisibleSet& visible, const View& view, uint32_t width,
                            uint32_t height, uint32_t slot_index) {
  Slot& slot = slots_[slot_index];
  slot.views.clear();
  slot.record_count = 0;
  const World& world = scene.drawables;
  const size_t drawables = world.instances.size();
  const size_t view_count = visible.transforms.size();
  if (view_count > kMaxLinkViews)
    return Status::error("visible set has " + std::to_string(view_count) + " view transforms; at most " +
                         std::to_string(kMaxLinkViews) + " are drawn");
  auto* link_views = static_cast<GpuLinkView*>(slot.link_views.mapped());
  for (size_t t = 1; t < view_count; ++t)
    link_views[t].world_from_seen = glm::mat4(glm::inverse(visible.transforms[t].seen_from_world));

  const glm::mat4 view_proj = view_projection(view);
  const glm::dvec3 eye(view.eye_world);
  commands_.clear();
  ids_.clear();
  records_.clear();
  keep_planes_.clear();
  cut_planes_.clear();
  keep_first_.assign(view_count, ~0u);
  cut_first_.assign(view_count, ~0u);
  view_drawn_.assign(std::max<size_t>(view_count, 1), 0);
  view_drawn_[0] = 1;
  size_t next_cell = 0, next_instance = 0;
  for (uint32_t t = 1; t < view_count; ++t) {
    // Members of view t: its linked cells' own drawables, then the instances the CPU cull found.
    members_.clear();
    NdcRect rect;
    for (; next_cell < visible.linked_cells.size() && visible.linked_cells[next_cell].transform == t; ++next_cell) {
      const VisibleCell& vc = visible.linked_cells[next_cell];
      if (vc.cell >= world.cells.size())
        return Status::error("visible set names linked cell " + std::to_string(vc.cell) + " out of range");
      rect.extend(vc.rect_ndc.min);
      rect.extend(vc.rect_ndc.max);
      for (uint32_t d : world.cells[vc.cell].instances) members_.push_back(d);
    }
    for (; next_instance < visible.linked_instances.size() && visible.linked_instances[next_instance].transform == t;
         ++next_instance)
      members_.push_back(visible.linked_instances[next_instance].instance);
    for (uint32_t d : members_)
      if (d >= drawables)
        return Status::error("visible set names linked instance " + std::to_string(d) + " out of range");
    std::sort(members_.begin(), members_.end());
    members_.erase(std::unique(members_.begin(), members_.end()), members_.end());
    const ViewTransform& vt = visible.transforms[t];
    // Drawn only when its parent is (a view seen through a view that draws nothing shows nothing).
    if (members_.empty() || rect.empty() || vt.parent >= t || !view_drawn_[vt.parent]) continue;
    view_drawn_[t] = 1;

    // Its portal as the eye sees it: the polygon where the parent view draws it.
    polygon_.clear();
    if (vt.portal < world.portals.size())
      for (const glm::vec3& v : world.portals[vt.portal].polygon_world)
        polygon_.push_back(glm::dvec3(visible.transforms[vt.parent].seen_from_world * glm::dvec4(glm::dvec3(v), 1.0)));
    const size_t keep_at = keep_planes_.size(), cut_at = cut_planes_.size();
    if (linked_pyramid(polygon_, eye, keep_planes_, cut_planes_)) {
      keep_first_[t] = uint32_t(keep_at);
      cut_first_[t] = uint32_t(cut_at);
    }

    LinkedViewDraw draw;
    draw.push = GBufferPush{view_proj, glm::vec4(view.eye_world, 1.0f), ndc_rect_to_pixels(rect, width, height),
                            glm::uvec4(t, 1, 0, 0)};
    const size_t first_id = ids_.size();
    const CommandRange range = append_commands(scene, members_, commands_, ids_);
    draw.first_command = range.first;
    draw.command_count = range.count;
    for (size_t k = first_id; k < ids_.size(); ++k) {
      records_.push_back(linked_record(scene.draw_instances[ids_[k]], vt.seen_from_world, t));
      ids_[k] = uint32_t(k);  // the record's index in this slot's buffer
    }
    slot.views.push_back(draw);
  }
  // Entries the walk above did not reach are out of order or name a transform the set lacks:
  // drawing without them would drop what they show.
  if (next_cell != visible.linked_cells.size() || next_instance != visible.linked_instances.size())
    return Status::error(
        "visible set's linked entries are not in ascending transform order, or name a transform "
        "beyond its " +
        std::to_string(view_count) + " transforms");

  // The clip buffer: per view its keep run, and its drawn children's cut runs one after another.
  clip_views_.assign(kMaxLinkViews, GpuLinkClip{});
  planes_.clear();
  for (uint32_t t = 1; t < view_count; ++t) {
    if (!view_drawn_[t] || keep_first_[t] == ~0u) continue;
    clip_views_[t].keep = glm::uvec4(uint32_t(planes_.size()), 1, 0, 0);
    const size_t first = keep_first_[t];
    planes_.insert(planes_.end(), keep_planes_.begin() + std::ptrdiff_t(first),
                   keep_planes_.begin() + std::ptrdiff_t(first + 1 + pyramid_planes(keep_planes_[first])));
  }
  for (uint32_t v = 0; v < view_count; ++v) {
    if (!view_drawn_[v]) continue;
    const uint32_t start = uint32_t(planes_.size());
    uint32_t children = 0;
    for (uint32_t t = v + 1; t < view_count; ++t) {
      if (visible.transforms[t].parent != v || !view_drawn_[t] || cut_first_[t] == ~0u) continue;
      const size_t first = cut_first_[t];
      planes_.insert(planes_.end(), cut_planes_.begin() + std::ptrdiff_t(first),
                     cut_planes_.begin() + std::ptrdiff_t(first + 1 + pyramid_planes(cut_planes_[first])));
      ++children;
    }
    if (children) clip_views_[v].cut = glm::uvec4(start, children, 0, 0);
  }
  // Plane indices count from the plane array, which follows the kMaxLinkViews views.
  if (planes_.size() > 2 * kMaxLinkViews * kPlanesPerRun)
    return Status::internal("linked views' clip planes outgrew their buffer");
  std::memcpy(slot.link_clip.mapped(), clip_views_.data(), clip_views_.size() * sizeof(GpuLinkClip));
  if (!planes_.empty())
    std::memcpy(static_cast<char*>(slot.link_clip.mapped()) + clip_views_.size() * sizeof(GpuLinkClip), planes_.data(),
                planes_.size() * sizeof(glm::vec4));

  if (Status s = grow(slot, uint32_t(records_.size()), uint32_t(commands_.size()), slot_index); !s) return s;
  if (!records_.empty()) {
    std::memcpy(slot.records.mapped(), records_.data(), records_.size() * sizeof(GpuDrawInstance));
    std::memcpy(slot.ids.mapped(), ids_.data(), ids_.size() * 4);
  }
  if (!commands_.empty())
    std::memcpy(slot.commands.mapped(), commands_.data(), commands_.size() * sizeof(gpu::DrawIndexedCommand));
  slot.record_count = uint32_t(records_.size());
  return {};
}

LinkedFrame LinkedDraws::frame(uint32_t slot) const {
  const Slot& s = slots_[slot];
  return {sets_[slot], s.commands.handle(), s.views};
}

}  // namespace lintel::render
