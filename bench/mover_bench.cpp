// Moving instances per frame: DynamicInstances::move for 1,000 instances (membership
// by centre crossings, reach re-derived), take_moved(), and the builder's CPU-cull update
// (instances_moved), on the generated 32 x 32 grid (1,024 rooms, triangle volumes) with 1,000
// boxes walking to and fro through doors (worst case) or circling inside their rooms (the common
// case). Also closing and opening a door (O(1)).
// Run: build/bin/mover_bench (docs/perf.md has the figures and the exact command).
#include <lintel/dynamic_instances.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr uint32_t kGrid = 32;
constexpr uint32_t kMovers = 1000;
constexpr size_t kFrames = 1200;  // 20 s of precomputed transforms per mover, then the loop repeats

struct MoverScene {
  lintel::World world;
  std::vector<uint32_t> movers;                        // instance indices
  std::vector<std::vector<glm::mat4>> frames;          // [frame][mover]: to and fro through doors
  std::vector<std::vector<glm::mat4>> frames_in_room;  // [frame][mover]: circles inside the room
};

// The generated grid plus kMovers boxes (0.3 m cubes). Mover m walks to and fro between the
// centres of the two rooms of portal (m * 7919) mod portals, through the door's centre, at
// 0.5..2.5 m/s (60 fps frames): every mover crosses a doorway every few seconds (a worst case for
// crossings and reach changes; a real level moves most objects within their rooms).
MoverScene& scene() {
  static MoverScene s = [] {
    MoverScene out;
    const lintel::SceneDesc desc = lintel::generate_grid({kGrid, kGrid, false, 1});
    if (lintel::Status st = lintel::build_world(desc, "grid32x32", out.world); !st) {
      std::fprintf(stderr, "%s\n", st.message().c_str());
      std::abort();
    }
    lintel::World& w = out.world;
    lintel::Mesh box;
    box.name = "mover_box";
    box.bounds_mesh.extend(glm::vec3(-0.15f));
    box.bounds_mesh.extend(glm::vec3(0.15f));
    w.meshes.push_back(box);
    w.groups.push_back({uint32_t(w.meshes.size() - 1), {}});
    std::vector<std::array<glm::vec3, 3>> legs(kMovers);  // from-room centre, door centre, to-room centre
    auto room_centre = [&](uint32_t cell, float y) {
      glm::vec3 c = lintel::transform_aabb(w.cells[cell].cell_to_world, w.cells[cell].volume_box_cell).center();
      c.y = y;
      return c;
    };
    for (uint32_t m = 0; m < kMovers; ++m) {
      const lintel::Portal& p = w.portals[(m * 7919u) % uint32_t(w.portals.size())];
      const glm::vec3 door = p.centroid_world;
      legs[m] = {room_centre(p.from, door.y), door, room_centre(p.to, door.y)};
      lintel::Instance inst;
      inst.name = "mover" + std::to_string(m);
      inst.cell = p.from;
      inst.mesh = uint32_t(w.meshes.size() - 1);
      inst.group = uint32_t(w.groups.size() - 1);
      inst.mesh_to_world = glm::translate(glm::mat4(1.0f), legs[m][0]);
      out.movers.push_back(uint32_t(w.instances.size()));
      w.instances.push_back(inst);
    }
    if (lintel::Status st = lintel::finalize_world(w); !st) std::abort();
    out.frames.assign(kFrames, std::vector<glm::mat4>(kMovers));
    out.frames_in_room.assign(kFrames, std::vector<glm::mat4>(kMovers));
    for (uint32_t m = 0; m < kMovers; ++m) {
      const auto& [a, door, b] = legs[m];
      const float length = glm::length(door - a) + glm::length(b - door), speed = 0.5f + 2.0f * float(m % 5) / 4.0f;
      for (size_t f = 0; f < kFrames; ++f) {
        // Triangle wave along the two legs, phase-shifted per mover.
        float d = std::fmod(speed * float(f) / 60.0f + 0.37f * float(m), 2.0f * length);
        if (d > length) d = 2.0f * length - d;
        const float first = glm::length(door - a);
        const glm::vec3 at =
            d < first ? a + (door - a) * (d / first) : door + (b - door) * ((d - first) / (length - first));
        out.frames[f][m] = glm::translate(glm::mat4(1.0f), at);
        // The common case: a circle of radius 0.3..1 m about the room's centre, same speeds.
        const float radius = 0.3f + 0.7f * float(m % 8) / 7.0f, angle = speed / radius * float(f) / 60.0f + float(m);
        out.frames_in_room[f][m] =
            glm::translate(glm::mat4(1.0f), a + glm::vec3(radius * std::cos(angle), 0.0f, radius * std::sin(angle)));
      }
    }
    return out;
  }();
  return s;
}

// One iteration = one frame: move all kMovers instances, take_moved(), and (with_builder) the
// builder's CPU-cull update. The loop of frames repeats, so a mover's path is a closed circle.
void move_frame(benchmark::State& state, bool with_builder, bool through_doors) {
  MoverScene& s = scene();
  const std::vector<std::vector<glm::mat4>>& path = through_doors ? s.frames : s.frames_in_room;
  lintel::DynamicInstances movers;
  if (!movers.reset(s.world).ok()) std::abort();
  lintel::VisibilityBuilder builder;
  builder.prepare(s.world);
  size_t f = 0;
  uint64_t crossings = 0, frames = 0;
  for (auto _ : state) {
    const std::vector<glm::mat4>& frame = path[f];
    f = f + 1 == kFrames ? 0 : f + 1;
    for (uint32_t m = 0; m < kMovers; ++m) {
      (void)movers.move(s.world, s.movers[m], frame[m]);  // valid by construction
      crossings += movers.last_crossings().size();
    }
    benchmark::DoNotOptimize(movers.take_moved().data());
    if (with_builder) builder.instances_moved(s.world, movers);
    ++frames;
  }
  state.counters["movers"] = kMovers;
  state.counters["crossings_per_frame"] = double(crossings) / double(frames);
  state.counters["per_move"] =
      benchmark::Counter(double(frames) * kMovers, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Closing and opening a door: two flag writes, whatever the world's size.
void toggle_door(benchmark::State& state) {
  MoverScene& s = scene();
  uint32_t p = 0;
  for (auto _ : state) {
    s.world.set_portal_open(p, false);
    s.world.set_portal_open(p, true);
    benchmark::DoNotOptimize(s.world.portals[p].open_from_to);
    p = p + 1 == s.world.portals.size() ? 0 : p + 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("move_1000_instances/through_doors", [](benchmark::State& st) {
    move_frame(st, false, true);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("move_1000_instances_and_cpu_cull_update/through_doors", [](benchmark::State& st) {
    move_frame(st, true, true);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("move_1000_instances/within_rooms", [](benchmark::State& st) {
    move_frame(st, false, false);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("move_1000_instances_and_cpu_cull_update/within_rooms", [](benchmark::State& st) {
    move_frame(st, true, false);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("close_and_open_a_door", toggle_door)->Unit(benchmark::kNanosecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
