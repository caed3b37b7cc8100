// The GPU-vs-reference comparison and the random scenes of the property test.
#include "reference_compare.h"

#include <lintel/instance_cull.h>
#include <lintel/instance_reach.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace lintel::gpu::test {
namespace {

double max_abs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

bool decide(const ProjectedBox& box, const ClipRegionView& region) { return box_visible_in_region(box, region); }

}  // namespace

bool borderline(const glm::dmat4& view_proj, const glm::dvec3& eye, const Aabb& box, const ClipRegionView& region) {
  if (box.empty()) return false;
  const glm::dvec3 lo(box.min), hi(box.max);
  const ProjectedBox exact = project_aabb(view_proj, eye, lo, hi);
  // Eye containment compares the same floats on both sides: exact, never borderline.
  if (exact.contains_eye) return false;
  const bool decision = decide(exact, region);
  // The GPU works eye-relative (GpuCullConstants), so its error scales with the box's offset from
  // the eye, not with the distance from the origin.
  const double scale = std::max({max_abs(lo - eye), max_abs(hi - eye), 1.0});
  const glm::dvec3 d(kWorldTolerance * scale);
  for (int sign : {1, -1}) {
    const glm::dvec3 plo = lo - double(sign) * d, phi = hi + double(sign) * d;
    if (glm::any(glm::greaterThan(plo, phi))) return true;  // thinner than the tolerance: anything goes
    ProjectedBox p = project_aabb(view_proj, eye, plo, phi);
    p.contains_eye = false;
    if (decide(p, region) != decision) return true;
  }
  if (exact.in_slab) {
    for (int sign : {1, -1}) {
      ProjectedBox p = exact;
      auto widen = [&](float v, int outward) {
        const double delta = kNdcTolerance * std::max(1.0, std::abs(double(v)));
        return float(double(v) + double(outward * sign) * delta);
      };
      p.rect_ndc.min = {widen(exact.rect_ndc.min.x, -1), widen(exact.rect_ndc.min.y, -1)};
      p.rect_ndc.max = {widen(exact.rect_ndc.max.x, 1), widen(exact.rect_ndc.max.y, 1)};
      if (p.rect_ndc.empty()) return true;
      if (decide(p, region) != decision) return true;
    }
  }
  return false;
}

FrameComparison compare_frame(const World& world, const View& view, const VisibleSet& visible, const CullScene& scene,
                              const CullReadback& rb) {
  FrameComparison out;
  const uint32_t n = uint32_t(world.instances.size());
  auto error = [&](std::string message) {
    if (out.errors.size() < 20) out.errors.push_back(std::move(message));
  };
  if (rb.commands.size() != scene.groups.size()) error("command count != group count");
  std::vector<uint8_t> gpu(n, 0);
  for (uint32_t g = 0; g < rb.commands.size() && g < scene.groups.size(); ++g) {
    const DrawIndexedCommand& c = rb.commands[g];
    const GpuDrawGroup& group = scene.groups[g];
    if (c.first_instance != group.base || c.index_count != group.index_count || c.first_index != group.first_index ||
        c.vertex_offset != group.vertex_offset || c.instance_count > group.capacity)
      error("group " + std::to_string(g) + ": command does not match the group");
    for (uint32_t id : rb.group_ids(g)) {
      if (id >= n) {
        error("group " + std::to_string(g) + ": id " + std::to_string(id) + " out of range");
        continue;
      }
      if (world.instances[id].group != g)
        error("instance " + std::to_string(id) + " drawn by group " + std::to_string(g));
      if (gpu[id]++) error("instance " + std::to_string(id) + " drawn twice");
    }
  }
  if (rb.stats.overflow_instances) error("capacity overflow");
  std::vector<uint8_t> cpu(n, 0);
  for (uint32_t id : visible.instances) cpu[id] = 1;

  const glm::dmat4 view_proj = view_projection_d(view);
  const glm::dvec3 eye(view.eye_world);
  // An instance is decided in every visible cell its bounds reach (instance_reach.h); borderline
  // when it is borderline in any of them.
  InstanceReach reach;
  reach.compute(world);
  for (uint32_t i = 0; i < n; ++i) {
    out.cpu_visible += cpu[i];
    out.gpu_visible += gpu[i] ? 1 : 0;
    bool any_visible = false, is_borderline = false;
    for (const uint32_t* c = reach.begin(i); c != reach.end(i); ++c) {
      const VisibleCell* cell = visible.find(*c);
      if (!cell) continue;
      any_visible = true;
      is_borderline =
          is_borderline || borderline(view_proj, eye, world.instances[i].bounds_world, visible.region(*cell));
    }
    if (!any_visible) {
      if (gpu[i] || cpu[i]) error("instance " + std::to_string(i) + " of an invisible cell drawn");
      continue;
    }
    ++out.tested;
    out.borderline += is_borderline;
    if (bool(gpu[i]) == bool(cpu[i])) continue;
    if (is_borderline) {
      (gpu[i] ? out.borderline_gpu_extra : out.borderline_gpu_missing) += 1;
    } else {
      error("instance " + std::to_string(i) + " (cell " + std::to_string(world.instances[i].cell) +
            "): reference says " + (cpu[i] ? "visible" : "culled") + ", GPU says " + (gpu[i] ? "visible" : "culled") +
            ", not borderline");
    }
  }
  return out;
}

// ---- random scenes ------------------------------------------------------------------------------

namespace {

// Deterministic on every platform: no std:: distributions (their algorithms are unspecified).
struct Rng {
  std::mt19937_64 engine;
  double uniform() { return double(engine() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  uint32_t below(uint32_t n) { return uint32_t(uniform() * n) % n; }
  bool chance(double p) { return uniform() < p; }
  glm::dvec3 direction() {
    const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * std::numbers::pi);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
};

// Convex, counter-clockwise, inside [-1, 1]^2: points on a circle at increasing angles, or
// (sometimes) an axis-aligned rect on the 1024-cell snap lattice as the traversal makes them.
std::vector<glm::vec2> random_polygon(Rng& rng) {
  if (rng.chance(0.3)) {
    auto lattice = [&] { return float(-1.0 + 2.0 * rng.below(1025) / 1024.0); };
    float x0 = lattice(), x1 = lattice(), y0 = lattice(), y1 = lattice();
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    if (x0 == x1) x1 = std::min(1.0f, x0 + 2.0f / 1024.0f), x0 = x1 - 2.0f / 1024.0f;
    if (y0 == y1) y1 = std::min(1.0f, y0 + 2.0f / 1024.0f), y0 = y1 - 2.0f / 1024.0f;
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  }
  const uint32_t count = 3 + rng.below(30);  // 3..32
  const double radius = rng.uniform(0.02, 0.9);
  const glm::dvec2 center(rng.uniform(-1.0 + radius, 1.0 - radius), rng.uniform(-1.0 + radius, 1.0 - radius));
  std::vector<double> angles(count);
  for (double& a : angles) a = rng.uniform(0.0, 2.0 * std::numbers::pi);
  std::sort(angles.begin(), angles.end());
  std::vector<glm::vec2> poly;
  for (double a : angles) {
    const glm::vec2 p(glm::dvec2(center.x + radius * std::cos(a), center.y + radius * std::sin(a)));
    if (poly.empty() || glm::length(glm::dvec2(p - poly.back())) > 1e-3) poly.push_back(p);
  }
  while (poly.size() > 3 && glm::length(glm::dvec2(poly.front() - poly.back())) <= 1e-3) poly.pop_back();
  if (poly.size() < 3) return {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.0f, 0.5f}};
  return poly;
}

}  // namespace

RandomCullCase make_random_case(uint64_t seed) {
  Rng rng{std::mt19937_64(seed)};
  RandomCullCase out;
  World& w = out.world;
  w.source = "random-" + std::to_string(seed);

  View& v = out.view;
  // Mostly a building-sized neighbourhood of the origin; sometimes kilometers away, where float
  // world coordinates (and so the GPU's clip coordinates) are coarsest.
  const double far_away = rng.chance(0.1) ? 3000.0 : 0.0;
  v.eye_world = glm::vec3(rng.uniform(-50, 50) + rng.uniform(-far_away, far_away), rng.uniform(-5, 5),
                          rng.uniform(-50, 50) + rng.uniform(-far_away, far_away));
  const glm::dvec3 forward = rng.direction();
  v.target_world = glm::vec3(glm::dvec3(v.eye_world) + forward * rng.uniform(0.5, 10.0));
  v.up_world = std::abs(forward.y) > 0.95 ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  v.fov_y_deg = float(rng.uniform(20.0, 150.0));
  v.aspect = float(rng.uniform(0.5, 3.0));
  v.near_m = float(rng.uniform(0.01, 1.0));
  v.far_m = float(rng.uniform(20.0, 400.0));

  const uint32_t cells = 1 + rng.below(12);
  const uint32_t groups = 1 + rng.below(300);
  const uint32_t instances = 200 + rng.below(2800);
  w.cells.resize(cells);
  for (uint32_t c = 0; c < cells; ++c) w.cells[c].name = "cell" + std::to_string(c);
  w.meshes.resize(groups);
  w.groups.resize(groups);
  for (uint32_t g = 0; g < groups; ++g) {
    w.meshes[g].indices.assign(3 * (1 + g % 5), 0);
    w.meshes[g].positions.assign(3, glm::vec3(0.0f));
    w.groups[g].mesh = g;
  }
  const bool runs = rng.chance(0.5);  // instances of a group listed together, or shuffled
  const glm::dvec3 eye(v.eye_world);
  for (uint32_t i = 0; i < instances; ++i) {
    Instance inst;
    inst.cell = rng.below(cells);
    inst.group = runs ? uint32_t(uint64_t(i) * groups / instances) : rng.below(groups);
    inst.mesh = inst.group;
    glm::dvec3 center;
    const double kind = rng.uniform();
    if (kind < 0.6) {  // in front of the eye, mostly in view
      const glm::dvec3 dir = glm::normalize(forward + 0.8 * rng.direction());
      center = eye + dir * std::exp(rng.uniform(std::log(0.05), std::log(double(v.far_m) * 1.2)));
    } else if (kind < 0.7) {  // across the near plane
      center = eye + forward * double(v.near_m) * rng.uniform(0.5, 1.5) + rng.direction() * rng.uniform(0.0, 0.5);
    } else if (kind < 0.75) {  // around the eye
      center = eye + rng.direction() * rng.uniform(0.0, 0.3);
    } else {  // anywhere
      center = eye + rng.direction() * rng.uniform(0.0, 500.0);
    }
    const glm::dvec3 half(std::exp(rng.uniform(std::log(0.01), std::log(5.0))),
                          std::exp(rng.uniform(std::log(0.01), std::log(5.0))),
                          std::exp(rng.uniform(std::log(0.01), std::log(5.0))));
    inst.bounds_world.min = glm::vec3(center - half);
    inst.bounds_world.max = glm::vec3(center + half);
    w.groups[inst.group].instances.push_back(i);
    w.instances.push_back(inst);
  }

  VisibleSet& vs = out.visible;
  vs.slot_of_cell.assign(cells, -1);
  for (uint32_t c = 0; c < cells; ++c) {
    if (!rng.chance(0.75)) continue;
    VisibleCell vc;
    vc.cell = c;
    vc.first_polygon = uint32_t(vs.polygons.size());
    vc.polygon_count = rng.chance(0.2) ? 1 : 1 + rng.below(kMaxRegionPolygonsLimit);
    for (uint32_t p = 0; p < vc.polygon_count; ++p) {
      const std::vector<glm::vec2> poly =
          rng.chance(0.05) && p == 0 ? std::vector<glm::vec2>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}} : random_polygon(rng);
      vs.polygons.push_back({uint32_t(vs.vertices_ndc.size()), uint32_t(poly.size())});
      vs.vertices_ndc.insert(vs.vertices_ndc.end(), poly.begin(), poly.end());
      for (const glm::vec2& q : poly) vc.rect_ndc.extend(q);
    }
    vs.slot_of_cell[c] = int32_t(vs.cells.size());
    vs.cells.push_back(vc);
  }
  CullData data;
  data.prepare(w);
  cull_instances(data, view_projection_d(v), eye, vs);
  return out;
}

}  // namespace lintel::gpu::test
