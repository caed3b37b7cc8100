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
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel {

// Structure-of-arrays instance bounds, grouped by cell, prepared once per World (allocates).
// Slots of cell c: [cell_begin[c], cell_begin[c + 1]); within a cell, ascending instance index.
// An instance has one slot in every cell it reaches, so size() >= the number of instances.
struct CullData {
  std::vector<float> min_x, min_y, min_z;  // world space, meters
  std::vector<float> max_x, max_y, max_z;
  std::vector<uint32_t> instance;          // World::instances index of each slot
  std::vector<uint32_t> cell_begin;        // cells + 1 offsets

  // Groups world.instances by the cells they reach (InstanceReach).
  // Precondition: every instance's cell is a valid index.
  void prepare(const World& world);
  size_t size() const { return instance.size(); }
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
// each once) and counts visible.stats.instances_tested (slots). No allocation when visible.instances has capacity
// for all instances. `data` must have been prepared from the world `visible` was built on.
void cull_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                    VisibleSet& visible);

}  // namespace lintel
