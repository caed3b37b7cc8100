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
};

// The hard stop of the unbounded mode, as a multiple of pop_bound().
inline constexpr uint64_t kUnboundedSafetyFactor = 100;

}  // namespace lintel
