// The stability suite (stability_suite.h): generated worlds and camera placements where portal
// methods are known to fail (docs/accuracy.md, "Where methods fail"; LESSONS.md).
#include <lintel/reference/stability_suite.h>
#include <lintel/file_commit.h>

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace lintel {
namespace {

struct Case {
  std::string label, note;
  AccuracyScene scene;
  // Eye placement at portals: offset from the plane (m, on `from`'s side) and the view direction
  // relative to the portal frame; or none (use the benchmark's own views).
  enum class Kind { BenchViews, PortalOffset, PastPlane, Grazing, FacingNear, Straddle, Aimed } kind = Kind::BenchViews;
  double param = 0.0;
};

// A view from `eye` whose ray through the centre of pixel (i, j) of an R x R ground-truth grid
// points exactly at `at` (fixed-point iteration on the view direction; converges in a few steps
// for pixels inside the frustum). A portal smaller than a pixel is then still crossed by a ray.
View aimed_view(const glm::dvec3& eye, const glm::dvec3& at, uint32_t i, uint32_t j, uint32_t resolution) {
  const glm::vec2 ndc = pixel_center_ndc(i, j, resolution);
  const glm::dvec3 w = glm::normalize(at - eye);
  View v = view_along(eye, w);
  const double tan_half = std::tan(glm::radians(double(v.fov_y_deg)) * 0.5);
  glm::dvec3 f = w;
  for (int iter = 0; iter < 8; ++iter) {
    const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(v.up_world))), u = glm::cross(r, f);
    const glm::dvec3 ray = f + double(ndc.x) * tan_half * double(v.aspect) * r + double(ndc.y) * tan_half * u;
    f = glm::normalize(f + (w * glm::length(ray) - ray));  // turn the pixel's ray onto w
  }
  v.target_world = glm::vec3(eye + f);
  return v;
}

// FNV-1a of the label: a seed that stays put when cases are added or reordered.
uint64_t label_seed(const std::string& label) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : label) h = (h ^ ch) * 1099511628211ull;
  return h;
}

// A unit vector in the portal's plane.
glm::dvec3 tangent_of(const Portal& p) {
  const glm::dvec3 n(p.normal_world);
  const glm::dvec3 a = std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  return glm::normalize(glm::cross(n, a));
}

std::vector<BenchView> portal_views(const Case& c, const RayGroundTruth& rays, uint32_t count, uint32_t resolution) {
  std::vector<BenchView> views;
  const World& w = c.scene.world;
  const double clearance = view_clearance_m(View{});
  for (uint32_t k = 0; views.size() < count && k < 50 * count && !w.portals.empty(); ++k) {
    const Portal& p = w.portals[k % w.portals.size()];
    const glm::dvec3 n(p.normal_world), t = tangent_of(p), b = glm::cross(n, t);
    const double angle = 0.7 * double(k);  // spreads directions deterministically
    glm::dvec3 eye(p.centroid_world), dir;
    switch (c.kind) {
      case Case::Kind::PortalOffset:  // on `from`'s side, looking through the portal at random tilts
        eye -= c.param * n;
        dir = n + 0.8 * std::cos(angle) * t + 0.5 * std::sin(angle) * b;
        break;
      case Case::Kind::PastPlane:  // `param` m past the plane on `to`'s side, start cell still `from`
        eye += c.param * n;        // (a tracker that has not seen the crossing yet)
        dir = n + 0.8 * std::cos(angle) * t + 0.5 * std::sin(angle) * b;
        break;
      case Case::Kind::Aimed:  // set below
        break;
      case Case::Kind::Grazing:  // set below
        break;
      case Case::Kind::Straddle:  // `param` m in front, looking sideways: the portal straddles w = 0
        eye -= c.param * n;
        dir = std::cos(angle) * t + std::sin(angle) * b + 0.3 * n;
        break;
      case Case::Kind::FacingNear:  // portal nearly parallel to the near plane, `param` m ahead
        eye -= c.param * n;
        dir = n + 1e-4 * std::cos(angle) * t;
        break;
      case Case::Kind::BenchViews:
        break;
    }
    if (c.kind == Case::Kind::Grazing) {
      // Half a meter in front of the portal, looking parallel to its plane (tilted by `param` rad
      // towards it): the portal is seen almost edge-on.
      eye = glm::dvec3(p.centroid_world) - 0.5 * n;
      dir = (glm::dvec3(p.centroid_world) + 0.4 * std::cos(angle) * t + 0.4 * std::sin(angle) * b - eye);
      dir = glm::normalize(dir - glm::dot(dir, n) * n) + c.param * n;
    }
    if (c.kind == Case::Kind::Aimed) {
      // On the portal's axis 0.12..0.5 m before it, one pixel (anywhere in the middle half of the
      // screen) aimed at its centre: a portal smaller than a pixel is still seen through.
      eye = glm::dvec3(p.centroid_world) - (0.12 + 0.38 * (0.5 + 0.5 * std::sin(1.3 * angle))) * n;
      if (!eye_clear_of_surfaces(rays, eye, clearance)) continue;
      const uint32_t i = resolution / 4 + (k * 37) % (resolution / 2),
                     jj = resolution / 4 + (k * 53) % (resolution / 2);
      const View v = aimed_view(eye, glm::dvec3(p.centroid_world), i, jj, resolution);
      if (!validate_view(v)) continue;
      views.push_back({v, p.from, "portal"});
      continue;
    }
    if (!eye_clear_of_surfaces(rays, eye, clearance)) continue;
    const View v = view_along(eye, dir);
    if (!validate_view(v)) continue;
    views.push_back({v, p.from, "portal"});
  }
  return views;
}

Status make_cases(std::vector<Case>& cases) {
  auto add_world = [&](std::string label, std::string note, const SceneDesc& desc, Case::Kind kind,
                       double param) -> Status {
    Case c;
    c.label = std::move(label);
    c.note = std::move(note);
    c.kind = kind;
    c.param = param;
    c.scene.label = c.label;
    if (Status s = build_world(desc, c.label, c.scene.world); !s) return s;
    cases.push_back(std::move(c));
    return {};
  };
  GridOptions jittered;
  jittered.width = jittered.height = 3;
  jittered.jitter = true;
  const SceneDesc grid = generate_grid(jittered);
  for (double off : {0.0, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
    char label[64];
    std::snprintf(label, sizeof label, "eye %.0e m off portal", off);
    if (Status s = add_world(off == 0.0 ? "eye on portal plane" : label,
                             "jittered 3x3 grid, eye at each portal's centre on its from side, looking through", grid,
                             Case::Kind::PortalOffset, off);
        !s)
      return s;
  }
  for (double off : {1e-7, 1e-4, 1e-2}) {
    char label[64];
    std::snprintf(label, sizeof label, "eye %.0e m past portal", off);
    if (Status s = add_world(label,
                             "jittered 3x3 grid, eye this far past each portal's centre on its to side, start cell "
                             "still from (a tracker one frame late), looking on",
                             grid, Case::Kind::PastPlane, off);
        !s)
      return s;
  }
  for (double size : {1e-3, 1e-2}) {
    GridOptions tiny = jittered;
    tiny.door_width_m = tiny.door_height_m = size;
    tiny.door_sill_m = 1.2;
    char label[64];
    std::snprintf(label, sizeof label, "portals %g mm", size * 1e3);
    if (Status s = add_world(label,
                             "jittered 3x3 grid whose openings are square windows this wide at 1.2 m, eye 0.12..0.5 m "
                             "before one on its axis, a pixel aimed through it",
                             generate_grid(tiny), Case::Kind::Aimed, 0);
        !s)
      return s;
  }
  for (double eps : {1e-2, 1e-4, 1e-6})
    if (Status s =
            add_world("grazing " + std::to_string(eps).substr(0, 8),
                      "jittered 3x3 grid, view within eps rad of a portal plane", grid, Case::Kind::Grazing, eps);
        !s)
      return s;
  for (double d : {1e-3, 0.03, 0.049, 0.051})
    if (Status s = add_world("portal at " + std::to_string(d).substr(0, 5) + " m, parallel to near",
                             "jittered 3x3 grid, looking straight through a portal this far ahead (near = 0.05 m)",
                             grid, Case::Kind::FacingNear, d);
        !s)
      return s;
  for (double d : {0.1, 0.3})
    if (Status s = add_world("portal straddling the eye plane, " + std::to_string(d).substr(0, 3) + " m",
                             "jittered 3x3 grid, eye this far in front of a portal looking past it: part of the "
                             "portal lies behind the eye (divide-before-clip flips it)",
                             grid, Case::Kind::Straddle, d);
        !s)
      return s;
  RandomOptions huge;
  huge.cells = 12;
  huge.seed = 5;
  huge.max_global_offset_m = 1e5;
  huge.max_offset_m = 1e5;
  if (Status s = add_world("huge coordinates", "random 12 cells, building and cell frames up to 1e5 m from the origin",
                           generate_random(huge), Case::Kind::BenchViews, 0);
      !s)
    return s;
  RandomOptions scales;
  scales.cells = 12;
  scales.seed = 6;
  scales.min_scale = 0.01;
  scales.max_scale = 100.0;
  if (Status s = add_world("non-uniform scales", "random 12 cells, cell frame scales 0.01..100 per axis",
                           generate_random(scales), Case::Kind::BenchViews, 0);
      !s)
    return s;
  GridOptions chain;
  chain.width = 64;
  chain.height = 1;
  if (Status s = add_world("chain of 64", "64 rooms in a row", generate_grid(chain), Case::Kind::BenchViews, 0); !s)
    return s;
  for (uint32_t n : {2u, 4u, 8u, 16u, 32u, 64u, 128u, 256u}) {
    RingOptions ring;
    ring.cells = n;
    if (Status s = add_world("ring of " + std::to_string(n), "rooms in a loop", generate_ring(ring),
                             Case::Kind::BenchViews, 0);
        !s)
      return s;
  }
  return {};
}

}  // namespace

Status run_stability_suite(const MethodFactory& factory, const StabilityOptions& options, StabilityResult& out) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Case> cases;
  if (Status s = make_cases(cases); !s) return s;
  out.scores.clear();
  out.case_notes.clear();
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const Case& c = cases[ci];
    RayGroundTruth rays;
    if (Status s = rays.build(c.scene.world); !s) return Status::error(c.label + ": " + s.message());
    // Views seeded by the case's label, so that adding a case does not change the others' views.
    const std::vector<BenchView> views =
        c.kind == Case::Kind::BenchViews
            ? make_bench_views(c.scene.world, rays, options.views_per_case, 17 + label_seed(c.label))
            : portal_views(c, rays, options.views_per_case, options.resolution);
    if (options.progress)
      std::fprintf(stderr, "[case %zu/%zu] %s: %zu views\n", ci + 1, cases.size(), c.label.c_str(), views.size());
    out.case_notes.push_back(c.label + ": " + c.note + " (" + std::to_string(views.size()) + " views)");
    std::vector<std::unique_ptr<CullMethod>> methods = factory();
    if (Status s = score_scene(c.scene, rays, views, methods, options.resolution, out.scores); !s) return s;
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {};
}

Status write_stability_outputs(const StabilityResult& result, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Status::error(dir + ": cannot create the output folder (" + ec.message() + ")");
  std::ostringstream md;  // both files committed at the end (file_commit.h)
  // "seen cells / view": cells the judged rays saw, per view (1 = the start cell only; more means
  // the case really looks through portals). "rim rays": share of rays within the scene's float
  // error of a portal edge, not judged; "past rim": cells / instances only those saw that the
  // method culls (ray_ground_truth.h).
  md << "| case | method | views | seen cells / view | rim rays | within bound | cell FN (≤3 rays) "
        "| instance FN (≤3 rays) | past rim | max bounds drift (NDC) | max pops | median ms |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::ostringstream js;
  js << "{\n  \"wall_s\": " << result.wall_s << ",\n  \"rows\": [\n";
  for (size_t i = 0; i < result.scores.size(); ++i) {
    const MethodScore& s = result.scores[i];
    const std::string method = s.settings.empty() ? s.method : s.method + " " + s.settings;
    const bool fn = s.cell_false_negatives + s.instance_false_negatives > 0;
    char drift[32];
    if (s.max_bounds_drift >= 0.0)
      std::snprintf(drift, sizeof drift, "%.2e", s.max_bounds_drift);
    else
      std::snprintf(drift, sizeof drift, "n/a");
    char seen[32], rim[32];
    std::snprintf(seen, sizeof seen, "%.2f", s.views ? double(s.true_cells) / s.views : 0.0);
    std::snprintf(rim, sizeof rim, "%.2f%%", 100.0 * s.rim_ray_fraction());
    md << "| " << s.scene << " | " << method << " | " << s.views << " | " << seen << " | " << rim << " | "
       << (s.bound_hits ? "**no (" + std::to_string(s.bound_hits) + " views)**" : std::string("yes")) << " | "
       << (fn ? "**" : "") << s.cell_false_negatives << (fn ? "**" : "") << " (" << s.cell_false_negatives_few_rays
       << ") | " << (fn ? "**" : "") << s.instance_false_negatives << (fn ? "**" : "") << " ("
       << s.instance_false_negatives_few_rays << ") | " << s.cell_past_rim_culled << "/" << s.instance_past_rim_culled
       << " | " << drift << " | " << s.max_pops << " | " << median_ms(s.times_ms) << " |\n";
    js << "    {\"case\": \"" << s.scene << "\", \"method\": \"" << s.method << "\", \"settings\": \"" << s.settings
       << "\", \"views\": " << s.views << ", \"true_cells\": " << s.true_cells
       << ", \"rim_ray_fraction\": " << s.rim_ray_fraction() << ", \"bound_hits\": " << s.bound_hits
       << ", \"cell_false_negatives\": " << s.cell_false_negatives
       << ", \"instance_false_negatives\": " << s.instance_false_negatives
       << ", \"cell_past_rim_culled\": " << s.cell_past_rim_culled
       << ", \"instance_past_rim_culled\": " << s.instance_past_rim_culled
       << ", \"max_bounds_drift\": " << s.max_bounds_drift << ", \"max_pops\": " << s.max_pops
       << ", \"median_ms\": " << median_ms(s.times_ms) << ", \"false_negative_examples\": [";
    for (size_t k = 0; k < s.false_negative_examples.size(); ++k)
      js << (k ? ", " : "") << '"' << s.false_negative_examples[k] << '"';
    js << "]}" << (i + 1 == result.scores.size() ? "\n" : ",\n");
  }
  md << "\nCases:\n\n";
  for (const std::string& n : result.case_notes) md << "- " << n << "\n";
  js << "  ]\n}\n";
  const std::string md_text = md.str(), js_text = js.str();
  return commit_files({{dir + "/stability.md", reinterpret_cast<const uint8_t*>(md_text.data()), md_text.size()},
                       {dir + "/stability.json", reinterpret_cast<const uint8_t*>(js_text.data()), js_text.size()}});
}

}  // namespace lintel
