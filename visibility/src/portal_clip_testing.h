// Test-only: the convex clip as first written (every Sutherland-Hodgman pass run, ping-pong
// buffers), the reference clip_convex_by_convex is checked against bit for bit. Reached like
// visibility_builder_testing.h (tests add visibility/src to their include path); never installed.
#pragma once

#include <lintel/portal_clip.h>

namespace lintel::detail {

// Same contract and output as clip_convex_by_convex.
uint32_t clip_convex_by_convex_plain(std::span<const glm::dvec2> subject, std::span<const glm::vec2> window,
                                     std::span<glm::dvec2> out, std::span<glm::dvec2> scratch);

}  // namespace lintel::detail
