// Internal: the traversal's nodes when a world has linked portals. A node is a (cell, view) pair;
// view 0 is the identity and node c is (c, 0), so worlds without links number nodes as before.
// Views seen through linked portals (at most kMaxViewTransforms, chains of at most kMaxLinkDepth
// links) and their nodes (at most kMaxLinkedNodes) are made on demand during a build; everything
// is sized by prepare() and reused, so a build allocates nothing.
#pragma once

#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace lintel::detail {

inline constexpr uint32_t kNoNode = std::numeric_limits<uint32_t>::max();

struct LinkView {
  ViewTransform transform;    // what VisibleSet::transforms reports
  glm::dmat4 view_proj{1.0};  // the frame's view_proj * seen_from_world
  glm::dvec3 eye{0.0};        // inverse(seen_from_world) * eye: the eye in the cells' own space
};

class LinkViews {
 public:
  // Sizes for `world` (allocates). Without linked portals only view 0 and nodes [0, cells) exist.
  void prepare(const World& world);
  uint32_t node_capacity() const { return cells_ + linked_budget_; }
  bool has_links() const { return linked_budget_ > 0; }

  // Starts a build: view 0 with the frame's own matrix and eye (bit for bit), no linked nodes.
  void reset(const glm::dmat4& view_proj, const glm::dvec3& eye);

  uint32_t cell_of(uint32_t node) const { return node < cells_ ? node : node_cell_[node - cells_]; }
  uint32_t view_of(uint32_t node) const { return node < cells_ ? 0 : node_view_[node - cells_]; }
  const LinkView& view(uint32_t v) const { return views_[v]; }
  uint32_t view_count() const { return static_cast<uint32_t>(views_.size()); }

  // The view seen from view `from_view` through linked portal `portal_index`: an existing view
  // with the same matrix (within 1e-6 relative: a teleport ring that closes maps back onto the
  // view it started from; the merged views differ by a micrometre at most at that scale), else a
  // new one; kNoNode when the chain would exceed kMaxLinkDepth or the views are spent.
  uint32_t view_through(uint32_t from_view, const Portal& portal, uint32_t portal_index);
  // The node of (cell, view), made if new; kNoNode when the linked-node budget is spent.
  uint32_t node(uint32_t view, uint32_t cell);

 private:
  uint32_t cells_ = 0;
  uint32_t linked_budget_ = 0;
  glm::dmat4 frame_view_proj_{1.0};
  glm::dvec3 frame_eye_{0.0};
  std::vector<LinkView> views_;                  // capacity kMaxViewTransforms
  std::vector<int32_t> node_of_;                 // (view - 1) * cells + cell -> node, or -1 (views >= 1)
  std::vector<uint32_t> node_cell_, node_view_;  // linked nodes, made in order
};

}  // namespace lintel::detail
