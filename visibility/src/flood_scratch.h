// Internal: the fixed-size scratch one portal's step of the flood works in (projection, depth
// slab, clip against a window, snap), sized for the largest inputs and reused by every step, and
// the request for its first lines at a build's start: a game's build finds them out of every
// cache (prefetch.h).
#pragma once

#include <lintel/clip_region.h>
#include <lintel/ndc_snap.h>
#include <lintel/portal_clip.h>

#include "prefetch.h"

#include <array>

#include <glm/glm.hpp>

namespace lintel::detail {

struct FloodScratch {
  std::array<glm::dvec4, kMaxPortalVertices> portal_clip{};  // a portal's vertices in clip space
  std::array<glm::dvec4, kMaxSlabClippedVertices> slab{}, slab_scratch{};
  std::array<glm::dvec2, kMaxSlabClippedVertices> portal_ndc{};  // a projection not cached
  std::array<glm::dvec2, kMaxRegionClippedVertices> clipped{}, clip_scratch{};
  std::array<glm::vec2, kMaxRegionPolygonVertices> snapped{};
  SnapScratch snap{};

  // The lines a small build writes: the first two of each array (the snap's column halves apart).
  void prefetch() const {
    prefetch_write(portal_clip.data(), 2 * kCacheLine);
    prefetch_write(slab.data(), 2 * kCacheLine);
    prefetch_write(portal_ndc.data(), 2 * kCacheLine);
    prefetch_write(clipped.data(), 2 * kCacheLine);
    prefetch_write(clip_scratch.data(), 2 * kCacheLine);
    prefetch_write(snapped.data(), 2 * kCacheLine);
    prefetch_write(snap.boxes.data(), 2 * kCacheLine);
    prefetch_write(snap.lattice_points.data(), 2 * kCacheLine);
    prefetch_write(snap.lattice_points.data() + snap.lattice_points.size() / 2, 2 * kCacheLine);
    prefetch_write(snap.lattice_hull.data(), 2 * kCacheLine);
  }
};

}  // namespace lintel::detail
