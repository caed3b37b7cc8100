// Quality against cost of the realtime GI: each setting's image error (RMSE of linear radiance,
// and FLIP of the tonemapped images, a perceptual difference) against a path-traced reference of
// the same views, plotted against its frame time. The path
// tracer (pathtrace/) follows the renderer's light and material conventions exactly, so the error
// is what the approximations cost: probes instead of rays, L1 SH, no visibility inside a cell,
// a bounded number of bounces, shadow-map resolution, GTAO.
#include "bench_render.h"
#include "cli_common.h"

#include <lintel/reference/chart_plot.h>
#include <lintel/file_commit.h>
#include <lintel/reference/image_flip.h>
#include <lintel/reference/path_tracer.h>
#include <lintel/render/image_io.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace lintel::cli {
namespace {

struct GiSetting {
  std::string label;
  bool gi = true, ao = true;
  uint32_t bounces = 2;
  float spacing = 1.5f;
  uint32_t surfels = 384;
};

const std::vector<GiSetting>& settings() {
  static const std::vector<GiSetting> s = {
      {"direct only", false, false, 1, 1.5f, 384},
      {"1 bounce", true, true, 1, 1.5f, 384},
      {"2 bounces", true, true, 2, 1.5f, 384},
      {"4 bounces", true, true, 4, 1.5f, 384},
      {"default (8 bounces)", true, true, 8, 1.5f, 384},
      {"default, no AO", true, false, 8, 1.5f, 384},
      {"16 bounces", true, true, 16, 1.5f, 384},
      {"coarse (3 m, 128 surfels)", true, true, 8, 3.0f, 128},
      {"fine (0.75 m, 1024), 4 bounces", true, true, 4, 0.75f, 1024},
      {"fine (0.75 m, 1024), 8 bounces", true, true, 8, 0.75f, 1024},
  };
  return s;
}

const char* const kDefaultSetting = "default (8 bounces)";

render::Rgba8Image to_rgba8(const std::vector<glm::vec3>& srgb, uint32_t w, uint32_t h) {
  render::Rgba8Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 255)};
  for (size_t p = 0; p < srgb.size(); ++p)
    for (int c = 0; c < 3; ++c)
      img.pixels[4 * p + size_t(c)] = uint8_t(std::clamp(srgb[p][c], 0.0f, 1.0f) * 255.0f + 0.5f);
  return img;
}

// FLIP error 0 .. 1 as black -> red -> yellow -> white, so where the error sits reads at a glance.
render::Rgba8Image heat(const std::vector<float>& error, uint32_t w, uint32_t h) {
  std::vector<glm::vec3> rgb(error.size());
  for (size_t p = 0; p < error.size(); ++p) {
    const float e = std::clamp(error[p], 0.0f, 1.0f) * 3.0f;
    rgb[p] = glm::clamp(glm::vec3(e, e - 1.0f, e - 2.0f), 0.0f, 1.0f);
  }
  return to_rgba8(rgb, w, h);
}

}  // namespace

Status bench_render_quality(const World& world, const std::vector<BenchView>& views, gpu::Context& ctx,
                            const render::RenderOptions& base, const QualityArgs& args, const std::string& dir,
                            nlohmann::json& out) {
  const uint32_t ref_spp = args.ref_spp;
  const uint32_t w = 160, h = 90;
  std::vector<BenchView> picked;
  for (size_t k = 0; k < 3 && !views.empty(); ++k)
    picked.push_back(views[std::min(views.size() - 1, (2 * k + 1) * views.size() / 6)]);

  PathTracer tracer;
  if (Status s = tracer.build(world); !s) return s;
  std::vector<LinearImage> refs(picked.size());
  for (size_t i = 0; i < picked.size(); ++i) {
    std::fprintf(stderr, "  path-traced reference %zu of %zu (%ux%u, %u spp)...\n", i + 1, picked.size(), w, h,
                 ref_spp);
    PathTraceOptions o;
    o.width = w;
    o.height = h;
    o.samples_per_pixel = ref_spp;
    o.max_bounces = args.ref_bounces;
    View v = picked[i].view;
    v.aspect = float(w) / float(h);
    tracer.render(v, o, refs[i]);
  }
  // FLIP compares what a viewer sees: both images through the renderer's tonemap curve with one
  // exposure per view, the reference's (its log-average to middle grey), so a darker or brighter
  // realtime image counts as a difference, as it does in the RMSE.
  std::vector<float> ref_exposure(refs.size());
  std::vector<std::vector<glm::vec3>> ref_ldr(refs.size());
  for (size_t i = 0; i < refs.size(); ++i) {
    ref_exposure[i] = key_exposure(refs[i].rgb);
    ref_ldr[i] = tonemap_for_flip(refs[i].rgb, ref_exposure[i]);
  }
  // The picture of the run: one row per image kind, one column per view.
  std::vector<render::Rgba8Image> sheet, default_error;
  for (size_t i = 0; i < refs.size(); ++i) sheet.push_back(to_rgba8(ref_ldr[i], w, h));

  // GPUs idle at low clocks: render a while before timing anything.
  {
    std::unique_ptr<render::Renderer> warm;
    if (Status s = render::Renderer::create(ctx, world, base, warm); !s) return s;
    render::RenderedFrame f;
    for (int k = 0; k < 20; ++k) {
      View v = picked[size_t(k) % picked.size()].view;
      v.aspect = float(base.width) / float(base.height);
      if (Status s = warm->render(v, picked[size_t(k) % picked.size()].cell, f); !s) return s;
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  std::ostringstream csv, dat;  // written through commit_file once complete
  csv << "setting,gi,ao,bounces,probe_spacing_m,surfels_per_cell,rmse,flip,mean_ratio,median_gpu_ms,median_gi_gpu_ms\n";
  for (const GiSetting& g : settings()) {
    if (args.default_only && g.label != kDefaultSetting) continue;
    std::fprintf(stderr, "  GI setting: %s\n", g.label.c_str());
    render::RenderOptions small = base;
    small.width = w;
    small.height = h;
    small.gi = g.gi;
    small.ao = g.ao;
    small.gi_options.bounces = g.bounces;
    small.gi_options.probe_spacing_m = g.spacing;
    small.gi_options.surfels_per_cell = g.surfels;
    small.readback_hdr = true;
    small.view = render::kViewFinal;
    std::unique_ptr<render::Renderer> r;
    if (Status s = render::Renderer::create(ctx, world, small, r); !s) return s;
    double sq = 0.0, sum_rt = 0.0, sum_ref = 0.0, sum_flip = 0.0;
    std::vector<double> rmse_per_view;
    for (size_t i = 0; i < picked.size(); ++i) {
      render::RenderedFrame f;
      View v = picked[i].view;
      v.aspect = float(w) / float(h);
      if (Status s = r->render(v, picked[i].cell, f); !s) return s;
      std::vector<glm::vec3> rgb(f.hdr.size());
      for (size_t p = 0; p < rgb.size(); ++p) rgb[p] = glm::vec3(f.hdr[p]);
      const double e = render::rmse_linear(rgb, refs[i].rgb);
      sq += e * e;
      rmse_per_view.push_back(e);
      const std::vector<glm::vec3> ldr = tonemap_for_flip(rgb, ref_exposure[i]);
      std::vector<float> error_map;
      sum_flip += flip_ldr(ref_ldr[i], ldr, w, h, FlipOptions{}, &error_map);
      sheet.push_back(to_rgba8(ldr, w, h));
      if (g.label == kDefaultSetting) default_error.push_back(heat(error_map, w, h));
      for (size_t p = 0; p < rgb.size(); ++p) {
        sum_rt += double(rgb[p].r + rgb[p].g + rgb[p].b);
        sum_ref += double(refs[i].rgb[p].r + refs[i].rgb[p].g + refs[i].rgb[p].b);
      }
    }
    const double rmse = std::sqrt(sq / double(picked.size()));
    const double flip = sum_flip / double(picked.size());              // mean over the views of each view's mean FLIP
    const double mean_ratio = sum_ref > 0.0 ? sum_rt / sum_ref : 0.0;  // > 1: brighter than the reference
    // Cost at the benchmark's own resolution.
    render::RenderOptions full = small;
    full.width = base.width;
    full.height = base.height;
    full.readback_hdr = false;
    if (Status s = render::Renderer::create(ctx, world, full, r); !s) return s;
    std::vector<double> gpu, gi_gpu;
    for (const BenchView& bv : picked) {
      View v = bv.view;
      v.aspect = float(full.width) / float(full.height);
      render::RenderedFrame f;
      for (int k = 0; k < 12; ++k) {
        if (Status s = r->render(v, bv.cell, f); !s) return s;
        if (k < 2) continue;  // warm-up
        double t = 0.0, gi_t = 0.0;
        for (const render::PassTime& p : f.passes) {
          t += p.gpu_ms;
          if (p.name.rfind("gi ", 0) == 0) gi_t += p.gpu_ms;
        }
        gpu.push_back(t);
        gi_gpu.push_back(gi_t);
      }
    }
    const double ms = median_of(gpu), gi_ms = median_of(gi_gpu);
    csv << '"' << g.label << "\"," << g.gi << ',' << g.ao << ',' << g.bounces << ',' << g.spacing << ',' << g.surfels
        << ',' << rmse << ',' << flip << ',' << mean_ratio << ',' << ms << ',' << gi_ms << '\n';
    dat << '"' << g.label << "\" " << ms << ' ' << rmse << '\n';
    rows.push_back({{"setting", g.label},
                    {"gi", g.gi},
                    {"ao", g.ao},
                    {"bounces", g.bounces},
                    {"probe_spacing_m", g.spacing},
                    {"surfels_per_cell", g.surfels},
                    {"rmse", rmse},
                    {"rmse_per_view", rmse_per_view},
                    {"flip", flip},
                    {"mean_ratio", mean_ratio},
                    {"median_gpu_ms", ms},
                    {"median_gi_gpu_ms", gi_ms}});
    std::printf("  %-28s RMSE %.5f  FLIP %.4f  mean %.2fx reference  %8.3f ms GPU (GI %.3f ms) at %ux%u\n",
                g.label.c_str(), rmse, flip, mean_ratio, ms, gi_ms, full.width, full.height);
  }
  {
    std::ostringstream gp;
    gp << kChartScriptPrologue;
    for (const char* term : {"pngcairo size 1000,650", "svg size 1000,650"}) {
      const std::string ext = std::string(term).rfind("png", 0) == 0 ? "png" : "svg";
      gp << "set terminal " << term << "\nset output outdir.'quality_vs_cost." << ext << "'\n"
         << "set grid\nset xlabel 'GPU frame time (ms, " << base.width << "x" << base.height << ")'\n"
         << "set ylabel 'RMSE vs path-traced reference (linear radiance)'\n"
         << "set title 'Realtime GI settings: error against cost (cottage, " << picked.size() << " views)'\n"
         << "set offsets graph 0.05, graph 0.35, graph 0.1, graph 0.1\n"
         << "plot 'quality_vs_cost.dat' using 2:3 with points pt 7 ps 1.5 notitle, "
         << "'' using 2:3:1 with labels offset char 1,0.6 left notitle\n";
    }
    for (const auto& [name, text] :
         {std::pair{"/quality_vs_cost.csv", csv.str()}, std::pair{"/quality_vs_cost.dat", dat.str()},
          std::pair{"/quality_vs_cost.gp", gp.str()}})
      if (Status s = commit_file(dir + name, text); !s) return s;
  }
  sheet.insert(sheet.end(), default_error.begin(), default_error.end());
  if (Status s = render::write_png(dir + "/quality_images.png",
                                   render::contact_sheet(sheet, uint32_t(std::max<size_t>(1, refs.size())), w));
      !s)
    return s;
  std::vector<std::string> warnings;
  if (Status s = plot_charts(dir, "quality_vs_cost.gp", {"quality_vs_cost.png", "quality_vs_cost.svg"}, warnings); !s)
    return s;
  for (const std::string& message : warnings) warn(message);
  out = {{"reference",
          {{"width", w}, {"height", h}, {"spp", ref_spp}, {"max_bounces", args.ref_bounces}, {"views", picked.size()}}},
         {"flip",
          {{"version", "LDR-FLIP (Andersson et al. 2020)"},
           {"pixels_per_degree", FlipOptions{}.pixels_per_degree},
           {"tonemap", "reference's key exposure (0.18 / log-average), ACES fit, sRGB"}}},
         {"settings", rows}};
  std::printf("quality chart: %s/quality_vs_cost.png, images: %s/quality_images.png\n", dir.c_str(), dir.c_str());
  return {};
}

}  // namespace lintel::cli
