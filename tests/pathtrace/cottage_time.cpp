// Renders the cottage reference at the settings (160 x 90, 256 samples, 4 bounces) from
// the middle of its first timeline and prints the wall time: the cost of one reference image on
// this machine. Not a test. Usage: pathtrace_cottage_time [threads] [out.pfm] [plain]
// ("plain" turns light connections off, to compare the two estimators' cost).
#include <lintel/reference/path_tracer.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

int main(int argc, char** argv) {
  lintel::World world;
  const std::string path = LINTEL_SOURCE_DIR "/scenes/cottage.gltf";
  if (lintel::Status s = lintel::load_world(path, world); !s) {
    std::fprintf(stderr, "pathtrace_cottage_time: %s\n", s.message().c_str());
    return 2;
  }
  const lintel::Timeline& walk = world.timelines.at(0);
  const double t = 0.5 * (walk.keys.front().t + walk.keys.back().t);
  const lintel::View view = lintel::timeline_view(walk, t);
  lintel::PathTraceOptions options;  // the defaults are the settings
  if (argc > 1) options.threads = unsigned(std::atoi(argv[1]));
  if (argc > 3 && std::string(argv[3]) == "plain") options.light_connections = false;
  const unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
  const auto t0 = std::chrono::steady_clock::now();
  lintel::PathTracer tracer;
  if (lintel::Status s = tracer.build(world); !s) {
    std::fprintf(stderr, "pathtrace_cottage_time: %s\n", s.message().c_str());
    return 2;
  }
  const auto t1 = std::chrono::steady_clock::now();
  lintel::LinearImage image;
  tracer.render(view, options, image);
  const auto t2 = std::chrono::steady_clock::now();
  double sum = 0.0;
  for (const glm::vec3& px : image.rgb) sum += double(px.x + px.y + px.z) / 3.0;
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::printf(
      "cottage timeline '%s' t=%.2f s: %ux%u, %u spp, %u bounces, %u threads, light connections %s: "
      "build %.1f ms, render %.1f ms, mean radiance %.5f\n",
      walk.name.c_str(), t, options.width, options.height, options.samples_per_pixel, options.max_bounces, threads,
      options.light_connections ? "on" : "off", ms(t0, t1), ms(t1, t2), sum / double(image.rgb.size()));
  if (argc > 2 && argv[2][0] != '\0') {  // PFM: little-endian float RGB, rows bottom to top
    std::FILE* f = std::fopen(argv[2], "wb");
    if (!f) return 2;
    std::fprintf(f, "PF\n%u %u\n-1.0\n", image.width, image.height);
    for (uint32_t y = image.height; y-- > 0;)
      std::fwrite(&image.rgb[size_t{y} * image.width], sizeof(glm::vec3), image.width, f);
    std::fclose(f);
  }
  return 0;
}
