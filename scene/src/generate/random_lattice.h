// The random generator's floor plan: a lattice with random column widths, row depths and storey
// heights (mid-plane coordinates), a connected random subset of its cells grown from one root,
// and every pair of neighbouring chosen cells, marked when the growth used it (a spanning tree).
#pragma once

#include "generate/gen_random.h"

#include <cstdint>
#include <vector>

namespace lintel::gen {

struct LatticeCell {
  uint32_t ix = 0, iy = 0, iz = 0;  // iy: storey
};

struct Adjacency {
  int a = -1, b = -1;  // cell indices; b is a's neighbour towards +axis
  int axis = 0;        // 0: X (a wall x = const), 1: Y (a slab), 2: Z (a wall z = const)
  bool tree = false;   // the growth came through here
  bool tree_parent_is_b = false;
};

struct Lattice {
  std::vector<double> x, y, z;         // mid-plane coordinates, one more than cells along each axis
  std::vector<LatticeCell> cells;      // cells[0] is the root
  std::vector<Adjacency> adjacencies;  // sorted by (a, axis)
};

// `cells` >= 2 rooms on `storeys` >= 1 levels. Columns and rows 3-6 m, rooms 2.4-3.0 m high
// inside, slabs and walls kSlabThickness / kWallThickness thick.
Lattice grow_lattice(uint32_t cells, uint32_t storeys, GenRandom& rng);

}  // namespace lintel::gen
