// Which cells an instance's world box reaches: an object larger than its cell (a 4 m box standing
// in a 2 x 0.5 m cell) shows through its neighbours' regions too, so the cull lists it from every
// cell it reaches (docs/visibility.md, "Instances larger than their cell").
#pragma once

#include <lintel/aabb.h>
#include <lintel/world.h>

#include <cstdint>
#include <vector>

namespace lintel {

// Per instance, the cells its bounds reach: its own cell first, then the others in ascending
// order. Reach (conservative, closed: touching counts) = the cells found by walking portals from
// the instance's own cell, crossing a portal when the box overlaps the portal polygon's world
// bounds and meets its plane, and overlaps the neighbour's volume bounds in world space. An empty box reaches
// its own cell only. A box that pokes through a wall without passing a portal is not followed
// (walls are opaque: what pokes out behind one is seen only from the cells it reaches by portals
// or from its own).
struct InstanceReach {
  std::vector<uint32_t> first;  // instances + 1 offsets into `cells`
  std::vector<uint32_t> cells;

  // Computes the reach of every instance of `world` (allocates; once per World for static
  // instances). Cost: per instance, the portals of the cells it reaches.
  void compute(const World& world);
  size_t instance_count() const { return first.empty() ? 0 : first.size() - 1; }
  uint32_t count(uint32_t instance) const { return first[instance + 1] - first[instance]; }
  const uint32_t* begin(uint32_t instance) const { return cells.data() + first[instance]; }
  const uint32_t* end(uint32_t instance) const { return cells.data() + first[instance + 1]; }
};

// Closed overlap of two boxes (touching counts); false when either is empty.
inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return !a.empty() && !b.empty() && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

}  // namespace lintel
