// The knobs of the renderer's diffuse GI (RenderOptions::gi_options): probe density, surfels per
// cell and portal, bounces. Public on its own so that renderer.h needs none of the GI layout's
// internals (render/src/gi_layout.h); docs/rendering.md, "Global illumination", says what they do.
#pragma once

#include <cstdint>

namespace lintel::render {

struct GiOptions {
  float probe_spacing_m = 1.5f;  // probes per axis = ceil(extent / spacing), 1..max_probes_per_axis
  uint32_t max_probes_per_axis = 6;
  uint32_t surfels_per_cell = 384;  // area-weighted over the cell's shell and instances
  uint32_t surfels_per_portal = 8;
  uint32_t bounces = 8;  // light/gather iterations per frame (>= 1; 1 = one bounce)
  uint64_t seed = 1;
};

}  // namespace lintel::render
