// Test-only switches of VisibilityBuilder, kept out of the installed VisibilityOptions so that a
// game cannot turn off what makes the traversal terminate. Tests reach this header through
// visibility/src (tests/visibility adds it to their include path); it is never installed.
#pragma once

#include <lintel/visibility_builder.h>

#include <cstdint>

namespace lintel {

struct VisibilityBuilderTesting {
  // No lattice (polygons kept at float precision, widened an ulp outward), no re-process cap, for
  // `builder`'s builds from now on (until switched off). Exists for the drift-hang regression
  // test; nothing bounds the traversal then except a hard stop at kUnboundedSafetyFactor x
  // pop_bound(), which build() reports as an error.
  static void disable_snap_and_cap(VisibilityBuilder& builder, bool on);
  // The build's steps as first written, for `builder`'s builds from now on: every portal projected
  // each time it is tested (no per-build cache), every Sutherland-Hodgman pass run
  // (detail::clip_convex_by_convex_plain), the snap by the double hull
  // (detail::snap_polygon_by_double_hull). The reference the fast paths are checked against: both
  // must give bit-identical VisibleSets (test_build_equivalence).
  static void use_reference_paths(VisibilityBuilder& builder, bool on);
  // Whether a popped cell's pending polygons are merged into hulls before its portals are clipped
  // (on by default; pending_merge.h). Off: one window per pending polygon, the build as before.
  static void merge_pending_windows(VisibilityBuilder& builder, bool on);
};

// The hard stop of the unbounded mode, as a multiple of pop_bound().
inline constexpr uint64_t kUnboundedSafetyFactor = 100;

}  // namespace lintel
