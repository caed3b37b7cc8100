#include "render_args.h"

#include <cstdio>
#include "cli_common.h"

namespace lintel::cli {

namespace {
const char* const kPassNames[] = {"final", "albedo", "normal", "depth", "shadow", "gi", "ao"};
}

int pass_from_name(const std::string& name) {
  for (int i = 0; i < 7; ++i)
    if (name == kPassNames[i]) return i;  // the kView* constants, in order
  return -1;
}

void add_render_options(CLI::App* cmd, RenderArgs& a, bool with_device) {
  cmd->add_option("--width", a.width, "Image width in pixels")->capture_default_str()->check(CLI::Range(1, 8192));
  cmd->add_option("--height", a.height, "Image height in pixels")->capture_default_str()->check(CLI::Range(1, 8192));
  cmd->add_option("--pass", a.pass, "What to show: final, albedo, normal, depth, shadow, gi, ao")
      ->capture_default_str();
  cmd->add_option("--cull", a.cull,
                  "The camera's draws: portal, portal+hiz (portal, then two-phase hierarchical-Z occlusion), "
                  "frustum, none")
      ->capture_default_str();
  cmd->add_flag("--no-gi", a.no_gi, "Direct light only (no probe GI)");
  cmd->add_flag("--no-ao", a.no_ao, "No GTAO on the indirect light");
  cmd->add_flag("--no-shadow-cache", a.no_shadow_cache, "Redraw every active light's shadow maps every frame");
  cmd->add_option("--exposure", a.exposure,
                  "Exposure multiplier on the automatic exposure (or absolute with --fixed-exposure)")
      ->capture_default_str()
      ->check(finite_range(1e-4, 1e4));
  cmd->add_flag("--fixed-exposure", a.fixed_exposure, "No automatic exposure: --exposure alone scales the radiance");
  cmd->add_option("--shadow-res", a.shadow_resolution, "Shadow map size per view (pixels)")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--gi-bounces", a.gi_bounces, "GI light/gather iterations per frame")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  cmd->add_option("--gi-amortize", a.gi_amortized,
                  "With probes kept between frames (walk --frames): GI iterations of a frame on warm probes; a "
                  "frame with a newly active cell or after a door change runs --gi-bounces (0: always --gi-bounces)")
      ->capture_default_str()
      ->check(CLI::Range(0, 16));
  cmd->add_option("--probe-spacing", a.probe_spacing_m, "GI probe spacing in meters")
      ->capture_default_str()
      ->check(finite_range(0.1, 100.0));
  cmd->add_option("--surfels", a.surfels_per_cell, "GI surfels per cell")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  if (!with_device) return;
  cmd->add_option("--device", a.device,
                  "Vulkan device: index or name substring (default: LINTEL_VK_DEVICE, then the first GPU)")
      ->envname("LINTEL_VK_DEVICE");
  cmd->add_flag("--validation", a.validation, "Run under the Khronos validation layers; any message is an error");
}

Status render_options_from(const RenderArgs& a, render::RenderOptions& o) {
  const int view = pass_from_name(a.pass);
  if (view < 0)
    return Status::error("--pass '" + a.pass + "': expected final, albedo, normal, depth, shadow, gi or ao");
  if (a.cull == "portal")
    o.camera_cull = render::CameraCull::Portal;
  else if (a.cull == "portal+hiz")
    o.camera_cull = render::CameraCull::PortalHiz;
  else if (a.cull == "frustum")
    o.camera_cull = render::CameraCull::Frustum;
  else if (a.cull == "none")
    o.camera_cull = render::CameraCull::None;
  else
    return Status::error("--cull '" + a.cull + "': expected portal, portal+hiz, frustum or none");
  o.width = a.width;
  o.height = a.height;
  o.view = uint32_t(view);
  o.gi = !a.no_gi;
  o.ao = !a.no_ao;
  o.cache_shadow_maps = !a.no_shadow_cache;
  o.exposure = a.exposure;
  o.auto_exposure = !a.fixed_exposure;
  o.shadow_resolution = a.shadow_resolution;
  o.gi_options.bounces = a.gi_bounces;
  o.gi_options.amortized_bounces = a.gi_amortized;
  o.gi_options.probe_spacing_m = a.probe_spacing_m;
  o.gi_options.surfels_per_cell = a.surfels_per_cell;
  return {};
}

Status open_render_session(const World& world, const RenderArgs& args, const render::RenderOptions& options,
                           RenderSession& out) {
  gpu::ContextOptions co;
  co.device = args.device;
  co.validation = args.validation;
  if (Status s = gpu::Context::create(co, out.context); !s) return s;
  if (Status s = render::Renderer::create(*out.context, world, options, out.renderer); !s) return s;
  // A documented degradation (shadow maps reduced to fit the device) is said, not hidden.
  if (!out.renderer->setup_note().empty())
    std::fprintf(stderr, "lintel: note: %s\n", out.renderer->setup_note().c_str());
  return {};
}

}  // namespace lintel::cli
