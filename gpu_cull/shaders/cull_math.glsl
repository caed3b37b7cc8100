// The visibility rule of one instance box, step for step the CPU reference's
// (visibility/src/instance_cull.cpp project_aabb + box_visible_in_region, clip_region.cpp
// rect_overlaps_convex), in float where the reference uses double:
//   * a box containing the eye is visible;
//   * else its 12 edges are clipped to the slab 0 <= z <= w in clip space (Liang-Barsky, before
//     the divide: boxes around or beside the eye keep a finite rect), the clipped ends bound its
//     NDC rect, widened by one float ulp each way; nothing in the slab: culled;
//   * the rect must touch the region's rect, then one of its convex polygons: the polygon's
//     bounds, and no polygon edge with all four rect corners strictly outside.
// Two deliberate differences in form, not in value (GpuCullConstants): clip coordinates are taken
// eye-relative, and the far-plane distance w - z comes from a row precomputed in double, because
// in float both would cancel large terms.
// Where float and double still disagree the decision is within float error of a boundary; the
// tests classify such "borderline" instances and require equality on all others. Keep the two in
// step.
#ifndef LINTEL_CULL_MATH_GLSL
#define LINTEL_CULL_MATH_GLSL

#extension GL_EXT_control_flow_attributes : require  // [[unroll]]: corner arrays stay in registers

// std::nextafter(x, +inf) / (x, -inf) for finite x.
float next_up(float x) {
  if (x == 0.0) return uintBitsToFloat(1u);
  uint bits = floatBitsToUint(x);
  return uintBitsToFloat(x > 0.0 ? bits + 1u : bits - 1u);
}
float next_down(float x) {
  if (x == 0.0) return -uintBitsToFloat(1u);
  uint bits = floatBitsToUint(x);
  return uintBitsToFloat(x > 0.0 ? bits - 1u : bits + 1u);
}

// Closed: touching counts. Rects are (min x, min y, max x, max y).
bool rects_overlap(vec4 a, vec4 b) { return a.x <= b.z && b.x <= a.z && a.y <= b.w && b.y <= a.w; }

// Whether some corner of `rect` is not strictly outside the edge `line`.
// The reference's edge_side(a, b, p) as the edge's precomputed line (CullFrame::edges_ndc):
// > 0 inside. "All four corners strictly outside" is "the corner furthest inside is outside":
// the side is affine in p, so that corner follows from the normal's signs (one evaluation
// instead of four; they can differ only by rounding, i.e. on borderline instances).
bool rect_inside_edge(vec4 rect, vec4 line) {
  vec2 p = vec2(line.x > 0.0 ? rect.z : rect.x, line.y > 0.0 ? rect.w : rect.y);
  return !(line.x * p.x + line.y * p.y + line.z < 0.0);
}

bool rect_overlaps_polygon(vec4 rect, GpuPolygon poly) {
  if (!rects_overlap(rect, poly.bounds_ndc)) return false;
  uint n = min(poly.vertex_count, kMaxPolygonVertices);
  for (uint i = 0u; i < n; ++i)
    if (!rect_inside_edge(rect, edges_ndc[poly.first_vertex + i])) return false;
  return true;
}

// The region test; a region without polygons (a hand-made one over the GPU limits) is its rect.
bool rect_overlaps_region(vec4 rect, GpuRegion region) {
  if (!rects_overlap(rect, region.rect_ndc)) return false;
  if (region.polygon_count == 0u) return true;
  uint n = min(region.polygon_count, kMaxRegionPolygons);
  for (uint i = 0u; i < n; ++i)
    if (rect_overlaps_polygon(rect, polygons[region.first_polygon + i])) return true;
  return false;
}

const uvec2 kBoxEdges[12] = uvec2[12](uvec2(0, 1), uvec2(2, 3), uvec2(4, 5), uvec2(6, 7), uvec2(0, 2), uvec2(1, 3),
                                      uvec2(4, 6), uvec2(5, 7), uvec2(0, 4), uvec2(1, 5), uvec2(2, 6), uvec2(3, 7));

// What project_box concludes about a box, before any region is looked at.
const uint kBoxCulled = 0u;      // empty, or nothing of it between the near and far planes
const uint kBoxHoldsEye = 1u;    // contains the eye: visible wherever a cell of it is visible
const uint kBoxProjected = 2u;   // `rect`: the NDC rect to test against regions
const uint kBoxStraddles = 3u;   // (clip_edges false) a corner lies outside the slab: not projected

// test_regions == false (a coarser variant): the whole screen stands in for the region.
bool rect_visible_in_region(vec4 rect, uint region_index, bool test_regions) {
  if (!test_regions) return rects_overlap(rect, vec4(-1.0, -1.0, 1.0, 1.0));
  return rect_overlaps_region(rect, regions[region_index]);
}

// clip_edges == false (a constant at the call): a box that would need its edges clipped is left
// to a later pass (kBoxStraddles), so this call compiles without the clipping code.
uint project_box(vec3 box_min, vec3 box_max, mat4 view_proj_rel, vec4 far_row_rel, vec3 eye, bool clip_edges,
                 out vec4 rect) {
  rect = vec4(0.0);
  if (any(greaterThan(box_min, box_max))) return kBoxCulled;
  if (all(lessThanEqual(box_min, eye)) && all(lessThanEqual(eye, box_max))) return kBoxHoldsEye;
  vec4 corner[8];
  float far_distance[8];  // w - z, from the far row (GpuCullConstants::far_row_rel)
  bool all_in_slab = true, all_behind_near = true, all_beyond_far = true;
  [[unroll]] for (uint i = 0u; i < 8u; ++i) {
    vec3 p = vec3((i & 1u) != 0u ? box_max.x : box_min.x, (i & 2u) != 0u ? box_max.y : box_min.y,
                  (i & 4u) != 0u ? box_max.z : box_min.z);
    vec4 p_rel = vec4(p - eye, 1.0);  // eye-relative: see GpuCullConstants
    corner[i] = view_proj_rel * p_rel;
    far_distance[i] = dot(far_row_rel, p_rel);
    all_in_slab = all_in_slab && corner[i].z >= 0.0 && far_distance[i] >= 0.0;
    all_behind_near = all_behind_near && corner[i].z < 0.0;
    all_beyond_far = all_beyond_far && far_distance[i] < 0.0;
  }
  // Shortcuts to what the edge clipping below would conclude: every edge outside one plane, or
  // no edge clipped at all (then the clipped ends are the corners themselves).
  if (all_behind_near || all_beyond_far) return kBoxCulled;
  bool in_slab = false;
  const float infinity = uintBitsToFloat(0x7f800000u);
  vec2 lo = vec2(infinity), hi = vec2(-infinity);
  if (all_in_slab) {
    [[unroll]] for (uint i = 0u; i < 8u; ++i) {
      if (!(corner[i].w > 0.0)) continue;
      in_slab = true;
      vec2 ndc = corner[i].xy / corner[i].w;
      lo = min(lo, ndc);
      hi = max(hi, ndc);
    }
  } else if (!clip_edges) {
    return kBoxStraddles;
  } else {
    [[unroll]] for (uint e = 0u; e < 12u; ++e) {
      vec4 a = corner[kBoxEdges[e].x];
      vec4 b = corner[kBoxEdges[e].y];
      float t0 = 0.0, t1 = 1.0;
      bool inside = true;
      // Plane distances along the edge, linear in t: near z, far w - z.
      float da[2] = float[2](a.z, far_distance[kBoxEdges[e].x]);
      float db[2] = float[2](b.z, far_distance[kBoxEdges[e].y]);
      [[unroll]] for (uint p = 0u; p < 2u; ++p) {
        if (!inside) break;
        if (da[p] < 0.0 && db[p] < 0.0) {
          inside = false;
        } else if (da[p] < 0.0) {
          t0 = max(t0, da[p] / (da[p] - db[p]));
        } else if (db[p] < 0.0) {
          t1 = min(t1, da[p] / (da[p] - db[p]));
        }
      }
      if (!inside || t0 > t1) continue;
      [[unroll]] for (uint k = 0u; k < 2u; ++k) {
        vec4 c = a + (b - a) * (k == 0u ? t0 : t1);
        if (!(c.w > 0.0)) continue;
        in_slab = true;
        vec2 ndc = c.xy / c.w;
        lo = min(lo, ndc);
        hi = max(hi, ndc);
      }
    }
  }
  if (!in_slab) return kBoxCulled;
  rect = vec4(next_down(lo.x), next_down(lo.y), next_up(hi.x), next_up(hi.y));
  return kBoxProjected;
}

bool box_visible(vec3 box_min, vec3 box_max, mat4 view_proj_rel, vec4 far_row_rel, vec3 eye, uint region_index,
                 bool test_regions) {
  vec4 rect;
  uint kind = project_box(box_min, box_max, view_proj_rel, far_row_rel, eye, true, rect);
  if (kind != kBoxProjected) return kind == kBoxHoldsEye;
  return rect_visible_in_region(rect, region_index, test_regions);
}

#endif
