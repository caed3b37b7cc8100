// Command-line options shared by the subcommands that render (render, walk --frames, bench
// render): image size, debug pass, GI/AO switches, shadow resolution, device; and the Vulkan
// context + Renderer they make.
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/render/renderer.h>
#include <lintel/world.h>

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace lintel::cli {

struct RenderArgs {
  uint32_t width = 640, height = 360;
  std::string pass = "final";
  std::string cull = "portal";  // portal, portal+hiz, frustum, none (render::CameraCull)
  bool no_gi = false, no_ao = false, fixed_exposure = false, no_shadow_cache = false;
  float exposure = 1.0f;
  uint32_t shadow_resolution = 512;
  uint32_t gi_bounces = 8;
  uint32_t gi_amortized = 2;  // GiOptions::amortized_bounces (walk --frames keeps the probes)
  float probe_spacing_m = 1.5f;
  uint32_t surfels_per_cell = 384;
  std::string device;
  bool validation = false;
};

// `with_device`: also --device and --validation (walk has its own --device).
void add_render_options(CLI::App* cmd, RenderArgs& args, bool with_device = true);

// RenderArgs -> RenderOptions. Errors: an unknown --pass.
Status render_options_from(const RenderArgs& args, render::RenderOptions& out);

// The debug view named by --pass (final, albedo, normal, depth, shadow, gi, ao), or -1.
int pass_from_name(const std::string& name);

struct RenderSession {
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<render::Renderer> renderer;
};

Status open_render_session(const World& world, const RenderArgs& args, const render::RenderOptions& options,
                           RenderSession& out);

}  // namespace lintel::cli
