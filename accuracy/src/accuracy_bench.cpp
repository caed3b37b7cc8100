// The accuracy benchmark loop (accuracy_bench.h): per scene, build the ground truth, sample the
// views, run every method on each view and score it against the rays and the exact oracle.
#include <lintel/reference/accuracy_bench.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lintel {

double percentile_ms(std::vector<double> times, double q) {
  if (times.empty()) return 0.0;
  std::sort(times.begin(), times.end());
  const size_t k = std::min(times.size() - 1, size_t(std::ceil(q * double(times.size()))) - (q > 0.0 ? 1 : 0));
  return times[k];
}

double median_ms(std::vector<double> times) { return percentile_ms(std::move(times), 0.5); }

double MethodScore::median_over_inclusion() const { return median_ms(view_over_inclusion); }

namespace {

double area_of(const MethodResult& r) {
  double a = 0.0;
  for (size_t c = 0; c < r.cell_region_area.size(); ++c) {
    if (!r.cell_visible[c]) continue;
    if (r.cell_region_area[c] < 0.0) return -1.0;
    a += r.cell_region_area[c];
  }
  return a;
}

constexpr size_t kMaxFalseNegativeExamples = 8;

// Whether every judged ray whose pixel centre lies in the NDC rect of `box`'s projected corners
// hits something nearer (view depth) than the box's nearest corner (MethodScore::ideal_box_occluded).
// Rim rays and rays that escaped or were blocked count as seeing through (infinite depth).
bool ideal_box_occluded(const GroundTruth& gt, const View& view, const Aabb& box) {
  if (box.empty()) return false;
  const glm::dvec3 eye(view.eye_world), fwd = glm::normalize(glm::dvec3(view.target_world) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::dvec3(view.up_world))), up = glm::cross(right, fwd);
  const double ty = std::tan(glm::radians(double(view.fov_y_deg)) * 0.5), tx = ty * double(view.aspect);
  double zmin = std::numeric_limits<double>::infinity();
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 c((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                       (k & 4) ? box.max.z : box.min.z);
    const glm::dvec3 d = c - eye;
    const double z = glm::dot(d, fwd);
    if (!(z > double(view.near_m))) return false;
    zmin = std::min(zmin, z);
    const glm::dvec2 p(glm::dot(d, right) / (z * tx), glm::dot(d, up) / (z * ty));
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  const uint32_t r = gt.resolution;
  for (uint32_t j = 0; j < r; ++j)
    for (uint32_t i = 0; i < r; ++i) {
      const glm::vec2 p = pixel_center_ndc(i, j, r);
      if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) continue;
      if (!(double(gt.pixels[size_t(j) * r + i].depth) < zmin)) return false;
    }
  return true;
}

std::string describe(const BenchView& v, size_t index, const char* what, size_t which) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "view %zu (%s, start cell %u, eye %.9g,%.9g,%.9g, target %.9g,%.9g,%.9g): %s %zu",
                index, v.kind.c_str(), v.start_cell, double(v.view.eye_world.x), double(v.view.eye_world.y),
                double(v.view.eye_world.z), double(v.view.target_world.x), double(v.view.target_world.y),
                double(v.view.target_world.z), what, which);
  return buf;
}

void score_view(const GroundTruth& gt, const std::vector<uint32_t>& cell_rays,
                const std::vector<uint32_t>& instance_rays, const MethodResult& r, double exact_area, double time_ms,
                const BenchView& v, size_t view_index, const World& world, MethodScore& s) {
  ++s.views;
  uint64_t fn = 0;
  auto note = [&](const char* what, size_t which, uint32_t rays) {
    if (s.false_negative_examples.size() >= kMaxFalseNegativeExamples) return;
    s.false_negative_examples.push_back(describe(v, view_index, what, which) + " (" + std::to_string(rays) + " rays)");
  };
  for (size_t c = 0; c < gt.cell_visible.size(); ++c) {
    if (gt.cell_visible[c]) {
      ++s.true_cells;
      if (!r.cell_visible[c]) {
        ++s.cell_false_negatives, ++fn, note("cell", c, cell_rays[c]);
        if (cell_rays[c] <= kFewRays) ++s.cell_false_negatives_few_rays;
      }
    }
    if (r.cell_visible[c]) ++s.drawn_cells;
  }
  for (size_t i = 0; i < gt.instance_visible.size(); ++i) {
    if (gt.instance_visible[i]) {
      ++s.true_instances;
      if (!r.instance_visible[i]) {
        ++s.instance_false_negatives, ++fn, note("instance", i, instance_rays[i]);
        if (instance_rays[i] <= kFewRays) ++s.instance_false_negatives_few_rays;
      }
    }
    if (r.instance_visible[i]) ++s.drawn_instances;
    if (r.instance_visible[i] && !gt.instance_visible[i] &&
        ideal_box_occluded(gt, v.view, world.instances[i].bounds_world))
      ++s.ideal_box_occluded;
  }
  if (fn) ++s.views_with_false_negatives;
  uint64_t drawn = 0, truly = 0;
  for (size_t i = 0; i < gt.instance_visible.size(); ++i) {
    truly += gt.instance_visible[i];
    drawn += r.instance_visible[i];
  }
  if (truly) s.view_over_inclusion.push_back(double(drawn) / double(truly));
  for (size_t c = 0; c < gt.past_rim_cell_visible.size(); ++c)
    if (gt.past_rim_cell_visible[c] && !r.cell_visible[c]) ++s.cell_past_rim_culled;
  for (size_t i = 0; i < gt.past_rim_instance_visible.size(); ++i)
    if (gt.past_rim_instance_visible[i] && !r.instance_visible[i]) ++s.instance_past_rim_culled;
  s.rays += gt.pixels.size();
  s.rim_rays += gt.rim_pixels;
  const double a = area_of(r);
  if (a >= 0.0 && exact_area >= 0.0) {
    s.region_area += a;
    s.exact_region_area += exact_area;
  }
  s.pops += r.pops;
  s.max_pops = std::max(s.max_pops, r.pops);
  if (r.bound_hit) ++s.bound_hits;
  s.times_ms.push_back(time_ms);
}

}  // namespace

Status score_scene(const AccuracyScene& scene, const RayGroundTruth& rays, const std::vector<BenchView>& views,
                   std::vector<std::unique_ptr<CullMethod>>& methods, uint32_t resolution,
                   std::vector<MethodScore>& out, const std::function<void(size_t)>& progress) {
  const size_t first = out.size();
  int exact_index = -1;
  for (size_t m = 0; m < methods.size(); ++m) {
    MethodScore s;
    s.scene = scene.label;
    s.method = methods[m]->name();
    s.settings = methods[m]->settings();
    s.claims_conservative = methods[m]->claims_conservative();
    s.cells = uint32_t(scene.world.cells.size());
    s.instances = uint32_t(scene.world.instances.size());
    out.push_back(std::move(s));
    if (exact_index < 0 && methods[m]->name() == "exact") exact_index = int(m);
  }
  GroundTruth gt;
  std::vector<MethodResult> results(methods.size());
  std::vector<double> times(methods.size(), 0.0);
  std::vector<uint32_t> cell_rays, instance_rays;
  for (size_t vi = 0; vi < views.size(); ++vi) {
    if (progress) progress(vi);
    const BenchView& bv = views[vi];
    rays.cast(ray_camera_of(bv.view), resolution, gt);
    cell_rays.assign(scene.world.cells.size(), 0);
    instance_rays.assign(scene.world.instances.size(), 0);
    for (const RayHitId& h : gt.pixels) {
      if (h.cell != RayHitId::kNone) ++cell_rays[h.cell];
      if (h.instance != RayHitId::kNone) ++instance_rays[h.instance];
    }
    for (size_t m = 0; m < methods.size(); ++m) {
      if (const Status w = methods[m]->warm_up(scene.world, bv.view, bv.start_cell); !w)  // off the clock
        return Status::error(scene.label + ": view " + std::to_string(vi) + ": " + methods[m]->name() + " " +
                             methods[m]->settings() + ": " + w.message());
      results[m].reset(scene.world);  // the benchmark's bookkeeping: off the clock
      const auto a = std::chrono::steady_clock::now();
      const Status s = methods[m]->find_visible(scene.world, bv.view, bv.start_cell, results[m]);
      times[m] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
      if (!s)
        return Status::error(scene.label + ": view " + std::to_string(vi) + ": " + methods[m]->name() + " " +
                             methods[m]->settings() + ": " + s.message());
      methods[m]->measure(results[m]);  // scoring data (areas, bounds): off the clock
    }
    const MethodResult* exact = exact_index >= 0 ? &results[size_t(exact_index)] : nullptr;
    const double exact_area = exact ? area_of(*exact) : -1.0;
    for (size_t m = 0; m < methods.size(); ++m) {
      MethodScore& sc = out[first + m];
      score_view(gt, cell_rays, instance_rays, results[m], exact_area, times[m], bv, vi, scene.world, sc);
      if (!exact) continue;
      for (size_t c = 0; c < results[m].cell_bounds.size(); ++c) {
        if (!exact->cell_visible[c] || !results[m].cell_visible[c]) continue;
        const glm::dvec4 d = glm::abs(results[m].cell_bounds[c] - exact->cell_bounds[c]);
        const double drift = std::max(std::max(d.x, d.y), std::max(d.z, d.w));
        if (std::isfinite(drift)) sc.max_bounds_drift = std::max(sc.max_bounds_drift, drift);
      }
    }
  }
  return {};
}

Status run_accuracy_bench(const std::vector<AccuracyScene>& scenes, const MethodFactory& factory,
                          const AccuracyBenchOptions& options, AccuracyBenchResult& out) {
  const auto t0 = std::chrono::steady_clock::now();
  out.scores.clear();
  for (size_t si = 0; si < scenes.size(); ++si) {
    const AccuracyScene& scene = scenes[si];
    RayGroundTruth rays;
    if (Status s = rays.build(scene.world); !s) return Status::error(scene.label + ": " + s.message());
    const std::vector<BenchView> views =
        make_bench_views(scene.world, rays, options.views_per_scene, options.seed * 1000003ull + si);
    std::vector<std::unique_ptr<CullMethod>> methods = factory();
    auto progress = [&](size_t vi) {
      if (options.progress && (vi % 20 == 0 || vi + 1 == views.size()))
        std::fprintf(stderr, "[scene %zu/%zu] %s: view %zu/%zu\n", si + 1, scenes.size(), scene.label.c_str(), vi + 1,
                     views.size());
    };
    if (Status s = score_scene(scene, rays, views, methods, options.resolution, out.scores, progress); !s) return s;
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {};
}

std::vector<MethodScore> merge_scores(const std::vector<MethodScore>& scores) {
  std::vector<MethodScore> merged;
  for (const MethodScore& s : scores) {
    auto it = std::find_if(merged.begin(), merged.end(),
                           [&](const MethodScore& m) { return m.method == s.method && m.settings == s.settings; });
    if (it == merged.end()) {
      MethodScore m = s;
      m.scene = "all";
      for (std::string& e : m.false_negative_examples) e = s.scene + ": " + e;
      merged.push_back(std::move(m));
      continue;
    }
    it->cells = std::max(it->cells, s.cells);
    it->instances = std::max(it->instances, s.instances);
    it->views += s.views;
    it->cell_false_negatives += s.cell_false_negatives;
    it->instance_false_negatives += s.instance_false_negatives;
    it->views_with_false_negatives += s.views_with_false_negatives;
    it->cell_false_negatives_few_rays += s.cell_false_negatives_few_rays;
    it->instance_false_negatives_few_rays += s.instance_false_negatives_few_rays;
    it->cell_past_rim_culled += s.cell_past_rim_culled;
    it->instance_past_rim_culled += s.instance_past_rim_culled;
    it->rays += s.rays;
    it->rim_rays += s.rim_rays;
    it->drawn_instances += s.drawn_instances;
    it->ideal_box_occluded += s.ideal_box_occluded;
    it->true_instances += s.true_instances;
    it->drawn_cells += s.drawn_cells;
    it->true_cells += s.true_cells;
    it->region_area += s.region_area;
    it->exact_region_area += s.exact_region_area;
    it->pops += s.pops;
    it->max_pops = std::max(it->max_pops, s.max_pops);
    it->bound_hits += s.bound_hits;
    it->max_bounds_drift = std::max(it->max_bounds_drift, s.max_bounds_drift);
    for (const std::string& e : s.false_negative_examples)
      if (it->false_negative_examples.size() < kMaxFalseNegativeExamples)
        it->false_negative_examples.push_back(s.scene + ": " + e);
    it->times_ms.insert(it->times_ms.end(), s.times_ms.begin(), s.times_ms.end());
    it->view_over_inclusion.insert(it->view_over_inclusion.end(), s.view_over_inclusion.begin(),
                                   s.view_over_inclusion.end());
  }
  return merged;
}

}  // namespace lintel
