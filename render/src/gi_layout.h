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
  std::vector<GpuProbe> probes;      // positions and cells; sh zero
};

GiLayout build_gi_layout(const RenderScene& scene, const GiOptions& options);

}  // namespace lintel::render
