// Grid decomposition of a face with holes, and the reveals around each hole split at the same
// coordinates as the grid, so that reveal and face share whole edges.
#include "generate/wall_panel.h"

#include <algorithm>
#include <cassert>

namespace lintel::gen {
namespace {

const PanelHole* hole_at(const WallPanel& panel, double a, double b) {
  for (const PanelHole& h : panel.holes)
    if (a > h.a0 && a < h.a1 && b > h.b0 && b < h.b1) return &h;
  return nullptr;
}

void emit_reveals(const WallPanel& panel, const PanelHole& h, ShellMesh& out) {
  const auto& A = panel.a_splits;
  const auto& B = panel.b_splits;
  auto quad = [&](double a0, double b0, double a1, double b1, const glm::dvec3& n) {
    // An edge of the hole from (a0, b0) to (a1, b1), extruded from the face to the mid-plane.
    out.add_quad(panel.point(a0, b0, false), panel.point(a1, b1, false), panel.point(a1, b1, true),
                 panel.point(a0, b0, true), n);
  };
  for (size_t j = 0; j + 1 < B.size(); ++j) {
    if (B[j] < h.b0 || B[j + 1] > h.b1) continue;
    quad(h.a0, B[j], h.a0, B[j + 1], panel.axis_a);
    quad(h.a1, B[j], h.a1, B[j + 1], -panel.axis_a);
  }
  for (size_t i = 0; i + 1 < A.size(); ++i) {
    if (A[i] < h.a0 || A[i + 1] > h.a1) continue;
    quad(A[i], h.b0, A[i + 1], h.b0, panel.axis_b);
    quad(A[i], h.b1, A[i + 1], h.b1, -panel.axis_b);
  }
}

}  // namespace

std::vector<double> splits_within(std::vector<double> values, double lo, double hi) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  values.erase(std::remove_if(values.begin(), values.end(), [&](double v) { return v < lo || v > hi; }), values.end());
  return values;
}

void emit_panel(const WallPanel& panel, ShellMesh& out) {
  const auto& A = panel.a_splits;
  const auto& B = panel.b_splits;
  assert(A.size() >= 2 && B.size() >= 2);
  for (const PanelHole& h : panel.holes) {
    assert(std::find(A.begin(), A.end(), h.a0) != A.end() && std::find(A.begin(), A.end(), h.a1) != A.end());
    assert(std::find(B.begin(), B.end(), h.b0) != B.end() && std::find(B.begin(), B.end(), h.b1) != B.end());
    assert(h.a0 > A.front() || h.kind == PanelHole::Kind::Cutout);
    (void)h;
  }
  for (size_t j = 0; j + 1 < B.size(); ++j)
    for (size_t i = 0; i + 1 < A.size(); ++i) {
      const double a0 = A[i], a1 = A[i + 1], b0 = B[j], b1 = B[j + 1];
      const PanelHole* hole = hole_at(panel, 0.5 * (a0 + a1), 0.5 * (b0 + b1));
      const bool plug = hole && hole->kind == PanelHole::Kind::Plugged;
      if (hole && !plug) continue;
      out.add_quad(panel.point(a0, b0, plug), panel.point(a1, b0, plug), panel.point(a1, b1, plug),
                   panel.point(a0, b1, plug), panel.normal);
    }
  for (const PanelHole& h : panel.holes)
    if (h.kind != PanelHole::Kind::Cutout) emit_reveals(panel, h, out);
}

}  // namespace lintel::gen
