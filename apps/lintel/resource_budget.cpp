// Estimates are deliberately simple sums of the big allocations: they exist to refuse work that
// cannot fit before anything is allocated, not to predict the peak to the byte.
#include "resource_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace lintel::cli {

uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : uint64_t{1} << 32;
}

Status parse_byte_size(const std::string& text, uint64_t& out) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  double unit = 1.0;
  const std::string suffix = end ? std::string(end) : std::string();
  if (suffix == "K" || suffix == "k")
    unit = 1024.0;
  else if (suffix == "M" || suffix == "m")
    unit = 1024.0 * 1024.0;
  else if (suffix == "G" || suffix == "g")
    unit = 1024.0 * 1024.0 * 1024.0;
  else if (!suffix.empty())
    end = nullptr;
  if (end == nullptr || end == text.c_str() || !std::isfinite(v) || !(v * unit >= 1.0) || v * unit > 1e18)
    return Status::error("--max-memory: expected a positive byte count such as 1073741824, 512M or 2G, got '" + text +
                         "'");
  out = uint64_t(v * unit);
  return {};
}

std::string byte_text(uint64_t bytes) { return std::to_string(bytes) + " bytes"; }

uint64_t estimate_render_bytes(const World& world, const render::RenderOptions& o) {
  uint64_t shadow_views = 0;
  for (const Light& l : world.lights)
    shadow_views += l.type == Light::Type::Point ? 6 : l.type == Light::Type::Spot ? 1 : 2;
  const uint64_t shadow = shadow_views * uint64_t(o.shadow_resolution) * o.shadow_resolution * 4;  // D32
  uint64_t probes = 0;
  for (const Cell& c : world.cells) {
    const glm::vec3 extent =
        glm::max(c.volume_box_cell.empty() ? glm::vec3(0.0f) : c.volume_box_cell.extent(), glm::vec3(1e-3f));
    uint64_t n = 1;
    for (int a = 0; a < 3; ++a) {
      const double len = double(extent[a]) * double(glm::length(glm::vec3(c.cell_to_world[a])));
      n *= uint64_t(std::clamp(std::ceil(len / double(o.gi_options.probe_spacing_m)), 1.0,
                               double(std::max(1u, o.gi_options.max_probes_per_axis))));
    }
    probes += n;
  }
  const uint64_t surfels = uint64_t(world.cells.size()) * o.gi_options.surfels_per_cell;
  uint64_t geometry = uint64_t(world.instances.size()) * 128;
  for (const Mesh& m : world.meshes) geometry += uint64_t(m.positions.size()) * 32 + uint64_t(m.indices.size()) * 4;
  return shadow + probes * 80 + surfels * 64 + uint64_t(o.width) * o.height * 64 + geometry;
}

Status check_render_budget(const World& world, const render::RenderOptions& o, uint64_t max_memory) {
  const uint64_t surfels = uint64_t(world.cells.size()) * o.gi_options.surfels_per_cell;
  if (o.gi && surfels > kMaxRenderSurfels)
    return Status::error("render: " + std::to_string(world.cells.size()) + " cells x " +
                         std::to_string(o.gi_options.surfels_per_cell) + " surfels = " + std::to_string(surfels) +
                         " GI surfels, over the limit of " + std::to_string(kMaxRenderSurfels) +
                         " (lower --surfels or pass --no-gi)");
  const uint64_t need = estimate_render_bytes(world, o);
  if (need > max_memory)
    return Status::error("render: needs at least " + byte_text(need) +
                         " (shadow maps, GI, g-buffer, geometry), over the " + "--max-memory budget of " +
                         byte_text(max_memory));
  return {};
}

Status check_walk_budget(const World& world, size_t frames, uint64_t max_memory) {
  const uint64_t cell_frames = uint64_t(frames) * std::max<uint64_t>(1, world.cells.size());
  if (cell_frames > kMaxWalkCellFrames)
    return Status::error("walk: " + std::to_string(frames) + " frames x " + std::to_string(world.cells.size()) +
                         " cells = " + std::to_string(cell_frames) + " cell-frames, over the limit of " +
                         std::to_string(kMaxWalkCellFrames));
  const uint64_t need = uint64_t(frames) * 64;  // timing, transitions and tracker history per frame
  if (need > max_memory)
    return Status::error("walk: " + std::to_string(frames) + " frames need about " + byte_text(need) +
                         ", over the --max-memory budget of " + byte_text(max_memory));
  return {};
}

}  // namespace lintel::cli
