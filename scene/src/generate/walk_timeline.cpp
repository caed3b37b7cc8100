// Timed waypoints -> Timeline. Look-ahead targets use the horizontal direction of the next
// segment that moves horizontally, with its slope clamped, so stairs tilt the view and vertical
// climbs through a hole keep looking where the walk continues.
#include "generate/walk_timeline.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel::gen {
namespace {

constexpr double kLookAhead = 2.0;
constexpr double kMaxPitch = 0.75;  // |dy| / horizontal distance of the look direction

glm::dvec3 look_direction(const std::vector<glm::dvec3>& w, size_t i) {
  const size_t n = w.size();
  glm::dvec3 seg = i + 1 < n ? w[i + 1] - w[i] : w[i] - w[i - 1];
  glm::dvec2 horizontal(0.0);
  // The first segment from here on (else before here) that moves horizontally gives the heading.
  for (size_t j = i; j + 1 < n && glm::length(horizontal) < 0.05; ++j)
    horizontal = {w[j + 1].x - w[j].x, w[j + 1].z - w[j].z};
  for (size_t j = i; j > 0 && glm::length(horizontal) < 0.05; --j)
    horizontal = {w[j].x - w[j - 1].x, w[j].z - w[j - 1].z};
  if (glm::length(horizontal) < 0.05) horizontal = {1.0, 0.0};
  const double seg_h = std::sqrt(seg.x * seg.x + seg.z * seg.z);
  double pitch = seg_h > 1e-9 ? seg.y / seg_h : (seg.y > 0 ? kMaxPitch : -kMaxPitch);
  pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
  const glm::dvec2 h = glm::normalize(horizontal);
  return glm::normalize(glm::dvec3(h.x, pitch, h.y));
}

}  // namespace

Timeline walk_timeline(const std::string& name, double fps, const std::vector<glm::dvec3>& waypoints) {
  return walk_timeline(name, fps, std::vector<std::vector<glm::dvec3>>{waypoints});
}

namespace {

// The first millisecond a >= from such that [a, a + 1] keeps kJumpMarginMs away from every frame
// time t0 + i * period (all in ms); `from` itself when fps leaves no such gap.
double jump_slot_ms(double from, double t0, double fps) {
  const double period = 1000.0 / fps;
  for (double a = from; a < from + period + 2.0; a += 1.0) {
    const double phase = std::fmod(a - t0, period);  // ms since the last frame at or before a
    if (phase >= kJumpMarginMs && phase + 1.0 <= period - kJumpMarginMs) return a;
  }
  return from;
}

}  // namespace

Timeline walk_timeline(const std::string& name, double fps, const std::vector<std::vector<glm::dvec3>>& runs) {
  std::vector<std::vector<glm::dvec3>> kept;
  size_t total = 0;
  for (const std::vector<glm::dvec3>& run : runs) {
    std::vector<glm::dvec3> w;
    for (const glm::dvec3& p : run)
      if (w.empty() || glm::length(p - w.back()) > 1e-3) w.push_back(p);
    total += w.size();
    if (!w.empty()) kept.push_back(std::move(w));
  }
  assert(total >= 2);
  (void)total;
  Timeline t;
  t.name = name;
  t.fps = fps;
  t.fov_y_deg = 70.0;
  t.aspect = 16.0 / 9.0;
  double start_ms = 0.0;  // the first key of the run, whole milliseconds
  glm::dvec3 heading(1.0, 0.0, 0.0);
  for (size_t r = 0; r < kept.size(); ++r) {
    const std::vector<glm::dvec3>& w = kept[r];
    if (r > 0) {  // the jump: wait at the run's end for a slot between frames, then 1 ms later land
      const TimelineKey end = t.keys.back();
      const double end_ms = std::round(end.t * 1000.0);
      const double slot_ms = jump_slot_ms(end_ms, std::round(t.keys.front().t * 1000.0), fps);
      if (slot_ms > end_ms) t.keys.push_back({slot_ms / 1000.0, end.eye_world, end.target_world});
      start_ms = slot_ms + 1.0;
    }
    double distance = 0.0;
    for (size_t i = 0; i < w.size(); ++i) {
      if (i > 0) distance += glm::length(w[i] - w[i - 1]);
      TimelineKey key;
      key.t = (start_ms + std::round(distance / kWalkSpeed * 1000.0)) / 1000.0;
      key.eye_world = glm::vec3(w[i]);
      if (w.size() > 1) heading = look_direction(w, i);
      key.target_world = glm::vec3(w[i] + kLookAhead * heading);
      assert(t.keys.empty() || key.t > t.keys.back().t);
      t.keys.push_back(key);
    }
  }
  if (kept.size() > 1 && kept.back().size() == 1) {  // hold where the last jump lands for a frame
    const TimelineKey land = t.keys.back();
    t.keys.push_back(
        {(std::round(land.t * 1000.0) + std::ceil(1000.0 / fps)) / 1000.0, land.eye_world, land.target_world});
  }
  return t;
}

double eye_level(const RoomPlan& room) { return room.floor_mid + 0.5 * kSlabThickness + kEyeHeight; }

glm::dvec3 room_eye_point(const RoomPlan& room) {
  glm::dvec2 c(0.0);
  for (const glm::dvec2& p : room.footprint) c += p;
  c /= double(room.footprint.size());
  return {c.x, eye_level(room), c.y};
}

void add_crossing(const BuildingPlan& plan, const OpeningPlan& o, int from_room, std::vector<glm::dvec3>& waypoints) {
  assert(from_room == o.from || from_room == o.to);
  const int to_room = from_room == o.from ? o.to : o.from;
  const glm::dvec3 forward = from_room == o.from ? o.normal : -o.normal;
  const glm::dvec3 c = o.center();
  if (o.in_slab) {
    waypoints.push_back({c.x, eye_level(plan.rooms[size_t(from_room)]), c.z});
    waypoints.push_back({c.x, eye_level(plan.rooms[size_t(to_room)]), c.z});
    return;
  }
  const double y = eye_level(plan.rooms[size_t(from_room)]);
  const glm::dvec3 at(c.x, y, c.z);
  waypoints.push_back(at - forward);
  waypoints.push_back(at + forward);
}

}  // namespace lintel::gen
