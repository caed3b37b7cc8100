// Random growth: pick a random frontier entry, take its lattice cell if still free and remember
// where it came from. Frontier order and picks come from the generator's own RNG only.
#include "generate/random_lattice.h"

#include "generate/building_plan.h"

#include <cassert>
#include <cmath>

namespace lintel::gen {

Lattice grow_lattice(uint32_t cells, uint32_t storeys, GenRandom& rng) {
  assert(cells >= 2 && storeys >= 1);
  // Half as many lattice cells again as rooms, so the shape is irregular but compact.
  const uint32_t ny = storeys;
  const uint32_t per_storey = (cells * 3 / 2 + ny - 1) / ny;
  const auto n = std::max<uint32_t>(2, uint32_t(std::ceil(std::sqrt(double(per_storey)))));
  const uint32_t nx = n, nz = n;
  Lattice out;
  out.x = {0.0};
  out.z = {0.0};
  out.y = {-0.5 * kSlabThickness};
  for (uint32_t i = 0; i < nx; ++i) out.x.push_back(out.x.back() + rng.uniform(3.0, 6.0));
  for (uint32_t i = 0; i < nz; ++i) out.z.push_back(out.z.back() + rng.uniform(3.0, 6.0));
  for (uint32_t i = 0; i < ny; ++i) out.y.push_back(out.y.back() + rng.uniform(2.4, 3.0) + kSlabThickness);

  auto slot = [&](uint32_t ix, uint32_t iy, uint32_t iz) { return size_t((iy * nz + iz) * nx + ix); };
  std::vector<int> room_at(size_t(nx) * ny * nz, -1);
  std::vector<int> parent;
  struct Candidate {
    uint32_t ix, iy, iz;
    int from;
  };
  std::vector<Candidate> frontier{{nx / 2, 0, nz / 2, -1}};
  while (out.cells.size() < cells) {
    assert(!frontier.empty());
    const size_t pick = rng.below(uint32_t(frontier.size()));
    const Candidate c = frontier[pick];
    frontier[pick] = frontier.back();
    frontier.pop_back();
    if (room_at[slot(c.ix, c.iy, c.iz)] >= 0) continue;
    const int index = int(out.cells.size());
    room_at[slot(c.ix, c.iy, c.iz)] = index;
    out.cells.push_back({c.ix, c.iy, c.iz});
    parent.push_back(c.from);
    if (c.ix > 0) frontier.push_back({c.ix - 1, c.iy, c.iz, index});
    if (c.ix + 1 < nx) frontier.push_back({c.ix + 1, c.iy, c.iz, index});
    if (c.iz > 0) frontier.push_back({c.ix, c.iy, c.iz - 1, index});
    if (c.iz + 1 < nz) frontier.push_back({c.ix, c.iy, c.iz + 1, index});
    if (c.iy > 0) frontier.push_back({c.ix, c.iy - 1, c.iz, index});
    if (c.iy + 1 < ny) frontier.push_back({c.ix, c.iy + 1, c.iz, index});
  }

  for (size_t i = 0; i < out.cells.size(); ++i) {
    const LatticeCell& c = out.cells[i];
    const uint32_t next[3][3] = {{c.ix + 1, c.iy, c.iz}, {c.ix, c.iy + 1, c.iz}, {c.ix, c.iy, c.iz + 1}};
    for (int axis = 0; axis < 3; ++axis) {
      const uint32_t* p = next[axis];
      if (p[0] >= nx || p[1] >= ny || p[2] >= nz) continue;
      const int j = room_at[slot(p[0], p[1], p[2])];
      if (j < 0) continue;
      Adjacency adj;
      adj.a = int(i);
      adj.b = j;
      adj.axis = axis;
      adj.tree = parent[size_t(j)] == int(i) || parent[i] == j;
      adj.tree_parent_is_b = parent[i] == j;
      out.adjacencies.push_back(adj);
    }
  }
  return out;
}

}  // namespace lintel::gen
