// What each light sees, found with the same portal visibility as the camera (lights do not move,
// so this runs once per scene): the cells it can light (a bitmask the lighting passes test, so a
// light never reaches a cell no portal path joins to it — exactly zero, not just shadowed) and,
// per shadow view, the shadow casters: every drawable the light's visibility query keeps. A
// caster outside the camera's view but visible to the light is in that list, so its shadow does
// not pop when it leaves the screen.
//
//   point light  -> 6 cube-face perspective views (90 degrees plus a PCF margin);
//   spot light   -> 1 perspective view over its outer cone (a spot wider than 80 degrees is
//                   treated as a point light: 6 faces);
//   directional  -> orthographic views: a fine one over the lit cells other than the light's own
//                   (when they are much smaller than the scene), then one over the whole scene;
//                   its cells are those reached from its cell through portals the light's
//                   direction passes (a flood, conservative: apertures are ignored), its casters
//                   every drawable of those cells in each view's box.
#pragma once

#include "render_scene.h"
#include <lintel/status.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::render {

struct ShadowView {
  uint32_t light = 0;
  glm::mat4 world_to_clip{1.0f};  // same clip convention as the camera (lintel/view.h)
  std::vector<uint32_t> casters;  // drawables, ascending
  // Perspective views: shadow texel size per meter of distance (2 tan(fov/2) / resolution); the
  // lighting's normal offset scales with it. 0 for orthographic views, whose texel size the
  // shader derives from the matrix.
  float texel_scale = 0.0f;
};

struct LightViews {
  std::vector<ShadowView> views;     // grouped by light, in light order
  std::vector<uint32_t> first_view;  // per light
  std::vector<uint32_t> view_count;  // per light
  std::vector<uint32_t> cell_mask;   // per light, words_per_light words: bit c = lights cell c
  uint32_t words_per_light = 0;
};

struct LightViewOptions {
  uint32_t shadow_resolution = 512;  // per face; the PCF margin of cube faces depends on it
};

// The most shadow views build_light_views gives `light` (to plan the atlas before building them).
uint32_t max_shadow_views(const Light& light);

// Errors: a light whose view the visibility core rejects (e.g. NaN position).
Status build_light_views(const RenderScene& scene, const LightViewOptions& options, LightViews& out);

}  // namespace lintel::render
