// The exact oracle (exact_oracle.h): breadth-first portal flood over exact polygon sets.
// Learns from: Luebke & Georges 1995 (screen regions shrinking through portals), with the
// approximations of real portal engines removed — CGAL's Boolean set operations on Epeck
// (Fogel, Halperin & Wein, "CGAL Arrangements and Their Applications", 2012) replace snapping.
// The projection is exact too: clip = M * p with M and p given as doubles/floats is a product of
// exact rationals, clipped against w >= d and z <= w and divided exactly.
#include <lintel/reference/exact_oracle.h>

#include <lintel/doorway_rule.h>
#include <lintel/instance_cull.h>
#include <lintel/instance_reach.h>
#include <lintel/portal_clip.h>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>

#include <array>
#include <cassert>
#include <cmath>
#include <deque>

namespace lintel {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

struct Hom {
  FT x, y, z, w;
};

Hom lerp(const Hom& a, const Hom& b, const FT& t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z), a.w + t * (b.w - a.w)};
}

// Sutherland-Hodgman against one half-space given by a linear function of the vertex (>= 0 kept).
template <class F>
std::vector<Hom> clip_half(const std::vector<Hom>& in, F dist) {
  std::vector<Hom> out;
  const size_t n = in.size();
  for (size_t i = 0; i < n; ++i) {
    const Hom& a = in[i];
    const Hom& b = in[(i + 1) % n];
    const FT da = dist(a), db = dist(b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
  }
  return out;
}

double set_area(const PolygonSet& set) {
  std::vector<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  FT a = 0;
  for (const PolygonWithHoles& p : parts) {
    a += p.outer_boundary().area();
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += h->area();  // holes are clockwise
  }
  return CGAL::to_double(a);
}

class ExactMethod final : public CullMethod {
 public:
  std::string name() const override { return "exact"; }
  std::string settings() const override { return ""; }
  bool claims_conservative() const override { return true; }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    regions_out_.assign(world.cells.size(), {});
    region_.clear();
    if (Status s = validate_view(view); !s) return s;
    if (start_cell >= world.cells.size()) return Status::error("exact: start cell out of range");
    const size_t n = world.cells.size();
    region_.assign(n, PolygonSet());
    std::vector<PolygonSet>& region = region_;
    std::vector<PolygonSet> processed(n);
    std::vector<uint8_t> queued(n, 0), reached(n, 0);
    std::deque<uint32_t> queue;
    const glm::dmat4 vp = view_projection_d(view);
    const glm::dvec3 eye(view.eye_world);
    const double near_extent = near_half_extent(view);
    const FT clip_depth = portal_clip_depth(view);
    const uint64_t hard_stop = kExactOracleMaxPopsPerCell * n;

    Polygon screen;
    screen.push_back(Point(-1, -1));
    screen.push_back(Point(1, -1));
    screen.push_back(Point(1, 1));
    screen.push_back(Point(-1, 1));
    region[start_cell].insert(screen);
    reached[start_cell] = 1;
    queue.push_back(start_cell);
    queued[start_cell] = 1;
    while (!queue.empty()) {
      if (out.pops >= hard_stop) {
        out.bound_hit = true;
        break;
      }
      const uint32_t cell = queue.front();
      queue.pop_front();
      queued[cell] = 0;
      ++out.pops;
      // Only what arrived since the last processing needs to go on.
      PolygonSet pending = region[cell];
      pending.difference(processed[cell]);
      processed[cell] = region[cell];
      if (pending.is_empty()) continue;
      for (const PortalLink& link : world.cells[cell].links) {
        const Portal& portal = world.portals[link.portal];
        if (portal.from != cell && (portal.to != cell || !portal.two_way)) continue;
        PolygonSet through = pending;
        const double s = portal_signed_distance(portal, cell, eye);
        if (!(std::abs(s) <= double(view.near_m) && projects_inside_portal(portal, eye, near_extent))) {
          if (!(s < 0.0)) continue;
          Polygon projected;
          if (!project_portal(portal, vp, clip_depth, projected)) continue;
          through.intersection(projected);
          if (through.is_empty()) continue;
        }
        PolygonSet grown = through;
        grown.difference(region[link.neighbour]);
        if (grown.is_empty()) continue;
        region[link.neighbour].join(through);
        reached[link.neighbour] = 1;
        if (!queued[link.neighbour]) {
          queued[link.neighbour] = 1;
          queue.push_back(link.neighbour);
        }
      }
    }

    for (uint32_t c = 0; c < n; ++c) {
      if (!reached[c] || region[c].is_empty()) continue;
      out.cell_visible[c] = 1;
    }
    if (reach_world_ != &world || reach_.instance_count() != world.instances.size()) {
      reach_.compute(world);  // once per world, like VisibilityBuilder::prepare
      reach_world_ = &world;
    }
    for (uint32_t i = 0; i < world.instances.size(); ++i) {
      const Instance& inst = world.instances[i];
      // Listed from every visible cell its bounds reach (instance_reach.h), as Lintel lists it.
      bool any_visible = false;
      for (const uint32_t* c = reach_.begin(i); c != reach_.end(i); ++c)
        any_visible = any_visible || out.cell_visible[*c];
      if (!any_visible) continue;
      const ProjectedBox box =
          project_aabb(vp, eye, glm::dvec3(inst.bounds_world.min), glm::dvec3(inst.bounds_world.max));
      if (box.contains_eye) {
        out.instance_visible[i] = 1;
        continue;
      }
      if (!box.in_slab) continue;
      // Lintel's rule: touching counts, so the closed rect against the closed region.
      const NdcRect& r = box.rect_ndc;
      Polygon rect;
      rect.push_back(Point(r.min.x, r.min.y));
      rect.push_back(Point(r.max.x, r.min.y));
      rect.push_back(Point(r.max.x, r.max.y));
      rect.push_back(Point(r.min.x, r.max.y));
      if (r.min.x == r.max.x || r.min.y == r.max.y) {  // degenerate rect: test its bounds widened by an ulp
        rect.clear();
        const float lx = std::nextafter(r.min.x, -2.0f), hx = std::nextafter(r.max.x, 2.0f);
        const float ly = std::nextafter(r.min.y, -2.0f), hy = std::nextafter(r.max.y, 2.0f);
        rect.push_back(Point(lx, ly));
        rect.push_back(Point(hx, ly));
        rect.push_back(Point(hx, hy));
        rect.push_back(Point(lx, hy));
      }
      for (const uint32_t* c = reach_.begin(i); c != reach_.end(i) && !out.instance_visible[i]; ++c)
        if (out.cell_visible[*c] && region[*c].do_intersect(rect)) out.instance_visible[i] = 1;
    }
    return {};
  }

  // Scoring only (outside the benchmark's clock): exact areas and double outlines of the regions.
  void measure(MethodResult& out) override {
    for (uint32_t c = 0; c < region_.size(); ++c) {
      if (!out.cell_visible[c]) continue;
      out.cell_region_area[c] = set_area(region_[c]);
      std::vector<PolygonWithHoles> parts;
      region_[c].polygons_with_holes(std::back_inserter(parts));
      NdcRect bounds;
      for (const PolygonWithHoles& p : parts) {
        std::vector<glm::dvec2>& poly = regions_out_[c].emplace_back();
        for (auto v = p.outer_boundary().vertices_begin(); v != p.outer_boundary().vertices_end(); ++v) {
          poly.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
          bounds.extend(glm::vec2(poly.back()));
        }
      }
      out.cell_bounds[c] = glm::dvec4(bounds.min.x, bounds.min.y, bounds.max.x, bounds.max.y);
    }
  }

  const std::vector<std::vector<std::vector<glm::dvec2>>>& regions() const { return regions_out_; }

 private:
  // The portal clipped to the slab w >= clip_depth, z <= w and divided, counter-clockwise.
  // False when nothing with positive area is left.
  static bool project_portal(const Portal& portal, const glm::dmat4& vp, const FT& clip_depth, Polygon& out) {
    std::vector<Hom> poly;
    for (const glm::vec3& v : portal.polygon_world) {
      const FT p[4] = {FT(double(v.x)), FT(double(v.y)), FT(double(v.z)), FT(1)};
      FT c[4];
      for (int r = 0; r < 4; ++r) {
        c[r] = FT(0);
        for (int k = 0; k < 4; ++k) c[r] += FT(vp[k][r]) * p[k];  // glm is column-major: vp[col][row]
      }
      poly.push_back({c[0], c[1], c[2], c[3]});
    }
    poly = clip_half(poly, [&](const Hom& h) { return h.w - clip_depth; });
    if (poly.size() >= 3) poly = clip_half(poly, [](const Hom& h) { return h.w - h.z; });
    if (poly.size() < 3) return false;
    out.clear();
    for (const Hom& h : poly) {
      const Point p(h.x / h.w, h.y / h.w);
      if (out.size() > 0 && (p == *(out.vertices_end() - 1) || p == *out.vertices_begin())) continue;
      out.push_back(p);
    }
    // Collinear runs (from the slab clip or an edge-on portal) are dropped: a convex polygon
    // without them is simple exactly when it still has three vertices.
    std::vector<Point> pts(out.vertices_begin(), out.vertices_end());
    for (bool changed = true; changed && pts.size() >= 3;) {
      changed = false;
      for (size_t i = 0; i < pts.size() && pts.size() >= 3; ++i) {
        const Point& a = pts[(i + pts.size() - 1) % pts.size()];
        const Point& c = pts[(i + 1) % pts.size()];
        if (CGAL::orientation(a, pts[i], c) == CGAL::COLLINEAR) {
          pts.erase(pts.begin() + std::ptrdiff_t(i));
          changed = true;
          break;
        }
      }
    }
    if (pts.size() < 3) return false;
    out = Polygon(pts.begin(), pts.end());
    if (!out.is_simple()) return false;
    if (out.orientation() == CGAL::CLOCKWISE) out.reverse_orientation();
    return true;
  }

  std::vector<PolygonSet> region_;  // of the last run, kept for measure()
  InstanceReach reach_;
  const World* reach_world_ = nullptr;
  std::vector<std::vector<std::vector<glm::dvec2>>> regions_out_;
};

}  // namespace

std::unique_ptr<CullMethod> make_exact_method() { return std::make_unique<ExactMethod>(); }

const std::vector<std::vector<std::vector<glm::dvec2>>>& exact_regions_of(const CullMethod& method) {
  return static_cast<const ExactMethod&>(method).regions();
}

}  // namespace lintel
