// The cells an instance's world box reaches through portals (instance_reach.h). A flood over the
// portal graph, limited to what the box overlaps; Godot's rooms lesson (objects dropping while
// they straddle two rooms) says a portal engine must list such objects in every room they touch.
#include <lintel/instance_reach.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel {
namespace {

// Whether the box reaches the portal's plane (n, d in `plane`): its corners' signed distances do
// not all have one sign, with a tolerance so the test stays conservative: the polygon's own
// distance from its plane (`off_plane`, computed once; the loader allows 1e-3 x the portal's size)
// plus float rounding of the coordinates.
bool box_meets_plane(const Aabb& box, const glm::dvec4& plane, double off_plane) {
  const glm::dvec3 n(plane);
  const glm::dvec3 lo(box.min), hi(box.max);
  const double d = plane.w;
  const double far =
      glm::dot(n, glm::dvec3(n.x >= 0 ? hi.x : lo.x, n.y >= 0 ? hi.y : lo.y, n.z >= 0 ? hi.z : lo.z)) - d;
  const double near =
      glm::dot(n, glm::dvec3(n.x >= 0 ? lo.x : hi.x, n.y >= 0 ? lo.y : hi.y, n.z >= 0 ? lo.z : hi.z)) - d;
  double scale = std::max(std::abs(d), 1.0);
  for (int k = 0; k < 3; ++k) scale = std::max({scale, std::abs(lo[k]), std::abs(hi[k])});
  const double tolerance = off_plane + 1e-5 * scale;
  return near <= tolerance && far >= -tolerance;
}

double off_plane_of(const Portal& portal) {
  const glm::dvec3 n(portal.normal_world);
  const double d = double(portal.plane_d_world);
  double off_plane = 0.0;
  for (const glm::vec3& v : portal.polygon_world)
    off_plane = std::max(off_plane, std::abs(glm::dot(n, glm::dvec3(v)) - d));
  return off_plane;
}

}  // namespace

void InstanceReach::flood(const Instance& inst) {
  assert(inst.cell + 1 < link_begin_.size());
  scratch_.assign(1, inst.cell);
  seen_[inst.cell] = 1;
  if (!inst.bounds_world.empty()) {
    stack_.assign(1, inst.cell);
    while (!stack_.empty()) {
      const uint32_t c = stack_.back();
      stack_.pop_back();
      for (uint32_t k = link_begin_[c]; k < link_begin_[c + 1]; ++k) {  // compact copy of Cell::links
        const PortalLink& link = links_[k];
        if (seen_[link.neighbour]) continue;
        if (!boxes_overlap(inst.bounds_world, portal_world_[link.portal]) ||
            !box_meets_plane(inst.bounds_world, plane_[link.portal], off_plane_[link.portal]))
          continue;
        if (!boxes_overlap(inst.bounds_world, volume_world_[link.neighbour])) continue;
        seen_[link.neighbour] = 1;
        scratch_.push_back(link.neighbour);
        stack_.push_back(link.neighbour);
      }
    }
  }
  for (uint32_t c : scratch_) seen_[c] = 0;
  std::sort(scratch_.begin() + 1, scratch_.end());
}

void InstanceReach::compute(const World& world) {
  const size_t n_cells = world.cells.size();
  volume_world_.assign(n_cells, Aabb{});
  portal_world_.assign(world.portals.size(), Aabb{});
  off_plane_.resize(world.portals.size());
  plane_.resize(world.portals.size());
  for (size_t p = 0; p < world.portals.size(); ++p) {
    off_plane_[p] = off_plane_of(world.portals[p]);
    plane_[p] = glm::dvec4(glm::dvec3(world.portals[p].normal_world), double(world.portals[p].plane_d_world));
  }
  link_begin_.assign(1, 0);
  links_.clear();
  for (const Cell& cell : world.cells) {
    links_.insert(links_.end(), cell.links.begin(), cell.links.end());
    link_begin_.push_back(uint32_t(links_.size()));
  }
  for (size_t c = 0; c < n_cells; ++c)
    volume_world_[c] = transform_aabb(world.cells[c].cell_to_world, world.cells[c].volume_box_cell);
  for (size_t p = 0; p < world.portals.size(); ++p)
    for (const glm::vec3& v : world.portals[p].polygon_world) portal_world_[p].extend(v);
  seen_.assign(n_cells, 0);

  const size_t n = world.instances.size();
  offset_.assign(n, 0);
  count_.assign(n, 0);
  capacity_.assign(n, 0);
  cells_.clear();
  cells_.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    flood(world.instances[i]);
    offset_[i] = uint32_t(cells_.size());
    count_[i] = capacity_[i] = uint32_t(scratch_.size());
    cells_.insert(cells_.end(), scratch_.begin(), scratch_.end());
  }
  total_ = cells_.size();
  slack_ = 0;
}

void InstanceReach::update(const World& world, uint32_t instance) {
  assert(instance < offset_.size() && seen_.size() == world.cells.size() &&
         portal_world_.size() == world.portals.size());
  flood(world.instances[instance]);
  const uint32_t n = uint32_t(scratch_.size());
  total_ = total_ - count_[instance] + n;
  if (n > capacity_[instance]) {  // outgrown: a new slot at the end, twice as large
    slack_ += capacity_[instance];
    offset_[instance] = uint32_t(cells_.size());
    capacity_[instance] = std::max<uint32_t>(4, 2 * n);
    cells_.resize(cells_.size() + capacity_[instance], 0);
  }
  std::copy(scratch_.begin(), scratch_.end(), cells_.begin() + offset_[instance]);
  count_[instance] = n;
  if (slack_ > 1024 && slack_ > cells_.size() / 2) compact();
}

void InstanceReach::compact() {
  std::vector<uint32_t> packed;
  packed.reserve(cells_.size() - slack_);
  for (size_t i = 0; i < offset_.size(); ++i) {
    const uint32_t at = uint32_t(packed.size());
    packed.insert(packed.end(), cells_.begin() + offset_[i], cells_.begin() + offset_[i] + capacity_[i]);
    offset_[i] = at;
  }
  cells_.swap(packed);
  slack_ = 0;
}

}  // namespace lintel
