// Box-built furniture. Each piece is a union of axis-aligned boxes; overlapping boxes (a leg under
// a table top) only hide faces inside the solid, which no ray from the room can reach.
#include "generate/furniture_meshes.h"
#include "generate/building_plan.h"

#include "generate/shell_mesh.h"

#include <algorithm>

namespace lintel::gen {
namespace {

void add_box(ShellMesh& m, glm::dvec3 lo, glm::dvec3 hi) {
  const glm::dvec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                           {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  m.add_quad(c[0], c[3], c[7], c[4], {-1, 0, 0});
  m.add_quad(c[1], c[5], c[6], c[2], {1, 0, 0});
  m.add_quad(c[0], c[4], c[5], c[1], {0, -1, 0});
  m.add_quad(c[3], c[2], c[6], c[7], {0, 1, 0});
  m.add_quad(c[0], c[1], c[2], c[3], {0, 0, -1});
  m.add_quad(c[4], c[7], c[6], c[5], {0, 0, 1});
}

MeshDesc to_mesh(const char* name, const ShellMesh& m, glm::vec4 color) {
  MeshDesc out;
  out.name = name;
  out.base_color = color;
  for (const glm::dvec3& p : m.positions()) out.positions.emplace_back(p);
  for (const glm::dvec3& n : m.normals()) out.normals.emplace_back(n);
  out.indices = m.indices();
  return out;
}

// Four legs of side `leg` under a top of half extents (hx, hz), height h.
void add_legs(ShellMesh& m, double hx, double hz, double h, double leg) {
  for (int sx = -1; sx <= 1; sx += 2)
    for (int sz = -1; sz <= 1; sz += 2) {
      const double x = sx * (hx - leg), z = sz * (hz - leg);
      add_box(m, {x - 0.5 * leg, 0.0, z - 0.5 * leg}, {x + 0.5 * leg, h, z + 0.5 * leg});
    }
}

}  // namespace

MeshDesc make_table(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.6, 0.71, -0.4}, {0.6, 0.75, 0.4});
  add_legs(m, 0.6, 0.4, 0.71, 0.06);
  return to_mesh("table", m, color);
}

MeshDesc make_chair(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.225, 0.42, -0.225}, {0.225, 0.46, 0.225});
  add_box(m, {-0.225, 0.46, -0.225}, {0.225, 0.95, -0.185});
  add_legs(m, 0.225, 0.225, 0.42, 0.04);
  return to_mesh("chair", m, color);
}

MeshDesc make_bed(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.7, 0.0, -1.0}, {0.7, 0.5, 1.0});
  add_box(m, {-0.7, 0.5, -1.0}, {0.7, 1.0, -0.92});
  return to_mesh("bed", m, color);
}

MeshDesc make_shelf(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.45, 0.0, -0.175}, {-0.43, 1.8, 0.175});
  add_box(m, {0.43, 0.0, -0.175}, {0.45, 1.8, 0.175});
  add_box(m, {-0.43, 0.0, -0.175}, {0.43, 1.8, -0.155});
  for (int i = 0; i < 5; ++i) {
    const double y = 0.05 + i * 0.43;
    add_box(m, {-0.43, y - 0.02, -0.155}, {0.43, y, 0.175});
  }
  return to_mesh("shelf", m, color);
}

MeshDesc make_sofa(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.9, 0.0, -0.4}, {0.9, 0.42, 0.4});
  add_box(m, {-0.9, 0.42, -0.4}, {0.9, 0.8, -0.22});
  add_box(m, {-0.9, 0.42, -0.22}, {-0.75, 0.62, 0.4});
  add_box(m, {0.75, 0.42, -0.22}, {0.9, 0.62, 0.4});
  return to_mesh("sofa", m, color);
}

MeshDesc make_crate(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.3, 0.0, -0.3}, {0.3, 0.6, 0.3});
  return to_mesh("crate", m, color);
}

MeshDesc make_door_leaf(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {0.0, 0.0, -kDoorWidth}, {0.04, kDoorHeight, 0.0});
  return to_mesh("door_leaf", m, color);
}

MeshDesc make_tree(glm::vec4 color) {
  ShellMesh m;
  add_box(m, {-0.15, 0.0, -0.15}, {0.15, 2.0, 0.15});
  add_box(m, {-1.0, 2.0, -1.0}, {1.0, 4.0, 1.0});
  return to_mesh("tree", m, color);
}

MeshDesc make_stair(glm::vec4 color, int steps, double run, double height, double width) {
  ShellMesh m;
  const double w = 0.5 * width, dx = run / steps, dy = height / steps;
  // Each step is a solid column from the floor to its tread: risers, treads and both sides are
  // the column faces that stay outside the solid.
  for (int i = 0; i < steps; ++i) {
    const double x0 = i * dx, x1 = (i + 1) * dx, top = (i + 1) * dy, below = i * dy;
    m.add_quad({x0, top, -w}, {x1, top, -w}, {x1, top, w}, {x0, top, w}, {0, 1, 0});       // tread
    m.add_quad({x0, below, -w}, {x0, top, -w}, {x0, top, w}, {x0, below, w}, {-1, 0, 0});  // riser
    m.add_quad({x0, 0, -w}, {x1, 0, -w}, {x1, top, -w}, {x0, top, -w}, {0, 0, -1});        // sides
    m.add_quad({x0, 0, w}, {x0, top, w}, {x1, top, w}, {x1, 0, w}, {0, 0, 1});
  }
  m.add_quad({run, 0, -w}, {run, height, -w}, {run, height, w}, {run, 0, w}, {1, 0, 0});  // back
  m.add_quad({0, 0, -w}, {run, 0, -w}, {run, 0, w}, {0, 0, w}, {0, -1, 0});               // bottom
  return to_mesh("stair", m, color);
}

glm::dvec3 mesh_extent(const MeshDesc& mesh) {
  glm::dvec3 e(0.0);
  for (const glm::vec3& p : mesh.positions) {
    e.x = std::max(e.x, std::abs(double(p.x)));
    e.z = std::max(e.z, std::abs(double(p.z)));
    e.y = std::max(e.y, double(p.y));
  }
  return e;
}

}  // namespace lintel::gen
