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
  // With RenderOptions::gi_persist: iterations of a frame that builds on warm probes (0 = every
  // frame runs `bounces`). A frame runs the full `bounces` when the probes are cold: the first
  // frame, after a door change reset them, or when a cell becomes active that was not the frame
  // before (its probes are stale); otherwise this many, and the iterations accumulate across
  // frames towards the same fixed point (docs/rendering.md, "GI amortised over frames").
  uint32_t amortized_bounces = 0;
  uint64_t seed = 1;
};

}  // namespace lintel::render
