// Which cells an instance's world box reaches: an object larger than its cell (a 4 m box standing
// in a 2 x 0.5 m cell) or one straddling a doorway shows through its neighbours' regions too, so
// the cull lists it from every cell it reaches (docs/visibility.md, "Instances larger than their
// cell" and "Moving instances").
#pragma once

#include <lintel/aabb.h>
#include <lintel/world.h>

#include <cstdint>
#include <vector>

namespace lintel {

// Per instance, the cells its bounds reach: its own cell first, then the others in ascending
// order. Reach (conservative, closed: touching counts) = the cells found by walking portals from
// the instance's own cell (Instance::cell), crossing a portal when the box overlaps the portal
// polygon's world bounds and meets its plane, and overlaps the neighbour's volume bounds in world
// space. An empty box reaches its own cell only. A box that pokes through a wall without passing
// a portal is not followed (walls are opaque: what pokes out behind one is seen only from the
// cells it reaches by portals or from its own).
// Door state is NOT read: reach is where the box is, and a box passing a closed door's opening is
// still on both sides of it (a closed door stops sight, not matter). Drawing that part from the
// other cell is conservative, and toggling a door stays O(1) (docs/visibility.md).
//
// Storage: each instance owns a slot of `capacity` entries in one array; update() rewrites a slot
// in place when the new list fits and moves it to the end of the array otherwise (the old slot is
// left as slack and reclaimed by a compaction once slack exceeds the live entries). Read through
// count()/begin()/end() only.
class InstanceReach {
 public:
  // Computes the reach of every instance of `world` and keeps the world's portal and volume
  // bounds for update() (allocates). Cost: per instance, the portals of the cells it reaches.
  void compute(const World& world);
  // Recomputes one instance's list from world.instances[instance] (its cell and bounds_world), as
  // compute() would. Precondition: compute() ran on this world (same cells and portals, geometry
  // unchanged since) and instance < instance_count(). Allocates only when the list outgrows its
  // slot (amortized: the slot doubles) or a compaction runs. Cost: as compute() for one instance.
  void update(const World& world, uint32_t instance);

  size_t instance_count() const { return offset_.size(); }
  uint32_t count(uint32_t instance) const { return count_[instance]; }
  const uint32_t* begin(uint32_t instance) const { return cells_.data() + offset_[instance]; }
  const uint32_t* end(uint32_t instance) const { return begin(instance) + count_[instance]; }
  // Sum of count() over all instances: the slots a per-cell cull list needs.
  size_t total() const { return total_; }
  // What compute() kept of portal p: its polygon's world bounds, and the polygon's largest distance
  // from its plane (the loader allows 1e-3 x its size).
  const Aabb& portal_box(uint32_t portal) const { return portal_world_[portal]; }
  double portal_off_plane(uint32_t portal) const { return off_plane_[portal]; }

 private:
  void flood(const Instance& inst);  // fills scratch_ (own cell first, rest sorted)
  void compact();

  std::vector<uint32_t> offset_, count_, capacity_;  // per instance, into cells_
  std::vector<uint32_t> cells_;
  size_t total_ = 0, slack_ = 0;
  std::vector<Aabb> volume_world_, portal_world_;  // per cell / portal, for update()
  // Compact copies of what the flood reads, so that a move touches a few cache lines, not the
  // World's large Cell and Portal records: per portal its plane (normal, d) and its polygon's
  // largest distance from it; per cell its links (CSR of Cell::links).
  std::vector<glm::dvec4> plane_;
  std::vector<double> off_plane_;
  std::vector<uint32_t> link_begin_;
  std::vector<PortalLink> links_;
  std::vector<uint8_t> seen_;
  std::vector<uint32_t> stack_, scratch_;
};

// Closed overlap of two boxes (touching counts); false when either is empty.
inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return !a.empty() && !b.empty() && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

}  // namespace lintel
