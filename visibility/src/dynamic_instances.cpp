// Moving instances (dynamic_instances.h). Learns from: Godot 3's rooms & portals "roaming" objects
// (kept in the right room as they move; "sprawl" across the portals their bounds straddle) and the
// reports about it (objects dropping while moving between rooms, stale room membership), and from
// Lintel's viewer tracker (crossings with a hysteresis band; containment after a jump).
#include <lintel/dynamic_instances.h>

#include <lintel/cell_locate.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace lintel {
namespace {

bool finite_affine(const glm::mat4& m) {
  // A float is an infinity or a NaN exactly when its exponent bits are all ones: one max over the
  // 16 exponents instead of 16 branches.
  uint32_t bits[16];
  std::memcpy(bits, &m[0][0], sizeof(bits));
  uint32_t exponent = 0;
  for (uint32_t b : bits) exponent = std::max(exponent, b & 0x7f800000u);
  return exponent != 0x7f800000u && m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
}

}  // namespace

void DynamicInstances::bind(const World& world) {
  world_ = &world;
  revision_ = world.revision;
  graph_.build(world);
  grid_.build(world);
  reach_.compute(world);
  dirty_flag_.assign(world.instances.size(), 0);
  inside_budget_m_.assign(world.instances.size(), 0.0);
  portal_budget_m_.assign(world.instances.size(), 0.0);
  dirty_.clear();
  dirty_.reserve(world.instances.size());
  taken_.clear();
  taken_.reserve(world.instances.size());
  crossed_.clear();
  crossed_.reserve(kMaxTrackerCrossings);
  taken_from_ = taken_through_ = world.instance_moves;
  relocated_ = false;
}

Status DynamicInstances::reset(const World& world) {
  if (!(options_.jump_distance_m > 0.0f) || !(options_.lost_tolerance_m >= 0.0f) ||
      !(options_.found_elsewhere_m >= 0.0f) || options_.max_crossings_per_move < 1 ||
      options_.max_crossings_per_move > kMaxTrackerCrossings)
    return Status::error("moving instances: options out of range");
  bind(world);
  return {};
}

double DynamicInstances::portal_clearance_m(uint32_t cell, const glm::dvec3& p) const {
  // A crossing point lies `band` beyond the portal's plane, over its polygon (1 um slack): within
  // band + 2 x off-plane + 1 um of the polygon's bounds. The rest covers float rounding of p.
  const double rounding = 1e-6 + 1e-6 * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  double clearance = std::numeric_limits<double>::infinity();
  for (uint32_t k = graph_.incident_begin[cell]; k < graph_.incident_begin[cell + 1]; ++k) {
    const uint32_t pi = graph_.incident[k];
    const Aabb& box = reach_.portal_box(pi);
    const glm::dvec3 lo(box.min), hi(box.max);
    const glm::dvec3 outside = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
    clearance =
        std::min(clearance, glm::length(outside) - graph_.band_m[pi] - 2.0 * reach_.portal_off_plane(pi) - rounding);
  }
  return clearance;
}

uint32_t DynamicInstances::follow(const World& world, uint32_t instance, uint32_t cell, const glm::dvec3& c0,
                                  const glm::dvec3& c1) {
  crossed_.clear();
  relocated_ = false;
  double& budget = inside_budget_m_[instance];
  double& portal_budget = portal_budget_m_[instance];
  const double step = glm::length(c1 - c0);
  auto settle = [&](uint32_t settled) {  // measure the clearances for the next moves
    budget = 0.0;
    // A convex volume's face planes give the clearance directly; others take the general measure.
    if (const double convex = graph_.inside_clearance(settled, c1); convex > 0.0)
      budget = 0.999 * convex - 1e-6;
    else if (graph_.surely_inside(settled, c1) || cell_volume_distance_m(world, settled, c1) == 0.0)
      budget = 0.999 * cell_volume_clearance_m(world, settled, c1) - 1e-6;
    portal_budget = portal_clearance_m(settled, c1);
    return settled;
  };
  if (step > double(options_.jump_distance_m)) {
    relocated_ = true;
    return settle(locate_cell(world, grid_, c1, graph_.volumes_m3).cell);
  }
  if (step < budget && step < portal_budget) {  // no portal within reach, and still inside: nothing to test
    budget -= step;
    portal_budget -= step;
    return cell;
  }
  cell = follow_portal_crossings(world, graph_, cell, c0, c1, options_.max_crossings_per_move, &crossed_);
  if (crossed_.empty() && step < budget) {  // still inside: the lost test cannot fire
    budget -= step;
    portal_budget = portal_clearance_m(cell, c1);
    return cell;
  }
  // A convex volume's planes decide containment: inside, 0; beyond a face plane by more than the
  // frames' rounding, the distance without the containment test (winding number) first. NaN (not
  // convex) and the rounding band take the general measure.
  const double by_planes = graph_.inside_clearance(cell, c1);
  const double rounding = 1e-5 * std::max({1.0, std::abs(c1.x), std::abs(c1.y), std::abs(c1.z)});
  const double outside_m = by_planes >= 0.0        ? 0.0
                           : by_planes < -rounding ? cell_volume_clearance_m(world, cell, c1)
                                                   : cell_volume_distance_m(world, cell, c1);
  if (outside_m > double(options_.lost_tolerance_m)) {
    relocated_ = true;
    return settle(locate_cell(world, grid_, c1, graph_.volumes_m3).cell);
  }
  if (outside_m > std::max(double(options_.found_elsewhere_m), graph_.max_band_m)) {
    uint32_t holder = 0;
    if (contained_cell(world, grid_, c1, graph_.volumes_m3, holder)) {
      relocated_ = holder != cell;
      return settle(holder);
    }
  }
  return settle(cell);
}

Status DynamicInstances::move(World& world, uint32_t instance, const glm::mat4& mesh_to_world) {
  if (instance >= world.instances.size())
    return Status::error("moving instances: instance " + std::to_string(instance) + " is not one of the world's " +
                         std::to_string(world.instances.size()));
  if (!finite_affine(mesh_to_world))
    return Status::error("moving instances: instance '" + world.instances[instance].name +
                         "': the transform is not a finite affine matrix");
  if (world_ != &world || revision_ != world.revision) bind(world);
  Instance& inst = world.instances[instance];
  const Aabb bounds = transform_aabb(mesh_to_world, world.meshes[inst.mesh].bounds_mesh);
  const uint32_t old_cell = inst.cell;
  uint32_t cell = inst.cell;
  if (!inst.bounds_world.empty() && !bounds.empty()) {
    cell = follow(world, instance, inst.cell, glm::dvec3(inst.bounds_world.center()), glm::dvec3(bounds.center()));
  } else {
    crossed_.clear();
    relocated_ = false;
    inside_budget_m_[instance] = portal_budget_m_[instance] = 0.0;  // not measured here: measure next time
  }
  inst.mesh_to_world = mesh_to_world;
  inst.bounds_world = bounds;
  if (cell != inst.cell) {
    std::vector<uint32_t>& old_list = world.cells[inst.cell].instances;
    const auto at = std::lower_bound(old_list.begin(), old_list.end(), instance);
    if (at != old_list.end() && *at == instance) old_list.erase(at);
    std::vector<uint32_t>& new_list = world.cells[cell].instances;
    new_list.insert(std::lower_bound(new_list.begin(), new_list.end(), instance), instance);
    inst.cell = cell;
  }
  // A box that stays farther from every portal of its unchanged cell than its half-diagonal meets
  // no portal's bounds: its reach is its own cell alone, as the flood would find.
  const bool reach_unchanged = !bounds.empty() && cell == old_cell && reach_.count(instance) == 1 &&
                               portal_budget_m_[instance] > 0.5 * glm::length(glm::dvec3(bounds.max - bounds.min));
  if (!reach_unchanged) reach_.update(world, instance);
  if (!dirty_flag_[instance]) {
    dirty_flag_[instance] = 1;
    dirty_.push_back(instance);
  }
  ++world.instance_moves;
  return {};
}

std::span<const uint32_t> DynamicInstances::take_moved() {
  taken_.swap(dirty_);
  dirty_.clear();
  for (uint32_t i : taken_) dirty_flag_[i] = 0;
  std::sort(taken_.begin(), taken_.end());
  taken_from_ = taken_through_;
  taken_through_ = world_ ? world_->instance_moves : 0;
  return taken_;
}

}  // namespace lintel
