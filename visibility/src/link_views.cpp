// The (cell, view) nodes of a traversal through linked portals: views composed along chains of
// teleports and mirrors (the camera moved through each link), deduplicated by matrix so a ring
// that closes returns to the view it left, and bounded in depth and number (the termination
// argument in docs/visibility.md, "Linked portals"). Learns from: Luebke & Georges 1995 (mirrors
// as portals with a reflected view), Source / Portal (recursion depth with a flat fill).
#include "link_views.h"

#include <lintel/portal_link.h>
#include <lintel/visibility_builder.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel::detail {

void LinkViews::prepare(const World& world) {
  cells_ = static_cast<uint32_t>(world.cells.size());
  const bool links =
      std::any_of(world.portals.begin(), world.portals.end(), [](const Portal& p) { return p.linked(); });
  linked_budget_ = links ? linked_node_budget(cells_) : 0;
  views_.clear();
  views_.reserve(links ? kMaxViewTransforms : 1);
  node_of_.assign(links ? size_t(kMaxViewTransforms - 1) * cells_ : 0, -1);
  node_cell_.clear();
  node_view_.clear();
  node_cell_.reserve(linked_budget_);
  node_view_.reserve(linked_budget_);
}

void LinkViews::reset(const glm::dmat4& view_proj, const glm::dvec3& eye) {
  for (size_t k = 0; k < node_cell_.size(); ++k)  // forget the previous build's linked nodes only
    node_of_[size_t(node_view_[k] - 1) * cells_ + node_cell_[k]] = -1;
  node_cell_.clear();
  node_view_.clear();
  frame_view_proj_ = view_proj;
  frame_eye_ = eye;
  // View 0's transform is the identity, written once: a build rewrites only its matrix and eye
  // (fewer lines written per build; the transform's lines are not touched again).
  if (views_.empty()) views_.emplace_back();
  views_.resize(1);
  views_[0].view_proj = view_proj;
  views_[0].eye = eye;
}

uint32_t LinkViews::view_through(uint32_t from_view, const Portal& portal, uint32_t portal_index) {
  const LinkView& parent = views_[from_view];
  // Seen through the link, the far place's geometry sits at M_parent * inverse(L).
  const glm::dmat4 seen = parent.transform.seen_from_world * glm::inverse(portal.link_world);
  double scale = 1.0;
  for (int r = 0; r < 3; ++r) scale = std::max(scale, std::abs(seen[3][r]));
  for (uint32_t v = 0; v < views_.size(); ++v) {
    const glm::dmat4& m = views_[v].transform.seen_from_world;
    bool same = true;
    for (int c = 0; c < 4 && same; ++c)
      for (int r = 0; r < 4 && same; ++r) same = std::abs(m[c][r] - seen[c][r]) <= 1e-6 * scale;
    if (same) return v;
  }
  if (parent.transform.depth + 1 > kMaxLinkDepth || views_.size() >= kMaxViewTransforms) return kNoNode;
  LinkView child;
  child.transform.seen_from_world = seen;
  child.transform.parent = from_view;
  child.transform.portal = portal_index;
  child.transform.depth = parent.transform.depth + 1;
  child.transform.mirrored = glm::determinant(glm::dmat3(seen)) < 0.0;
  child.view_proj = frame_view_proj_ * seen;
  child.eye = glm::dvec3(glm::inverse(seen) * glm::dvec4(frame_eye_, 1.0));
  views_.push_back(child);
  return static_cast<uint32_t>(views_.size() - 1);
}

uint32_t LinkViews::node(uint32_t view, uint32_t cell) {
  assert(view < views_.size() && cell < cells_);
  if (view == 0) return cell;
  int32_t& slot = node_of_[size_t(view - 1) * cells_ + cell];
  if (slot >= 0) return static_cast<uint32_t>(slot);
  if (node_cell_.size() >= linked_budget_) return kNoNode;
  slot = static_cast<int32_t>(cells_ + node_cell_.size());
  node_cell_.push_back(cell);
  node_view_.push_back(view);
  return static_cast<uint32_t>(slot);
}

}  // namespace lintel::detail
