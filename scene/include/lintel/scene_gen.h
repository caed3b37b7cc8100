// Procedural scenes in the Lintel format: the default cottage, grids, rings and random cyclic
// cell graphs. Deterministic for a given seed (no global RNG, no platform-dependent distribution).
#pragma once

#include <lintel/scene_desc.h>

#include <cstdint>

namespace lintel {

struct CottageOptions {
  uint64_t seed = 1;
};

struct GridOptions {
  uint32_t width = 4;   // rooms along X, 1..64
  uint32_t height = 4;  // rooms along Z, 1..64
  bool jitter = false;  // random rotation of every cell frame (geometry unchanged in world space)
  uint64_t seed = 1;
};

struct RingOptions {
  uint32_t cells = 8;  // 2..1024 rooms in a loop
  uint64_t seed = 1;
};

struct RandomOptions {
  uint32_t cells = 12;  // 2..4096
  uint64_t seed = 1;
};

SceneDesc generate_cottage(const CottageOptions& options);
SceneDesc generate_grid(const GridOptions& options);
SceneDesc generate_ring(const RingOptions& options);
SceneDesc generate_random(const RandomOptions& options);

}  // namespace lintel
