// One scene's doorway-timeline builds, each after every cache was evicted (a game renders between
// two builds), for counting what a cold build misses: run it under callgrind's cache simulation,
// collecting in cold_build() only, and divide the LL misses by the build count. Deterministic,
// unlike a cold build's wall time on a shared machine (docs/perf.md, "Cold builds"):
//
//   valgrind --tool=callgrind --cache-sim=yes --I1=32768,8,64 --D1=32768,8,64
//     --LL=33554432,16,64 --toggle-collect='*cold_build*' build/bin/cold_build_probe ring 64 --builds 40
//   callgrind_annotate --show=Ir,ILmr,DLmr,DLmw callgrind.out.* | grep 'PROGRAM TOTALS'
//
// Without valgrind it prints the median wall time of the cold builds. --cold-data: after the
// eviction another builder builds the same frame first, so that the code and the World are warm
// again and only the timed builder's own data and its output are cold: what the polygon method
// meets in `lintel bench accuracy`, where the other polygon variants build the same view before it.
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Frame {
  lintel::View view;
  uint32_t cell = 0;
};

// Reads and writes one word per line of a buffer twice the last-level cache (32 MB here).
[[gnu::noinline]] void evict_caches(std::vector<uint64_t>& buffer) {
  uint64_t sum = 0;
  for (size_t i = 0; i < buffer.size(); i += 8) sum += buffer[i]++;
  asm volatile("" : : "r"(sum));
}

// The builds callgrind collects (--toggle-collect='*cold_build*').
[[gnu::noinline]] lintel::Status cold_build(lintel::VisibilityBuilder& builder, const lintel::World& world,
                                            const Frame& f, lintel::VisibleSet& out) {
  return builder.build(world, f.view, f.cell, {}, out);
}

int usage() {
  std::fprintf(stderr, "usage: cold_build_probe grid|ring|cottage [SIZE] [--builds N] [--cold-data]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string kind = argv[1];
  uint32_t size = 0, builds = 200;
  bool cold_data = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cold-data")
      cold_data = true;
    else if (a == "--builds" && i + 1 < argc)
      builds = uint32_t(std::strtoul(argv[++i], nullptr, 10));
    else
      size = uint32_t(std::strtoul(argv[i], nullptr, 10));
  }
  const bool known = kind == "cottage" || ((kind == "grid" || kind == "ring") && size >= 2 && size <= 256);
  if (builds == 0 || !known) return usage();
  const lintel::SceneDesc desc = kind == "grid"   ? lintel::generate_grid({size, size, false, 1})
                                 : kind == "ring" ? lintel::generate_ring({size, 1})
                                                  : lintel::generate_cottage({1});
  lintel::World world;
  if (const lintel::Status s = lintel::build_world(desc, kind, world); !s) {
    std::fprintf(stderr, "cold_build_probe: %s\n", s.message().c_str());
    return 1;
  }
  const lintel::Timeline& t = world.timelines[size_t(std::max(0, world.find_timeline("doorway")))];
  lintel::ViewerTracker tracker;
  std::vector<Frame> frames;
  for (size_t f = 0; f < lintel::timeline_frame_count(t); ++f) {
    Frame frame;
    frame.view = lintel::timeline_view(t, t.keys.front().t + double(f) / t.fps);
    const glm::vec3& eye = frame.view.eye_world;
    if (!(f == 0 ? tracker.reset(world, eye) : tracker.update(world, eye)).ok()) return 1;
    frame.cell = tracker.cell();
    frames.push_back(frame);
  }
  lintel::VisibilityBuilder builder, other;
  lintel::VisibleSet visible, other_visible;
  builder.prepare(world, {}, visible);
  other.prepare(world, {}, other_visible);
  for (const Frame& f : frames)  // warm-up: everything sized, every frame checked
    if (const lintel::Status s = builder.build(world, f.view, f.cell, {}, visible); !s) {
      std::fprintf(stderr, "cold_build_probe: %s\n", s.message().c_str());
      return 1;
    }
  std::vector<uint64_t> buffer(size_t(64) << 17);  // 64 MB
  std::vector<double> us;
  for (uint32_t i = 0; i < builds; ++i) {
    const Frame& f = frames[(size_t(i) * 7) % frames.size()];
    evict_caches(buffer);
    if (cold_data) (void)other.build(world, f.view, f.cell, {}, other_visible);
    const auto a = std::chrono::steady_clock::now();
    (void)cold_build(builder, world, f, visible);
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(us.begin(), us.end());
  std::printf("%s %u: %u cold builds, median %.2f us\n", kind.c_str(), size, builds, us[us.size() / 2]);
  return 0;
}
