// The conservative depth buffer and max pyramid of occlusion_raster.h: coverage by contour-free
// footprints, depth by each touching triangle's deepest point over the footprint.
#include <lintel/reference/occlusion_raster.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace lintel {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Float error allowances (see margin_at): the ground truth's rays and Embree's intersections are
// float, this model is double on the same float vertices.
constexpr double kMarginAbsNdc = 2e-6;                // the float ray direction through a pixel centre (~3e-7)
constexpr double kMarginRel = 1e-6;                   // ~16 float ulps of the coordinates' magnitude, in meters
constexpr double kDepthRel = 1e-4, kDepthAbs = 1e-4;  // box depth vs occluder depth (Embree's t)

struct PosKey {
  float x, y, z;
  bool operator<(const PosKey& o) const { return std::tie(x, y, z) < std::tie(o.x, o.y, o.z); }
};

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// Texel index range of [lo, hi] in NDC (closed texels), clamped; empty when first > last.
void texel_range(double lo, double hi, double texel, int size, int& first, int& last) {
  const double a = std::clamp((lo + 1.0) / texel, -1.0, double(size)),
               b = std::clamp((hi + 1.0) / texel, -1.0, double(size));
  first = std::max(0, int(std::floor(a)));
  last = std::min(size - 1, int(std::floor(b)));
}

}  // namespace

OccluderMesh make_occluder_mesh(const Mesh& mesh, const glm::mat4& mesh_to_world) {
  OccluderMesh out;
  std::map<PosKey, uint32_t> index_of;
  std::vector<uint32_t> remap(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    // Exactly the ground truth's vertex (embree_mesh.cpp): float matrix times float vertex.
    const glm::vec3 p = glm::vec3(mesh_to_world * glm::vec4(mesh.positions[v], 1.0f));
    const auto [it, inserted] = index_of.emplace(PosKey{p.x, p.y, p.z}, uint32_t(out.positions_world.size()));
    if (inserted) {
      out.positions_world.push_back(p);
      out.bounds_world.extend(p);
    }
    remap[v] = it->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_of;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t t[3] = {remap[mesh.indices[i]], remap[mesh.indices[i + 1]], remap[mesh.indices[i + 2]]};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    const uint32_t tri = uint32_t(out.indices.size() / 3);
    out.indices.insert(out.indices.end(), t, t + 3);
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3], opp = t[(k + 2) % 3];
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = edge_of.emplace(key, uint32_t(out.edges.size()));
      if (inserted) {
        OccluderMesh::Edge e;
        e.a = key.first, e.b = key.second, e.tri[0] = tri, e.opposite[0] = opp;
        out.edges.push_back(e);
        continue;
      }
      OccluderMesh::Edge& e = out.edges[it->second];
      if (e.tri[1] == OccluderMesh::kNone) {
        e.tri[1] = tri, e.opposite[1] = opp;
      } else {
        e.opposite[1] = OccluderMesh::kNone;  // three or more triangles: a contour edge
      }
    }
  }
  return out;
}

void mark_portal_rims(const World& world, uint32_t cell, const std::vector<double>& rim_radius_m, OccluderMesh& mesh) {
  mesh.rim_portal.assign(mesh.edges.size(), OccluderMesh::kNone);
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    const Portal& portal = world.portals[p];
    if (portal.linked() || (portal.from != cell && portal.to != cell) || portal.from == portal.to) continue;
    const double r = 0.5 * rim_radius_m[p];
    if (!(r > 0.0)) continue;
    const glm::dvec3 n = glm::normalize(glm::dvec3(portal.normal_world));
    const size_t count = portal.polygon_world.size();
    for (size_t k = 0; k < count; ++k) {
      const glm::dvec3 a(portal.polygon_world[k]), b(portal.polygon_world[(k + 1) % count]);
      const double len = glm::length(b - a);
      if (!(len > 0.0)) continue;
      const glm::dvec3 along = (b - a) / len, across = glm::normalize(glm::cross(n, along));
      auto inside = [&](const glm::vec3& q) {
        const glm::dvec3 d = glm::dvec3(q) - a;
        const double s = glm::dot(d, along);
        return s >= -r && s <= len + r && std::abs(glm::dot(d, n)) <= r && std::abs(glm::dot(d, across)) <= r;
      };
      for (size_t e = 0; e < mesh.edges.size(); ++e) {
        const OccluderMesh::Edge& edge = mesh.edges[e];
        if (edge.tri[1] != OccluderMesh::kNone) continue;  // only boundary edges end at a rim
        if (inside(mesh.positions_world[edge.a]) && inside(mesh.positions_world[edge.b])) mesh.rim_portal[e] = p;
      }
    }
  }
}

void OcclusionBuffer::begin(const View& view, uint32_t size, double rim_pad_m) {
  assert(validate_view(view).ok());
  assert(size >= 1 && size <= 4096 && (size & (size - 1)) == 0);
  // The ground truth's camera basis (ray_ground_truth.cpp), in double.
  eye_ = glm::dvec3(view.eye_world);
  forward_ = glm::normalize(glm::dvec3(view.target_world) - eye_);
  right_ = glm::normalize(glm::cross(forward_, glm::dvec3(view.up_world)));
  up_ = glm::cross(right_, forward_);
  ty_ = std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
  tx_ = ty_ * double(view.aspect);
  // The rays start on the near plane; a surface closer than this is not drawn (and its cut is a
  // contour), so float rounding of the rays' start cannot put an occluder before it.
  clip_depth_ = double(view.near_m) * (1.0 + 1e-4);
  if (size_ != size) {
    size_ = size;
    levels_.clear();
    for (uint32_t s = size; s >= 1; s /= 2) levels_.emplace_back(size_t(s) * s);
    mesh_depth_.assign(size_t(size) * size, 0.0f);
    mesh_flags_.assign(size_t(size) * size, 0);
  }
  union_depth_.assign(size_t(size) * size, 0.0f);
  union_flags_.assign(size_t(size) * size, 0);
  rim_pad_m_ = rim_pad_m;
  texel_ = 2.0 / double(size);
  std::fill(levels_[0].begin(), levels_[0].end(), std::numeric_limits<float>::infinity());
  triangles_drawn_ = 0;
}

// NDC allowance at view depth `depth` for the float arithmetic of the rays and of Embree: an
// error of kMarginRel times the coordinates' magnitude (meters) seen from that depth.
double OcclusionBuffer::margin_at(double depth) const {
  return kMarginAbsNdc + kMarginRel * scale_m_ / (std::max(depth, 1e-9) * std::min(tx_, ty_));
}

void OcclusionBuffer::touch_rect(int x0, int y0, int x1, int y1) {
  rx0_ = std::min(rx0_, x0), ry0_ = std::min(ry0_, y0);
  rx1_ = std::max(rx1_, x1), ry1_ = std::max(ry1_, y1);
}

void OcclusionBuffer::mark_segment_ndc(const glm::dvec2& a, const glm::dvec2& b, double margin, uint8_t bit) {
  const int n = int(size_);
  int j0, j1;
  texel_range(std::min(a.y, b.y) - margin, std::max(a.y, b.y) + margin, texel_, n, j0, j1);
  for (int j = j0; j <= j1; ++j) {
    const double y0 = -1.0 + j * texel_ - margin, y1 = -1.0 + (j + 1) * texel_ + margin;
    double xl, xh;
    const double dy = b.y - a.y;
    if (std::abs(dy) <= 1e-300) {
      xl = std::min(a.x, b.x), xh = std::max(a.x, b.x);
    } else {
      double t0 = (y0 - a.y) / dy, t1 = (y1 - a.y) / dy;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
      if (t0 > t1) continue;
      const double xa = a.x + (b.x - a.x) * t0, xb = a.x + (b.x - a.x) * t1;
      xl = std::min(xa, xb), xh = std::max(xa, xb);
    }
    int i0, i1;
    texel_range(xl - margin, xh + margin, texel_, n, i0, i1);
    if (i0 > i1) continue;
    for (int i = i0; i <= i1; ++i) mesh_flags_[size_t(j) * size_ + i] |= bit;
    touch_rect(i0, j, i1, j);
  }
}

void OcclusionBuffer::mark_contour(const glm::dvec3& a, const glm::dvec3& b, uint8_t bit) {
  glm::dvec3 p = a, q = b;
  if (p.z < clip_depth_ && q.z < clip_depth_) return;
  if (p.z < clip_depth_) p = p + (q - p) * ((clip_depth_ - p.z) / (q.z - p.z));
  if (q.z < clip_depth_) q = q + (p - q) * ((clip_depth_ - q.z) / (p.z - q.z));
  const glm::dvec2 pn(p.x / (p.z * tx_), p.y / (p.z * ty_)), qn(q.x / (q.z * tx_), q.y / (q.z * ty_));
  mark_segment_ndc(pn, qn, margin_at(std::min(p.z, q.z)), bit);
}

// A convex polygon (3 or 4 view-space vertices, all at depth >= clip_depth_).
void OcclusionBuffer::draw_polygon(const glm::dvec3* v, int count) {
  glm::dvec2 p[4];
  double zmin = kInf, zmax = 0.0;
  for (int k = 0; k < count; ++k) {
    p[k] = glm::dvec2(v[k].x / (v[k].z * tx_), v[k].y / (v[k].z * ty_));
    zmin = std::min(zmin, v[k].z), zmax = std::max(zmax, v[k].z);
  }
  double area = 0.0;
  for (int k = 0; k < count; ++k) area += cross2(p[k], p[(k + 1) % count]);
  if (!(std::abs(area) > 1e-18)) return;  // edge-on: covers nothing (its edges are contours)
  const double orient = area > 0.0 ? 1.0 : -1.0;
  // Edge k as a unit line: e(x) = dot(nrm, x) + c >= 0 inside.
  glm::dvec2 nrm[4];
  double c[4], reach[4];
  const double margin = margin_at(zmin), half = 0.5 * texel_ + margin;
  for (int k = 0; k < count; ++k) {
    const glm::dvec2 d = p[(k + 1) % count] - p[k];
    const double len = glm::length(d);
    if (!(len > 0.0)) return;
    nrm[k] = orient * glm::dvec2(-d.y, d.x) / len;
    c[k] = -glm::dot(nrm[k], p[k]);
    reach[k] = (std::abs(nrm[k].x) + std::abs(nrm[k].y)) * half;  // max of e over a widened texel - e(centre)
  }
  // Plane through the polygon in view space, oriented so that k > 0: depth along the ray through
  // NDC (u, v) is k / D(u, v), D = n.x tx u + n.y ty v + n.z, wherever D > 0.
  glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
  double k = glm::dot(n, v[0]);
  if (k < 0.0) n = -n, k = -k;
  const bool plane_ok = k > 1e-12 * glm::length(n) * glm::length(v[0]);
  const double du = n.x * tx_, dv = n.y * ty_, spread = (std::abs(du) + std::abs(dv)) * half;

  glm::dvec2 lo = p[0], hi = p[0];
  for (int i = 1; i < count; ++i) lo = glm::min(lo, p[i]), hi = glm::max(hi, p[i]);
  const int size = int(size_);
  int i0, i1, j0, j1;
  texel_range(lo.x - margin, hi.x + margin, texel_, size, i0, i1);
  texel_range(lo.y - margin, hi.y + margin, texel_, size, j0, j1);
  if (i0 > i1 || j0 > j1) return;
  ++triangles_drawn_;
  touch_rect(i0, j0, i1, j1);
  for (int j = j0; j <= j1; ++j) {
    const double yc = -1.0 + (j + 0.5) * texel_;
    for (int i = i0; i <= i1; ++i) {
      const double xc = -1.0 + (i + 0.5) * texel_;
      bool touches = true, centre_in = true;
      for (int e = 0; e < count; ++e) {
        const double d = nrm[e].x * xc + nrm[e].y * yc + c[e];
        touches = touches && d >= -reach[e];
        centre_in = centre_in && d >= 0.0;
      }
      if (!touches) continue;
      double bound = zmax;  // the polygon's deepest vertex bounds it everywhere
      const double dmin = du * xc + dv * yc + n.z - spread;
      if (plane_ok && dmin > 0.0) bound = std::min(bound, k / dmin);
      const size_t idx = size_t(j) * size_ + i;
      // Round up to float: the stored bound must stay an upper bound.
      float f = float(bound);
      if (double(f) < bound) f = std::nextafter(f, std::numeric_limits<float>::infinity());
      mesh_depth_[idx] = std::max(mesh_depth_[idx], f);
      if (centre_in) mesh_flags_[idx] |= 1;
    }
  }
}

void OcclusionBuffer::add_mesh(const OccluderMesh& mesh, std::span<const uint8_t> sealed_portals) {
  assert(size_ > 0);
  if (mesh.indices.empty()) return;
  scale_m_ = std::max({std::abs(eye_.x), std::abs(eye_.y), std::abs(eye_.z), 1.0});
  for (int a = 0; a < 3; ++a)
    scale_m_ =
        std::max({scale_m_, std::abs(double(mesh.bounds_world.min[a])), std::abs(double(mesh.bounds_world.max[a]))});
  projected_.resize(mesh.positions_world.size());
  for (size_t i = 0; i < mesh.positions_world.size(); ++i) {
    const glm::dvec3 r = glm::dvec3(mesh.positions_world[i]) - eye_;
    Projected& pr = projected_[i];
    pr.v = glm::dvec3(glm::dot(r, right_), glm::dot(r, up_), glm::dot(r, forward_));
    pr.in_front = pr.v.z >= clip_depth_;
    pr.ndc = pr.in_front ? glm::dvec2(pr.v.x / (pr.v.z * tx_), pr.v.y / (pr.v.z * ty_)) : glm::dvec2(0.0);
  }
  rx0_ = ry0_ = int(size_), rx1_ = ry1_ = -1;
  const size_t tris = mesh.indices.size() / 3;
  tri_ok_.assign(tris, 0);
  for (size_t t = 0; t < tris; ++t) {
    const uint32_t* id = &mesh.indices[3 * t];
    const int front =
        int(projected_[id[0]].in_front) + int(projected_[id[1]].in_front) + int(projected_[id[2]].in_front);
    if (front == 0) continue;
    if (front == 3) {
      const glm::dvec3 v[3] = {projected_[id[0]].v, projected_[id[1]].v, projected_[id[2]].v};
      const double area =
          cross2(projected_[id[1]].ndc - projected_[id[0]].ndc, projected_[id[2]].ndc - projected_[id[0]].ndc);
      tri_ok_[t] = std::abs(area) > 1e-18;
      draw_polygon(v, 3);
      continue;
    }
    // Cut by the clip depth: the part in front (3 or 4 vertices), and the cut is a contour.
    glm::dvec3 poly[4], cut[2];
    int count = 0, cuts = 0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 a = projected_[id[k]].v, b = projected_[id[(k + 1) % 3]].v;
      const bool fa = a.z >= clip_depth_, fb = b.z >= clip_depth_;
      if (fa) poly[count++] = a;
      if (fa != fb) cut[cuts++] = poly[count++] = a + (b - a) * ((clip_depth_ - a.z) / (b.z - a.z));
    }
    if (count >= 3) {
      double area = 0.0;
      for (int k = 0; k < count; ++k) {
        const glm::dvec2 pa(poly[k].x / (poly[k].z * tx_), poly[k].y / (poly[k].z * ty_));
        const glm::dvec3& q = poly[(k + 1) % count];
        area += cross2(pa, glm::dvec2(q.x / (q.z * tx_), q.y / (q.z * ty_)));
      }
      tri_ok_[t] = std::abs(area) > 1e-18;
      draw_polygon(poly, count);
    }
    if (cuts == 2) mark_contour(cut[0], cut[1], 2);
  }
  // Contours: every edge not shared by two drawable triangles lying on opposite sides of it.
  for (const OccluderMesh::Edge& e : mesh.edges) {
    bool interior = e.tri[1] != OccluderMesh::kNone && e.opposite[1] != OccluderMesh::kNone && tri_ok_[e.tri[0]] &&
                    tri_ok_[e.tri[1]];
    if (interior) {
      // Opposite sides of the plane through the eye and the edge: the parts of the two triangles
      // in front of the eye project to opposite sides of the edge (also where one is cut).
      const glm::dvec3& a = projected_[e.a].v;
      const glm::dvec3 n = glm::cross(a, projected_[e.b].v);
      const glm::dvec3 &o0 = projected_[e.opposite[0]].v, &o1 = projected_[e.opposite[1]].v;
      const double s0 = glm::dot(n, o0 - a), s1 = glm::dot(n, o1 - a);
      const double tol0 = 1e-12 * glm::length(n) * glm::length(o0 - a),
                   tol1 = 1e-12 * glm::length(n) * glm::length(o1 - a);
      interior = (s0 > tol0 && s1 < -tol1) || (s0 < -tol0 && s1 > tol1);
    }
    if (interior) continue;
    const size_t index = size_t(&e - mesh.edges.data());
    const bool sealed = !mesh.rim_portal.empty() && mesh.rim_portal[index] != OccluderMesh::kNone &&
                        mesh.rim_portal[index] < sealed_portals.size() && sealed_portals[mesh.rim_portal[index]];
    mark_contour(projected_[e.a].v, projected_[e.b].v, sealed ? 4 : 2);
  }
  // Resolve: texels whose widened footprint this mesh covers take its bound (min with others).
  std::vector<float>& level0 = levels_[0];
  for (int j = ry0_; j <= ry1_; ++j) {
    for (int i = rx0_; i <= rx1_; ++i) {
      const size_t idx = size_t(j) * size_ + i;
      const uint8_t f = mesh_flags_[idx];
      if (f == 1) level0[idx] = std::min(level0[idx], mesh_depth_[idx]);
      union_flags_[idx] |= uint8_t(f & 3);
      union_depth_[idx] = std::max(union_depth_[idx], mesh_depth_[idx]);
      mesh_flags_[idx] = 0;
      mesh_depth_[idx] = 0.0f;
    }
  }
}

void OcclusionBuffer::build_pyramid() {
  // The union of all meshes (see the header): covered where some centre is and no contour is.
  std::vector<float>& level0 = levels_[0];
  for (size_t idx = 0; idx < level0.size(); ++idx) {
    if (union_flags_[idx] != 1) continue;
    double bound = double(union_depth_[idx]) + rim_pad_m_;
    float f = float(bound);
    if (double(f) < bound) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    level0[idx] = std::min(level0[idx], f);
  }
  for (size_t l = 1; l < levels_.size(); ++l) {
    const uint32_t s = size_ >> l, below = s * 2;
    const std::vector<float>& src = levels_[l - 1];
    std::vector<float>& dst = levels_[l];
    for (uint32_t y = 0; y < s; ++y)
      for (uint32_t x = 0; x < s; ++x) {
        const size_t a = size_t(2 * y) * below + 2 * x, b = a + below;
        dst[size_t(y) * s + x] = std::max(std::max(src[a], src[a + 1]), std::max(src[b], src[b + 1]));
      }
  }
}

bool OcclusionBuffer::box_occluded(const Aabb& box) const {
  if (box.empty() || size_ == 0) return false;
  double zmin = kInf, scale = std::max({std::abs(eye_.x), std::abs(eye_.y), std::abs(eye_.z), 1.0});
  glm::dvec2 lo(kInf), hi(-kInf);
  glm::dvec3 r[8];
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                            (k & 4) ? box.max.z : box.min.z);
    scale = std::max({scale, std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)});
    const glm::dvec3 d = corner - eye_;
    r[k] = glm::dvec3(glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_));
    zmin = std::min(zmin, r[k].z);
  }
  if (!(zmin > clip_depth_)) return false;  // reaches the near plane: never rejected
  for (const glm::dvec3& q : r) {
    const glm::dvec2 p(q.x / (q.z * tx_), q.y / (q.z * ty_));
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  const double margin = kMarginAbsNdc + kMarginRel * scale / (zmin * std::min(tx_, ty_));
  const int size = int(size_);
  int i0, i1, j0, j1;
  texel_range(lo.x - margin, hi.x + margin, texel_, size, i0, i1);
  texel_range(lo.y - margin, hi.y + margin, texel_, size, j0, j1);
  if (i0 > i1 || j0 > j1) return false;  // off screen: left to the portal test
  // The box's screen outline: the convex hull of its 8 projected corners (monotone chain),
  // counter-clockwise, as unit edge lines widened by the margin.
  glm::dvec2 pts[8], hull[16];
  for (int k = 0; k < 8; ++k) pts[k] = glm::dvec2(r[k].x / (r[k].z * tx_), r[k].y / (r[k].z * ty_));
  std::sort(pts, pts + 8,
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  int h = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const int base = h;
    for (int k = 0; k < 8; ++k) {
      const glm::dvec2& q = pass == 0 ? pts[k] : pts[7 - k];
      while (h >= base + 2 && cross2(hull[h - 1] - hull[h - 2], q - hull[h - 2]) <= 0.0) --h;
      hull[h++] = q;
    }
    --h;  // the last point starts the other chain
  }
  glm::dvec2 nrm[16];
  double c[16];
  int edges = 0;
  for (int k = 0; k < h; ++k) {
    const glm::dvec2 d = hull[(k + 1) % h] - hull[k];
    const double len = glm::length(d);
    if (!(len > 0.0)) continue;
    nrm[edges] = glm::dvec2(-d.y, d.x) / len;  // inside: dot(nrm, x) + c >= 0
    c[edges] = -glm::dot(nrm[edges], hull[k]) + margin;
    ++edges;
  }
  // Descend the pyramid from the finest level whose texels over the rect are at most 4 x 4: a
  // texel passes when its bound is in front of the box or its footprint misses the outline; a
  // level-0 texel that does neither keeps the box.
  const double threshold = (zmin - kDepthAbs) / (1.0 + kDepthRel);  // bounds below this occlude
  int level = 0;
  while (level + 1 < int(levels_.size()) && ((i1 >> level) - (i0 >> level) > 3 || (j1 >> level) - (j0 >> level) > 3))
    ++level;
  struct Item {
    int level, i, j;
  };
  Item stack[64 + 16];
  int top = 0;
  for (int j = j0 >> level; j <= (j1 >> level); ++j)
    for (int i = i0 >> level; i <= (i1 >> level); ++i) stack[top++] = {level, i, j};
  while (top > 0) {
    const Item t = stack[--top];
    const int s = size >> t.level;
    const float bound = levels_[size_t(t.level)][size_t(t.j) * s + t.i];
    if (double(bound) < threshold) continue;
    const double w = texel_ * double(1 << t.level), half = 0.5 * w;
    const double xc = -1.0 + (t.i + 0.5) * w, yc = -1.0 + (t.j + 0.5) * w;
    bool touches = true;
    for (int e = 0; e < edges && touches; ++e)
      touches = nrm[e].x * xc + nrm[e].y * yc + c[e] >= -(std::abs(nrm[e].x) + std::abs(nrm[e].y)) * half;
    if (!touches) continue;
    if (t.level == 0) return false;
    for (int k = 0; k < 4; ++k) stack[top++] = {t.level - 1, 2 * t.i + (k & 1), 2 * t.j + (k >> 1)};
  }
  return true;
}

uint64_t OcclusionBuffer::covered_texels() const {
  uint64_t n = 0;
  for (float d : levels_[0]) n += std::isfinite(d) ? 1 : 0;
  return n;
}

}  // namespace lintel
