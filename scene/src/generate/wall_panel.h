// One flat face of a shell (a wall, floor, ceiling, facade, ground or roof) with rectangular
// holes, as a grid of quads plus the reveals that line each hole from the face to the mid-plane.
// Using one grid for a face, with the same split coordinates as the faces it meets, leaves no
// T-junctions, so the shell is watertight wherever its faces meet.
#pragma once

#include "generate/shell_mesh.h"

#include <functional>
#include <vector>

namespace lintel::gen {

struct PanelHole {
  enum class Kind {
    Open,     // an opening: reveals from the face to the mid-plane, nothing across it
    Plugged,  // the far side of a one-way portal: reveals plus a plug on the mid-plane, so that
              // this cell cannot see out while the other side's rays stop at this cell's surface
    Cutout,   // simply not covered (the house's footprint in the exterior's ground plane)
  };
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0;
  Kind kind = Kind::Open;
};

struct WallPanel {
  // Sorted, unique; the first and last are the face's extent. Hole bounds must be among them.
  std::vector<double> a_splits, b_splits;
  std::vector<PanelHole> holes;
  glm::dvec3 normal{0.0};  // the face looks into the cell's air along this
  glm::dvec3 axis_a{0.0};  // unit directions of growing a and b, for the reveals' normals
  glm::dvec3 axis_b{0.0};
  // The point at face coordinates (a, b), on the face or (mid = true) on the mid-plane behind it.
  // Must be exact for shared corners: adjacent faces call it with identical doubles.
  std::function<glm::dvec3(double a, double b, bool mid)> point;
};

void emit_panel(const WallPanel& panel, ShellMesh& out);

// Sorts, removes duplicates, and keeps only values within [lo, hi].
std::vector<double> splits_within(std::vector<double> values, double lo, double hi);

}  // namespace lintel::gen
