// Work and memory a command will need, checked before it allocates: --max-memory (default half
// of physical memory) against the loader's buffers, the renderer's main allocations and a walk's
// per-frame records, plus fixed caps on GI surfels and walk length (docs: README "Limits").
#pragma once

#include <lintel/render/renderer.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <cstdint>
#include <string>

namespace lintel::cli {

// GI surfels over the scene (cells x --surfels): each is 64 bytes on the GPU and lit every
// bounce of every frame; 16 M is 1 GiB and minutes per frame on a software rasterizer.
inline constexpr uint64_t kMaxRenderSurfels = uint64_t{1} << 24;
// Timeline frames x cells for `walk`: one visibility build per frame costs up to a few hundred
// nanoseconds per cell, so 1e8 cell-frames is about half a minute.
inline constexpr uint64_t kMaxWalkCellFrames = 100'000'000;

uint64_t physical_memory_bytes();
// "1073741824", "512M", "2G", "64K" (binary units). Errors name --max-memory.
Status parse_byte_size(const std::string& text, uint64_t& out);
std::string byte_text(uint64_t bytes);

// A lower bound of what Renderer::create allocates for `world`: shadow maps (6 views per point
// light, 1 per spot, 2 per sun), probes, surfels, the g-buffer and the scene's geometry.
uint64_t estimate_render_bytes(const World& world, const render::RenderOptions& options);
// The surfel cap and estimate_render_bytes() against `max_memory`.
Status check_render_budget(const World& world, const render::RenderOptions& options, uint64_t max_memory);
// The walk's cell-frame cap and its per-frame records against `max_memory`.
Status check_walk_budget(const World& world, size_t frames, uint64_t max_memory);

}  // namespace lintel::cli
