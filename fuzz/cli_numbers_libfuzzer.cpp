// libFuzzer target for the numbers of the `lintel` command line: the camera and traversal options
// of vis/walk/cull (visibility_args.cpp), the renderer's options (render_args.cpp) and the X,Y,Z
// parser (cli_common.cpp parse_vec3), parsed by CLI11 and validated as the commands do.
// The input is the argument list, one argument per line.
// Property: parsing never crashes or throws anything but CLI::ParseError, and what passes the
// commands' checks (CLI11 validators, parse_vec3, validate_view, validate_options,
// render_options_from) is finite and in its documented range, and yields a finite view matrix.
#include "cli_common.h"
#include "render_args.h"
#include "visibility_args.h"

#include <lintel/view.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

[[noreturn]] void broken(const std::string& why) {
  std::fprintf(stderr, "CLI number invariant broken: %s\n", why.c_str());
  std::abort();
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_vec3(const std::string& text) {
  glm::vec3 v(0.0f);
  const lintel::Status s = lintel::cli::parse_vec3(text, "--eye", v);
  if (s.ok() && !finite(v)) broken("parse_vec3 accepted '" + text + "' as a non-finite vector");
  if (!s.ok() && (s.message().find('\n') != std::string::npos || s.message().rfind("--eye: ", 0) != 0))
    broken("parse_vec3 message is not one line naming the option: " + s.message());
}

void check_view(const lintel::View& view) {
  if (!finite(view.eye_world) || !finite(view.target_world)) broken("accepted a non-finite eye/target");
  if (!(view.fov_y_deg > 0.0f && view.fov_y_deg <= 179.0f)) broken("accepted fov " + std::to_string(view.fov_y_deg));
  if (!(view.aspect > 0.0f && view.aspect <= 1e4f)) broken("accepted aspect " + std::to_string(view.aspect));
  if (!(view.near_m > 0.0f && view.near_m < view.far_m)) broken("accepted near " + std::to_string(view.near_m));
  const glm::dmat4 m = lintel::view_projection_d(view);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) broken("an accepted view has a non-finite view-projection matrix");
}

void check_render(const lintel::render::RenderOptions& o) {
  if (o.width < 1 || o.width > 8192 || o.height < 1 || o.height > 8192) broken("image size out of range");
  if (o.shadow_resolution < 16 || o.shadow_resolution > 8192) broken("shadow resolution out of range");
  if (o.gi_options.bounces < 1 || o.gi_options.bounces > 16) broken("gi bounces out of range");
  if (o.gi_options.surfels_per_cell < 1 || o.gi_options.surfels_per_cell > 65536) broken("surfels out of range");
  if (!(std::isfinite(o.exposure) && o.exposure > 0.0f)) broken("accepted exposure " + std::to_string(o.exposure));
  if (!(o.gi_options.probe_spacing_m >= 0.1f && o.gi_options.probe_spacing_m <= 100.0f))
    broken("accepted probe spacing " + std::to_string(o.gi_options.probe_spacing_m));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args;  // CLI11 wants them in reverse order
  std::string current;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(char(data[i]));
    }
  }
  args.push_back(current);
  check_vec3(args.front());

  CLI::App app("fuzz");
  lintel::cli::VisibilityArgs vis;
  lintel::cli::RenderArgs render;
  std::string eye = "0,1.6,0", target = "0,1.6,-1";
  lintel::cli::add_visibility_options(&app, vis, true);
  lintel::cli::add_render_options(&app, render, false);
  app.add_option("--eye", eye);
  app.add_option("--target", target);
  std::reverse(args.begin(), args.end());
  try {
    app.parse(args);
  } catch (const CLI::ParseError&) {
    return 0;  // main() prints it and exits 2
  }
  check_vec3(eye);
  check_vec3(target);

  lintel::View view;
  view.fov_y_deg = vis.fov_y_deg;
  view.aspect = vis.aspect;
  view.near_m = vis.near_m;
  if (lintel::cli::parse_vec3(eye, "--eye", view.eye_world).ok() &&
      lintel::cli::parse_vec3(target, "--target", view.target_world).ok() && lintel::validate_view(view).ok())
    check_view(view);
  (void)lintel::validate_options(vis.options);  // must not crash; its ranges are its own tests'

  lintel::render::RenderOptions options;
  if (lintel::cli::render_options_from(render, options).ok()) check_render(options);
  return 0;
}
