// Viewer-cell tracking by portal crossings, with containment as the fallback.
// Learns from: the Lintel lessons (rooting the flood at "the cell containing the eye" flaps at
// doorways) and Godot's rooms & portals (stale room membership while moving between rooms; the
// world vanishing for a frame at a portal). A band of hysteresis past each portal's plane, the same
// from both sides, keeps a resting eye from flapping; the doorway rule keeps the visible set
// conservative inside the band.
#include <lintel/viewer_tracker.h>

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>

namespace lintel {
namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

double hysteresis_band_m(const Portal& portal) {
  const auto& poly = portal.polygon_world;
  double magnitude = 0.0;
  for (const glm::vec3& v : poly)
    magnitude = std::max({magnitude, double(std::abs(v.x)), double(std::abs(v.y)), double(std::abs(v.z))});
  // Inradius about the centroid: the distance from the centroid to the nearest edge line.
  const glm::dvec3 c(portal.centroid_world), n(portal.normal_world);
  double inradius = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    const glm::dvec3 edge = b - a;
    const double length = glm::length(edge);
    if (!(length > 0.0)) continue;
    inradius = std::min(inradius, std::abs(glm::dot(glm::cross(edge, c - a), n)) / length);
  }
  const double wanted = std::max(kMinHysteresisBand_m, 8.0 * double(FLT_EPSILON) * magnitude);
  const double cap = std::min(kMaxHysteresisBand_m, std::isfinite(inradius) ? 0.01 * inradius : kMaxHysteresisBand_m);
  return std::min(wanted, cap);
}

const char* transition_reason_name(TransitionReason reason) {
  switch (reason) {
    case TransitionReason::PortalCrossing:
      return "portal crossing";
    case TransitionReason::Containment:
      return "containment";
    case TransitionReason::Nearest:
      return "nearest";
    case TransitionReason::Teleport:
      return "teleport";
  }
  return "?";
}

void ViewerTracker::record(const CellTransition& t) {
  assert(transition_count_ < transitions_.size());
  transitions_[transition_count_++] = t;
}

void ViewerTracker::relocate(const World& world, const glm::dvec3& eye) {
  const CellLocation where = locate_cell(world, eye, volumes_m3_);
  if (where.cell == cell_) return;
  record({cell_, where.cell,
          where.reason == LocateReason::Containment ? TransitionReason::Containment : TransitionReason::Nearest,
          kNoCell});
  cell_ = where.cell;
}

void ViewerTracker::bind(const World& world) {
  world_ = &world;
  revision_ = world.revision;
  const size_t cells = world.cells.size();
  incident_begin_.assign(cells + 1, 0);
  // Mirrors are walls here; a teleport is crossed out of its `from` only (its polygon borders no other cell).
  for (const Portal& p : world.portals) {
    if (p.link == PortalLinkKind::Mirror) continue;
    ++incident_begin_[p.from + 1];
    if (p.to != p.from && !p.linked()) ++incident_begin_[p.to + 1];
  }
  for (size_t c = 0; c < cells; ++c) incident_begin_[c + 1] += incident_begin_[c];
  incident_.assign(incident_begin_.back(), 0);
  std::vector<uint32_t> next(incident_begin_.begin(), incident_begin_.end() - 1);
  for (uint32_t i = 0; i < world.portals.size(); ++i) {
    const Portal& p = world.portals[i];
    if (p.link == PortalLinkKind::Mirror) continue;
    incident_[next[p.from]++] = i;
    if (p.to != p.from && !p.linked()) incident_[next[p.to]++] = i;
  }
  volumes_m3_ = cell_volumes_m3(world);
  band_m_.resize(world.portals.size());
  max_band_m_ = 0.0;
  for (size_t i = 0; i < world.portals.size(); ++i) {
    band_m_[i] = hysteresis_band_m(world.portals[i]);
    max_band_m_ = std::max(max_band_m_, band_m_[i]);
  }
}

Status ViewerTracker::reset(const World& world, const glm::vec3& eye_world) {
  if (!finite3(eye_world)) return Status::error("tracker: eye is not finite");
  if (world.cells.empty()) return Status::error("tracker: the world has no cells");
  if (!(options_.jump_distance_m > 0.0f) || !(options_.lost_tolerance_m >= 0.0f) ||
      !(options_.found_elsewhere_m >= 0.0f) || options_.max_crossings_per_move < 1 ||
      options_.max_crossings_per_move > kMaxTrackerCrossings)
    return Status::error("tracker: options out of range");
  bind(world);
  transition_count_ = 0;
  teleport_ = glm::dmat4(1.0);
  cell_ = kNoCell;
  eye_ = eye_world;
  relocate(world, glm::dvec3(eye_world));
  return {};
}

Status ViewerTracker::update(const World& world, const glm::vec3& eye_world) {
  if (world_ != &world || cell_ == kNoCell) return Status::error("tracker: update() before reset() with this world");
  if (!finite3(eye_world)) return Status::error("tracker: eye is not finite");
  if (revision_ != world.revision && world.cells.empty()) return Status::error("tracker: the world has no cells");
  transition_count_ = 0;
  teleport_ = glm::dmat4(1.0);
  glm::dvec3 p0(eye_), p1(eye_world);
  eye_ = eye_world;
  if (revision_ != world.revision) {  // another level or an edited world: start over from containment
    bind(world);
    if (cell_ >= world.cells.size()) cell_ = kNoCell;
    relocate(world, p1);
    return {};
  }

  if (glm::length(p1 - p0) > double(options_.jump_distance_m)) {
    relocate(world, p1);
    return {};
  }

  // Follow crossings in order along the segment. Each portal's side is measured from the tracked
  // cell, and the plane plus its band belong to that cell: the same rule from either side.
  double t_done = 0.0;
  uint32_t last_portal = kNoCell;
  for (uint32_t step = 0; step < options_.max_crossings_per_move; ++step) {
    uint32_t best_portal = kNoCell;
    double best_t = 2.0;
    for (uint32_t k = incident_begin_[cell_]; k < incident_begin_[cell_ + 1]; ++k) {
      const uint32_t pi = incident_[k];
      if (pi == last_portal) continue;
      const Portal& portal = world.portals[pi];
      const double band = band_m_[pi];
      const double s0 = portal_signed_distance(portal, cell_, p0);
      const double s1 = portal_signed_distance(portal, cell_, p1);
      if (!(s0 <= band && s1 > band)) continue;
      const double t = (band - s0) / (s1 - s0);
      if (t < t_done || t >= best_t) continue;
      // Inside the polygon (closed, a micrometer of slack for the plane's float rounding).
      if (!projects_inside_portal(portal, p0 + (p1 - p0) * t, 1e-6)) continue;
      best_t = t;
      best_portal = pi;
    }
    if (best_portal == kNoCell) break;
    const Portal& crossed = world.portals[best_portal];
    const uint32_t next = cell_ == crossed.from ? crossed.to : crossed.from;
    if (crossed.linked()) {  // carried by the link: the rest of the move goes on at the far place
      p0 = glm::dvec3(crossed.link_world * glm::dvec4(p0, 1.0));
      p1 = glm::dvec3(crossed.link_world * glm::dvec4(p1, 1.0));
      teleport_ = crossed.link_world * teleport_;
      eye_ = glm::vec3(p1);
    }
    record(
        {cell_, next, crossed.linked() ? TransitionReason::Teleport : TransitionReason::PortalCrossing, best_portal});
    cell_ = next;
    t_done = best_t;
    last_portal = best_portal;
  }

  // Lost: far outside the tracked volume, or beyond found_elsewhere_m and inside another room.
  const double outside_m = cell_volume_distance_m(world, cell_, p1);
  if (outside_m > double(options_.lost_tolerance_m)) {
    relocate(world, p1);
  } else if (outside_m > std::max(double(options_.found_elsewhere_m), max_band_m_)) {
    const CellLocation where = locate_cell(world, p1, volumes_m3_);
    if (where.reason == LocateReason::Containment) relocate(world, p1);
  }
  return {};
}

}  // namespace lintel
