// Procedural scenes in the Lintel format: the default cottage, grids, rings and random cyclic
// cell graphs. Deterministic for a given seed (no global RNG, no platform-dependent distribution).
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/view.h>

#include <cstdint>
#include <vector>

namespace lintel {

struct CottageOptions {
  uint64_t seed = 1;
};

struct GridOptions {
  uint32_t width = 4;   // rooms along X, 1..64
  uint32_t height = 4;  // rooms along Z, 1..64
  bool jitter = false;  // random rotation of every cell frame (geometry unchanged in world space)
  uint64_t seed = 1;
  // The opening in every shared wall, centred along the wall: width, height and sill above the
  // floor (m). The defaults are a door; the stability suite's tiny portals are 1 mm windows.
  // Width in (0, 3.4], height in (0, 2.4 - sill], sill >= 0.
  double door_width_m = 0.9;
  double door_height_m = 2.1;
  double door_sill_m = 0.0;
};

struct RingOptions {
  uint32_t cells = 8;  // 2..1024 rooms in a loop
  uint64_t seed = 1;
};

// Linked portals (generate_links.cpp): a row of rooms closed into a ring by a teleport seam, plus
// a teleporter pair; and a hall with facing mirrors.
struct TeleportOptions {
  uint32_t cells = 4;  // 3..64 rooms in the row
};
struct MirrorOptions {};

// The closed-shell house (generate_house.cpp): 3 x 3 single-sided closed rooms whose walls lie back
// to back, tilted, random cell frames, a lamp in most rooms -- the renderer's sidedness and
// light-count case (docs/rendering.md).
struct HouseOptions {
  uint64_t seed = 1;  // picks the cell frames
};

// Rooms of random sizes on a random connected part of a lattice (several storeys joined by holes
// in the slabs), a spanning tree of doors and holes plus extra doors, windows and holes that make
// cycles (some one-way), every cell frame arbitrary and compensated in the vertices.
struct RandomOptions {
  uint32_t cells = 12;  // 2..4096
  uint64_t seed = 1;
  uint32_t storeys = 2;                 // lattice levels, >= 1
  double extra_portal_fraction = 0.35;  // share of non-tree neighbour pairs given an extra opening (>= 1 always)
  double window_fraction = 0.5;         // share of extra wall openings that are windows (the rest doors)
  double one_way_fraction = 0.15;       // share of extra openings that are one-way portals
  double volume_fraction = 0.5;         // share of cells with a volume node (the rest use their shell's box)
  double max_offset_m = 1e4;            // cell frame origin up to this far from its room, per axis
  double min_scale = 0.1;               // cell frame scales, log-uniform per axis (half the cells uniform)
  double max_scale = 10.0;
  bool global_rotation = true;       // whole building under a random rotation about any axis
  double max_global_offset_m = 1e3;  // and a translation up to this far, per axis
};

SceneDesc generate_cottage(const CottageOptions& options);
SceneDesc generate_grid(const GridOptions& options);
SceneDesc generate_ring(const RingOptions& options);
SceneDesc generate_random(const RandomOptions& options);
SceneDesc generate_teleport(const TeleportOptions& options);
SceneDesc generate_mirror(const MirrorOptions& options);
// `views`, when given, receives the house's inspection cameras (aspect left at its default), the
// same as its `inspect` timeline holds but with the house's tilted up vector.
SceneDesc generate_house(const HouseOptions& options, std::vector<View>* views = nullptr);

}  // namespace lintel
