// Where the diffuse GI lives (docs/rendering.md, "Global illumination"): per cell, a small grid
// of SH-L1 radiance probes over the box of the cell's volume as it lies in the world (so the cell's frame
// cannot change it), and surfels — points on the
// cell's own shell and instances, plus points on its portals. Probes gather only their own cell's
// surfels; light crosses between cells only through portal surfels, which emit what the
// neighbour's probes see. There is no other path between cells, so a sealed room receives
// exactly zero from its neighbour.
#pragma once

#include "render_scene.h"

#include <lintel/render/gi_options.h>
#include <lintel/render/render_shared.h>

#include <cstdint>
#include <vector>

namespace lintel::render {

struct GiLayout {
  std::vector<GpuSurfel> surfels;    // grouped by cell: surfaces, then portal surfels
  std::vector<GpuCellProbes> cells;  // per cell
  std::vector<GpuProbe> probes;      // positions, cells and visibility offsets; sh zero
  // Per probe, from GpuProbe::visibility.x on: one bit per surfel of its cell (surfaces, then
  // portals; 128 to a texel), set when nothing of the cell lies between the probe and the surfel.
  std::vector<glm::uvec4> probe_visibility;
};

// `probe_visibility` false (a renderer without GI, whose probes nothing reads): no occluders, so
// each probe sees every surfel facing it, without the BVH casts that are most of a large level's
// GI set-up.
GiLayout build_gi_layout(const RenderScene& scene, const GiOptions& options, bool probe_visibility = true);

}  // namespace lintel::render
