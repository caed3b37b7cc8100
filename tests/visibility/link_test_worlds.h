// Linked portals (teleports, mirrors) added to the hand-built test worlds, and the conservative
// check of a build against the link-following ray walk; shared by test_linked_portals and the
// rapidcheck properties.
#pragma once

#include "test_worlds.h"

#include <lintel/visibility_builder.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::testing {

// Appends a one-way linked portal to t.world (call finalize_world after): polygon in layout space,
// its normal pointing away from `from_side_layout`. Mirror: link_world = the reflection, to = from.
// Teleport: link_world left for link_teleport().
uint32_t add_linked_portal(TestWorld& t, uint32_t from, uint32_t to, const std::vector<glm::vec3>& polygon_layout,
                           const glm::vec3& from_side_layout, PortalLinkKind kind, const std::string& name);
// Sets portal `source`'s teleport link onto portal `target` (link_onto_target); false if not congruent.
bool link_teleport(World& world, uint32_t source, uint32_t target);

// One room (chain of 1: x in [0, 4], y in [0, 3], z in [-2, 2]) with mirrors on its two x walls.
TestWorld make_facing_mirrors(const WorldOptions& options = {});
// A chain of `rooms` (>= 2) closed into a ring by a teleport seam: room rooms-1's east wall links
// onto room 0's west wall and back, plus a mirror on room 0's south wall.
TestWorld make_teleport_ring(uint32_t rooms, const WorldOptions& options = {});

struct LinkCheck {
  uint64_t rays = 0, ambiguous = 0, beyond_depth = 0, checked_entries = 0;
  std::string failure;  // empty: every entry the ray walk sees is in the set with its pixel in the region
};
// Casts a `grid` x `grid` of rays through pixel centres; every (cell, transform) a ray sees within
// kMaxLinkDepth links must be an entry of `visible` (`cells` for the identity, `linked_cells` with
// a transform whose matrix equals the ray's within 1e-6 relative) whose region contains the pixel
// within `slack_ndc`; a ray needing more links must end in an unresolved rect (within the slack).
LinkCheck check_links_conservative(const World& world, const View& view, uint32_t start_cell, const VisibleSet& visible,
                                   uint32_t grid, double slack_ndc);

}  // namespace lintel::testing
