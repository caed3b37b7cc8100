// View sampling for the accuracy benchmark (bench_views.h).
#include <lintel/reference/bench_views.h>
#include <lintel/cell_locate.h>
#include <lintel/timeline.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lintel {
namespace {

// SplitMix64: a portable generator (std distributions differ between standard libraries).
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
  uint32_t below(uint32_t n) { return uint32_t(uniform() * n) % n; }
};

glm::dvec3 random_direction(Rng& rng) {
  const double az = 2.0 * 3.14159265358979 * rng.uniform();
  const double c = 2.0 * rng.uniform() - 1.0, s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return {s * std::cos(az), c, s * std::sin(az)};
}

View make_view_impl(const glm::dvec3& eye, const glm::dvec3& dir) {
  View v;
  v.eye_world = glm::vec3(eye);
  v.target_world = glm::vec3(eye + dir);
  v.up_world = std::abs(dir.y) > 0.95 ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  v.fov_y_deg = 70.0f;
  v.aspect = 16.0f / 9.0f;
  return v;
}

// No surface within `radius` of the eye along 26 probe directions (axes, edges, corners).
bool clear_impl(const RayGroundTruth& rays, const glm::dvec3& eye, double radius) {
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        bool blocked = false;
        const RayHitId hit =
            rays.cast_ray(glm::vec3(eye), glm::normalize(glm::vec3(x, y, z)), 0.0f, float(radius), &blocked);
        if (blocked || hit.cell != RayHitId::kNone) return false;
      }
  return true;
}

// Whether most of 26 long probe rays from `eye` hit surfaces of `cell` (its shell or instances)
// and none meets a shell from behind.
bool mostly_sees(const RayGroundTruth& rays, const glm::dvec3& eye, uint32_t cell) {
  int own = 0, total = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        bool blocked = false;
        const RayHitId hit = rays.cast_ray(glm::vec3(eye), glm::normalize(glm::vec3(x, y, z)), 0.0f, 1e30f, &blocked);
        if (blocked) return false;
        ++total;
        if (hit.cell == cell) ++own;
      }
  return 2 * own > total;
}

double clearance_impl(const View& v) {
  const double t = std::tan(double(v.fov_y_deg) * 3.14159265358979 / 360.0);
  const double h = double(v.near_m) * t * std::sqrt(1.0 + double(v.aspect) * double(v.aspect));
  return 1.5 * std::sqrt(double(v.near_m) * double(v.near_m) + h * h);
}

}  // namespace

bool eye_clear_of_surfaces(const RayGroundTruth& rays, const glm::dvec3& eye, double radius) {
  return clear_impl(rays, eye, radius);
}
double view_clearance_m(const View& view) { return clearance_impl(view); }
View view_along(const glm::dvec3& eye, const glm::dvec3& dir) { return make_view_impl(eye, dir); }

RayCamera ray_camera_of(const View& v) {
  return RayCamera{v.eye_world, v.target_world, v.up_world, v.fov_y_deg, v.aspect, v.near_m};
}

std::vector<BenchView> make_bench_views(const World& world, const RayGroundTruth& rays, uint32_t count, uint64_t seed) {
  std::vector<BenchView> views;
  if (world.cells.empty() || count == 0) return views;
  Rng rng{seed * 0x2545f4914f6cdd1dull + 1};
  const std::vector<double> volumes = cell_volumes_m3(world);
  const double clearance = clearance_impl(View{});

  // A quarter from the timelines, evenly spaced over all their frames.
  std::vector<std::pair<uint32_t, size_t>> frames;
  for (uint32_t t = 0; t < world.timelines.size(); ++t)
    for (size_t f = 0; f < timeline_frame_count(world.timelines[t]); ++f) frames.emplace_back(t, f);
  const uint32_t from_timeline = std::min<uint32_t>(count / 4, uint32_t(frames.size()));
  for (uint32_t k = 0; k < from_timeline; ++k) {
    const auto [t, f] = frames[size_t(k) * frames.size() / from_timeline];
    const Timeline& tl = world.timelines[t];
    const CameraPose pose = sample_timeline(tl, tl.keys.front().t + double(f) / tl.fps);
    View v = make_view_impl(glm::dvec3(pose.eye_world), glm::dvec3(pose.target_world - pose.eye_world));
    v.target_world = pose.target_world;
    v.fov_y_deg = float(tl.fov_y_deg);
    v.aspect = float(tl.aspect);
    if (!validate_view(v)) continue;
    // Frames outside every cell (a fly-in from outdoors) or too close to a wall are skipped.
    const CellLocation loc = locate_cell(world, glm::dvec3(v.eye_world), volumes);
    if (loc.reason != LocateReason::Containment || !clear_impl(rays, glm::dvec3(v.eye_world), clearance) ||
        !mostly_sees(rays, glm::dvec3(v.eye_world), loc.cell))
      continue;
    views.push_back({v, loc.cell, "timeline"});
  }

  // Then alternately an eye at a portal and an eye inside a cell.
  for (uint32_t tries = 0; views.size() < count && tries < 200 * count; ++tries) {
    const bool at_portal = !world.portals.empty() && (tries % 2 == 0);
    glm::dvec3 eye(0.0);
    uint32_t start = 0;
    if (at_portal) {
      const Portal& p = world.portals[rng.below(uint32_t(world.portals.size()))];
      // A point of the polygon pulled halfway to its centroid, then off the plane.
      const glm::dvec3 c(p.centroid_world), a(p.polygon_world[rng.below(uint32_t(p.polygon_world.size()))]);
      const glm::dvec3 on_plane = c + 0.5 * rng.uniform() * (a - c);
      const double off = std::pow(10.0, -4.0 + 3.5 * rng.uniform()) * (rng.uniform() < 0.5 ? -1.0 : 1.0);
      eye = on_plane + off * glm::dvec3(p.normal_world);
      start = off < 0.0 ? p.from : p.to;
      if (!p.two_way && start == p.to) continue;
    } else {
      const uint32_t c = rng.below(uint32_t(world.cells.size()));
      const Aabb& b = world.cells[c].volume_box_cell;
      if (b.empty()) continue;
      const glm::dvec3 u(rng.uniform(), rng.uniform(), rng.uniform());
      const glm::dvec3 local = glm::dvec3(b.min) + (0.1 + 0.8 * u) * glm::dvec3(b.extent());
      eye = glm::dvec3(world.cells[c].cell_to_world * glm::dvec4(local, 1.0));
      // A volume box of a rotated cell frame is much larger than its room and overlaps the
      // neighbours, so containment alone can name the wrong cell: the eye must also see mostly
      // the sampled cell's own walls.
      const CellLocation loc = locate_cell(world, eye, volumes);
      if (loc.reason != LocateReason::Containment || loc.cell != c || !mostly_sees(rays, eye, c)) continue;
      start = c;
    }
    if (!clear_impl(rays, eye, clearance)) continue;
    const View v = make_view_impl(eye, random_direction(rng));
    if (!validate_view(v)) continue;
    views.push_back({v, start, at_portal ? "portal" : "cell"});
  }
  return views;
}

}  // namespace lintel
