// CPU instance culling: the reference the GPU cull pass is checked against.
// Rule: an instance is visible iff a cell its bounds reach (instance_reach.h: its own cell and the
// cells behind portals its box overlaps) is visible and its world AABB (Instance::bounds_world:
// the mesh's real extent through the instance matrix, never a unit box) either contains the eye,
// or — clipped against the near and far planes in homogeneous space, its NDC rect — overlaps the
// cell's clip region (rect vs each convex polygon; touching counts). A box entirely behind the
// near plane or beyond the far plane is culled; so is one whose rect misses the region.
// Conservative: the NDC rect of the clipped box contains the box's true projection, so a false
// positive (rect corner overlaps, box does not) is accepted, a false negative is not.
#pragma once

#include <lintel/clip_region.h>
#include <lintel/instance_reach.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

// One instance's bounds in one cell it reaches: what a build's cull reads together, 32 bytes
// (aligned: two to a cache line, never split), so a visible cell's few slots are one or two
// lines rather than one line in each of seven arrays.
struct alignas(32) CullSlot {
  glm::vec3 min{0.0f}, max{0.0f};  // world space, meters
  uint32_t instance = 0;           // World::instances index
  uint32_t cell = 0;               // the reached cell (what a mover slot is matched on)
  friend bool operator==(const CullSlot&, const CullSlot&) = default;
};
static_assert(sizeof(CullSlot) == 32);

// Instance bounds grouped by cell, prepared once per World (allocates).
// Slots of cell c: [cell_begin[c], cell_begin[c + 1]); within a cell, ascending instance index.
// An instance has one slot in every cell it reaches, so size() >= the number of instances.
// Instances moved since prepare() (update()) leave their per-cell slots emptied (an empty box is
// never visible) and live in the mover slots instead: one per (instance, reached cell), in a flat
// list that cull_instances() scans after the visible cells' slots, keeping those whose cell is
// visible. A world whose every instance moves each frame pays one pass over the mover slots.
struct CullData {
  std::vector<CullSlot> slots;       // grouped by cell
  std::vector<uint32_t> cell_begin;  // cells + 1 offsets

  // Mover slots (same layout, CullSlot::cell naming the reached cell), in no particular order.
  std::vector<CullSlot> movers;

  // Groups world.instances by the cells they reach (InstanceReach).
  // Precondition: every instance's cell is a valid index.
  void prepare(const World& world);
  // Re-bounds the `moved` instances (each once, any order) from world.instances[i].bounds_world
  // and `reach` (their lists as InstanceReach::update() left them). Touches only those instances'
  // slots plus one pass over the mover slots; allocates only when the mover list grows past its
  // capacity. Precondition: prepare() ran on this world (same counts).
  void update(const World& world, const InstanceReach& reach, std::span<const uint32_t> moved);
  size_t size() const { return slots.size(); }
  size_t mover_slots() const { return movers.size(); }

 private:
  std::vector<uint32_t> static_first_, static_slot_;  // per instance (CSR): its per-cell slots
  std::vector<uint8_t> is_mover_, marked_;            // per instance
};

// Projection of one world AABB (min <= max componentwise; an empty box is never visible).
struct ProjectedBox {
  bool contains_eye = false;  // the eye is inside the box (closed): visible wherever its cell is
  bool in_slab = false;       // some part lies between the near and far planes
  NdcRect rect_ndc;           // NDC bounds of that part (may exceed [-1, 1]); empty if !in_slab
};
ProjectedBox project_aabb(const glm::dmat4& view_proj, const glm::dvec3& eye_world, const glm::dvec3& box_min,
                          const glm::dvec3& box_max);

// Whether a projected box passes the rule above against one cell's region.
bool box_visible_in_region(const ProjectedBox& box, const ClipRegionView& region);

// Appends the visible instances of every cell in visible.cells to visible.instances (ascending,
// each once) and counts visible.stats.instances_tested (slots, mover slots of visible cells
// included). No allocation when visible.instances has capacity
// for all instances. `data` must have been prepared from the world `visible` was built on.
void cull_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                    VisibleSet& visible);

// The same rule for every entry of visible.linked_cells, in its transform's view: the instance's
// world box is tested from the eye inverse(M) * eye_world with view_proj * M (M the entry's
// ViewTransform::seen_from_world), which is the box seen through the links (a reflection
// included). Appends (transform, instance) pairs to visible.linked_instances, ascending, each
// once per transform.
void cull_linked_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                           VisibleSet& visible);

}  // namespace lintel
