// Homogeneous near/far clipping and convex-convex clipping of projected portals.
// Learns from: Sutherland & Hodgman 1974 "Reentrant polygon clipping" (one plane at a time);
// Blinn & Newell 1978 "Clipping using homogeneous coordinates" (clip before the divide);
// Luebke & Georges 1995 "Portals and Mirrors" (the cull box shrinks through each portal).
// The Dark Mod's notes on Doom 3 show what goes wrong when the near clip happens after the divide
// (a portal around the eye vanishes or flips); here the divide only ever sees w >= min_depth > 0.
#include <lintel/portal_clip.h>

#include "portal_clip_testing.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace lintel {
namespace {

// One Sutherland-Hodgman pass against the plane dist(v) >= 0. Vertex types: dvec4 or dvec2.
template <typename Vertex, typename Distance>
uint32_t clip_against_plane(std::span<const Vertex> in, std::span<Vertex> out, Distance dist) {
  const size_t n = in.size();
  uint32_t count = 0;
  if (n == 0) return 0;
  Vertex prev = in[n - 1];
  double d_prev = dist(prev);
  for (size_t i = 0; i < n; ++i) {
    const Vertex cur = in[i];
    const double d_cur = dist(cur);
    if ((d_prev >= 0.0) != (d_cur >= 0.0)) {
      // The edge crosses the plane: interpolate from the inside end so that the new vertex is
      // computed the same way whichever direction the edge is walked (neighbouring polygons that
      // share the edge then agree on it bit for bit).
      assert(count < out.size());
      if (d_prev >= 0.0)
        out[count++] = prev + (cur - prev) * (d_prev / (d_prev - d_cur));
      else
        out[count++] = cur + (prev - cur) * (d_cur / (d_cur - d_prev));
    }
    if (d_cur >= 0.0) {
      assert(count < out.size());
      out[count++] = cur;
    }
    prev = cur;
    d_prev = d_cur;
  }
  return count;
}

}  // namespace

SlabClipResult clip_to_depth_slab(std::span<const glm::dvec4> in, double min_depth, std::span<glm::dvec4> out,
                                  std::span<glm::dvec4> scratch) {
  assert(in.size() >= 3 && in.size() <= kMaxPortalVertices);
  assert(out.size() >= in.size() + 2 && scratch.size() >= in.size() + 2);
  assert(min_depth > 0.0);
  SlabClipResult result;
  bool inside = true;
  for (const glm::dvec4& v : in) {
    assert(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w));
    if (v.w < min_depth) result.near_clipped = true;
    if (!(v.w - min_depth >= 0.0 && v.w - v.z >= 0.0)) inside = false;
  }
  if (inside) {  // what both passes would return: every vertex kept, in order
    std::copy(in.begin(), in.end(), out.begin());
    result.count = static_cast<uint32_t>(in.size());
    return result;
  }
  const uint32_t after_near =
      clip_against_plane<glm::dvec4>(in, scratch, [min_depth](const glm::dvec4& v) { return v.w - min_depth; });
  if (after_near < 3) return result;
  result.count = clip_against_plane<glm::dvec4>(std::span<const glm::dvec4>(scratch.data(), after_near), out,
                                                [](const glm::dvec4& v) { return v.w - v.z; });
  if (result.count < 3) result.count = 0;
  return result;
}

void perspective_divide(std::span<const glm::dvec4> in, std::span<glm::dvec2> out_ndc) {
  assert(out_ndc.size() >= in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    assert(in[i].w > 0.0);
    out_ndc[i] = glm::dvec2(in[i].x / in[i].w, in[i].y / in[i].w);
  }
}

double twice_signed_area(std::span<const glm::dvec2> poly) {
  double sum = 0.0;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {  // the same sum, in the same order, without a division per term
    const glm::dvec2& a = poly[i];
    const glm::dvec2& b = poly[i + 1 == n ? 0 : i + 1];
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

uint32_t clip_convex_by_convex(std::span<const glm::dvec2> subject, std::span<const glm::vec2> window,
                               std::span<glm::dvec2> out, std::span<glm::dvec2> scratch) {
  assert(window.size() >= 3 && window.size() <= kMaxRegionPolygonVertices);
  // Room for a pass's output: the buffers, as the plain passes check (a convex subject gains at
  // most one vertex per window edge, but a subject that rounding made slightly non-convex -- a
  // snapped hull clipped to the screen, say -- can gain more), and the distances' array.
  std::array<double, kMaxRegionClippedVertices + 4> dist;
  [[maybe_unused]] const size_t capacity = std::min({out.size(), scratch.size(), dist.size()});
  assert(subject.size() <= capacity);
  if (subject.size() < 3) return 0;
  // Sutherland-Hodgman, one window edge at a time, with the distances of a pass computed once up
  // front. Most passes of the traversal keep every vertex (a portal well inside its region): such
  // a pass would write its input unchanged, in order, so it is skipped; a pass with every vertex
  // outside would empty the polygon. The arithmetic of the other passes is clip_against_plane's,
  // so the result is the plain pass-by-pass clip's bit for bit (PortalClip.ConvexClipMatchesThe
  // PlainPasses).
  const size_t m = window.size();
  std::span<const glm::dvec2> current = subject;
  for (size_t e = 0; e < m; ++e) {
    const glm::dvec2 a(window[e]);
    const glm::dvec2 b(window[e + 1 == m ? 0 : e + 1]);
    const glm::dvec2 edge = b - a;
    const size_t n = current.size();
    bool any_out = false, any_in = false;
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec2& p = current[i];
      dist[i] = edge.x * (p.y - a.y) - edge.y * (p.x - a.x);
      (dist[i] >= 0.0 ? any_in : any_out) = true;
    }
    if (!any_out) continue;
    if (!any_in) return 0;
    glm::dvec2* target = current.data() == out.data() ? scratch.data() : out.data();
    uint32_t count = 0;
    size_t prev = n - 1;
    for (size_t i = 0; i < n; prev = i++) {
      const double d_prev = dist[prev], d_cur = dist[i];
      const glm::dvec2 cur = current[i], before = current[prev];
      if ((d_prev >= 0.0) != (d_cur >= 0.0)) {
        assert(count < capacity);
        if (d_prev >= 0.0)
          target[count++] = before + (cur - before) * (d_prev / (d_prev - d_cur));
        else
          target[count++] = cur + (before - cur) * (d_cur / (d_cur - d_prev));
      }
      if (d_cur >= 0.0) {
        assert(count < capacity);
        target[count++] = cur;
      }
    }
    if (count < 3) return 0;
    current = std::span<const glm::dvec2>(target, count);
  }
  if (current.data() != out.data()) std::copy(current.begin(), current.end(), out.begin());
  return static_cast<uint32_t>(current.size());
}

namespace detail {

uint32_t clip_convex_by_convex_plain(std::span<const glm::dvec2> subject, std::span<const glm::vec2> window,
                                     std::span<glm::dvec2> out, std::span<glm::dvec2> scratch) {
  assert(window.size() >= 3 && window.size() <= kMaxRegionPolygonVertices);
  if (subject.size() < 3) return 0;
  // Ping-pong so that the last pass writes into `out`.
  const size_t m = window.size();
  std::span<glm::dvec2> buffers[2] = {(m % 2 == 1) ? out : scratch, (m % 2 == 1) ? scratch : out};
  std::span<const glm::dvec2> current = subject;
  uint32_t count = static_cast<uint32_t>(subject.size());
  for (size_t e = 0; e < m; ++e) {
    const glm::dvec2 a(window[e]);
    const glm::dvec2 b(window[(e + 1) % m]);
    const glm::dvec2 edge = b - a;
    std::span<glm::dvec2> target = buffers[e % 2];
    count = clip_against_plane<glm::dvec2>(
        current, target, [&](const glm::dvec2& p) { return edge.x * (p.y - a.y) - edge.y * (p.x - a.x); });
    if (count < 3) return 0;
    current = std::span<const glm::dvec2>(target.data(), count);
  }
  assert(current.data() == out.data());
  return count;
}

}  // namespace detail
}  // namespace lintel
