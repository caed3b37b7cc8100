// Builds the scene pool of the visibility properties (see world_pool.h).
#include "world_pool.h"

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <cstdio>
#include <cstdlib>

namespace lintel::fuzz {
namespace {

uint64_t mix(uint64_t x) {  // splitmix64 finalizer: decorrelates consecutive seeds
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

std::vector<std::unique_ptr<PoolScene>> make_world_pool(size_t count, uint64_t seed, uint32_t max_cells) {
  std::vector<std::unique_ptr<PoolScene>> pool;
  for (size_t i = 0; i < count; ++i) {
    const uint64_t s = mix(seed + i);
    auto scene = std::make_unique<PoolScene>();
    switch (i % 6) {
      case 0: {  // jittered grid: many 4-cycles
        GridOptions o;
        o.width = 1 + uint32_t(s % 4);
        o.height = 2 + uint32_t((s >> 8) % 3);
        o.jitter = true;
        o.seed = s;
        scene->desc = generate_grid(o);
        scene->label = "grid --width " + std::to_string(o.width) + " --height " + std::to_string(o.height) +
                       " --jitter --seed " + std::to_string(s);
        break;
      }
      case 1: {  // ring: one long cycle
        RingOptions o;
        o.cells = 2 + uint32_t(s % std::max<uint32_t>(2, max_cells - 1));
        o.seed = s;
        scene->desc = generate_ring(o);
        scene->label = "ring --cells " + std::to_string(o.cells) + " --seed " + std::to_string(s);
        break;
      }
      default: {  // random cyclic graph with arbitrary frames
        RandomOptions o;
        o.cells = 2 + uint32_t(s % std::max<uint32_t>(2, max_cells - 1));
        o.seed = s;
        scene->desc = generate_random(o);
        scene->label = "random --cells " + std::to_string(o.cells) + " --seed " + std::to_string(s);
        break;
      }
    }
    if (Status st = build_world(scene->desc, scene->label, scene->world); !st) {
      std::fprintf(stderr, "world pool: %s does not load: %s\n", scene->label.c_str(), st.message().c_str());
      std::abort();
    }
    if (Status st = scene->rays.build(scene->world); !st) {
      std::fprintf(stderr, "world pool: %s: %s\n", scene->label.c_str(), st.message().c_str());
      std::abort();
    }
    pool.push_back(std::move(scene));
  }
  return pool;
}

SceneDesc rigidly_moved(const SceneDesc& desc, const glm::dquat& rotation, const glm::dvec3& translation) {
  SceneDesc moved = desc;
  for (NodeDesc& node : moved.nodes) {
    if (node.parent >= 0) continue;
    node.translation = glm::vec3(rotation * glm::dvec3(node.translation) + translation);
    node.rotation = glm::quat(glm::normalize(rotation * glm::dquat(node.rotation)));
  }
  for (Timeline& t : moved.timelines)
    for (TimelineKey& k : t.keys) {
      k.eye_world = glm::vec3(rotation * glm::dvec3(k.eye_world) + translation);
      k.target_world = glm::vec3(rotation * glm::dvec3(k.target_world) + translation);
    }
  return moved;
}

}  // namespace lintel::fuzz
