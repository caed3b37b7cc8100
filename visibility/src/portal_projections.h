// Internal: a portal's outline on the screen for one view (the flood's first step with a portal),
// and the per-build cache of the identity view's outlines, stored in the order the build makes
// them.
#pragma once

#include <lintel/portal_clip.h>
#include <lintel/world.h>

#include "flood_scratch.h"
#include "packed_portals.h"
#include "prefetch.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace lintel::detail {

// Projected portals and clip results smaller than this (NDC^2, about 2.5e-7 px^2 at 1000 px
// across) show nothing: they are edge-on portals or portals that only touch a region's border.
inline constexpr double kMinVisibleArea = 1e-12;

// A portal's outline on the screen for one view: clipped to the depth slab, divided,
// counter-clockwise, with its bounds. count < 3: nothing of it shows.
struct Projection {
  uint32_t first = 0;  // its vertices in PortalProjections' arena (when cached there)
  uint32_t count = 0;
  bool near_clipped = false;
  glm::dvec2 lo{0.0}, hi{0.0};
};

// Projects `polygon` (a portal's world vertices) by `view_proj` into `ndc_out` (room for its
// vertices plus the two the depth slab can add), working in `scratch`.
inline void project_portal(std::span<const glm::vec3> polygon, const glm::dmat4& view_proj, double clip_depth,
                           FloodScratch& scratch, glm::dvec2* ndc_out, Projection& p) {
  const size_t n = polygon.size();
  assert(n >= 3 && n <= kMaxPortalVertices);
  for (size_t i = 0; i < n; ++i) scratch.portal_clip[i] = view_proj * glm::dvec4(glm::dvec3(polygon[i]), 1.0);
  const SlabClipResult slab_result = clip_to_depth_slab(std::span<const glm::dvec4>(scratch.portal_clip.data(), n),
                                                        clip_depth, scratch.slab, scratch.slab_scratch);
  p.near_clipped = slab_result.near_clipped;
  p.count = 0;
  if (slab_result.count < 3) return;
  std::span<glm::dvec2> ndc(ndc_out, slab_result.count);
  perspective_divide(std::span<const glm::dvec4>(scratch.slab.data(), slab_result.count), ndc);
  const double area2 = twice_signed_area(ndc);
  if (std::abs(area2) <= 2.0 * kMinVisibleArea) return;
  if (area2 < 0.0) std::reverse(ndc.begin(), ndc.end());  // either stored winding works (and mirrored views)
  glm::dvec2 lo = ndc[0], hi = ndc[0];
  for (const glm::dvec2& v : ndc) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  p.lo = lo;
  p.hi = hi;
  p.count = slab_result.count;
}

// The projections of one build's identity view. A portal's projection depends on the view
// alone, not on the cell it is seen from or the region it is clipped to, yet a cell popped again
// would project all its portals again: computed once per build instead, on first use. They are
// stored in the order the build makes them (a portal's packed line says where, for which build),
// so a build writes and reads a few consecutive lines rather than one per portal scattered over
// the World's portal count: what a build that starts with cold caches pays for.
class PortalProjections {
 public:
  // Room for every portal of `world`, each with its vertices plus the two the depth slab can add.
  void prepare(const World& world) {
    projections_.assign(world.portals.size(), Projection{});
    size_t pool = 0;
    for (const Portal& p : world.portals) pool += p.polygon_world.size() + 2;
    pool_.assign(pool, glm::dvec2(0.0));
    reset();
  }
  // A new build: none made (the packed lines' stamps tell which entries are this build's).
  void reset() { made_ = used_ = 0; }

  // `portal`'s projection in the build stamped `stamp`, made on its first use.
  const Projection& get(PackedPortals& packed, uint32_t portal, uint32_t stamp, const glm::dmat4& view_proj,
                        double clip_depth, FloodScratch& scratch) {
    PackedPortal& entry = packed[portal];
    if (entry.projection_stamp != stamp) {
      entry.projection_stamp = stamp;
      entry.projection_slot = made_++;
      Projection& made = projections_[entry.projection_slot];
      made.first = used_;
      project_portal(packed.polygon(portal), view_proj, clip_depth, scratch, pool_.data() + used_, made);
      used_ += made.count;
    }
    return projections_[entry.projection_slot];
  }
  const glm::dvec2* vertices(const Projection& p) const { return pool_.data() + p.first; }

  // The first lines a build writes (prefetch.h).
  void prefetch() const {
    prefetch_write(projections_.data(), 4 * kCacheLine);
    prefetch_write(pool_.data(), 4 * kCacheLine);
  }

 private:
  std::vector<Projection> projections_;  // this build's, in the order made
  std::vector<glm::dvec2> pool_;         // their vertices, likewise
  uint32_t made_ = 0, used_ = 0;
};

}  // namespace lintel::detail
