// Shared by `lintel bench render` (cmd_bench_render.cpp) and its quality part
// (bench_render_quality.cpp, built only with the test-only path tracer).
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/render/renderer.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lintel::cli {

struct BenchView {
  View view;
  uint32_t cell = 0;  // tracked along the timeline, as a game would
};

double median_of(std::vector<double> v);

// `count` views spread evenly over the world's doorway timeline (else its first).
Status timeline_views(const World& world, uint32_t count, std::vector<BenchView>& out);

struct QualityArgs {
  uint32_t ref_spp = 256;
  uint32_t ref_bounces = 4;   // the path tracer's diffuse bounces
  bool default_only = false;  // only the default GI setting
};

// Path-traces references of up to 3 of `views` and renders them with a sweep of GI settings;
// writes DIR/quality_vs_cost.{csv,dat,gp,png,svg}, DIR/quality_images.png (a row per setting,
// the reference on top, the default's FLIP error map at the bottom) and fills `out`.
Status bench_render_quality(const World& world, const std::vector<BenchView>& views, gpu::Context& ctx,
                            const render::RenderOptions& base, const QualityArgs& args, const std::string& dir,
                            nlohmann::json& out);

}  // namespace lintel::cli
