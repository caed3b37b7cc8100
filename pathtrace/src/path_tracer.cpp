// PathTracer: the camera, the pixel loop and its threads. Rows are handed out through an atomic
// counter, and every pixel draws its random numbers from its own stream seeded by (seed, pixel
// index), so the image is the same whichever thread renders which row.
#include <lintel/reference/path_tracer.h>

#include "embree_scene.h"
#include "path_radiance.h"
#include "path_sampling.h"
#include "punctual_light.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <mutex>
#include <thread>

namespace lintel {

struct PathTracer::Impl {
  pathtrace_detail::EmbreeScene scene;
  std::vector<pathtrace_detail::PunctualLight> lights;
  glm::vec3 environment{0.0f};
  std::vector<Portal> linked_portals;  // World::portals that are linked (mirrors, teleports)
};

PathTracer::PathTracer() = default;
PathTracer::~PathTracer() = default;
PathTracer::PathTracer(PathTracer&&) noexcept = default;
PathTracer& PathTracer::operator=(PathTracer&&) noexcept = default;

Status PathTracer::build(const World& world) {
  auto impl = std::make_unique<Impl>();
  impl->lights.resize(world.lights.size());
  for (size_t i = 0; i < world.lights.size(); ++i) {
    if (Status s = pathtrace_detail::prepare_light(world.lights[i], i, impl->lights[i]); !s) return s;
  }
  if (Status s = impl->scene.build(world); !s) return s;
  impl->environment = world.environment;
  for (const Portal& portal : world.portals)
    if (portal.linked()) impl->linked_portals.push_back(portal);
  impl_ = std::move(impl);
  return {};
}

namespace {

// The pinhole of view_projection() (glm::lookAtRH + perspectiveRH_ZO): the basis is computed in
// double as there, then rounded once.
struct PinholeCamera {
  glm::vec3 eye, forward, right_extent, up_extent;  // extents: the NDC = 1 offsets at unit depth

  explicit PinholeCamera(const View& view) {
    const glm::dvec3 f = glm::normalize(glm::dvec3(view.target_world) - glm::dvec3(view.eye_world));
    const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(view.up_world)));
    const glm::dvec3 u = glm::cross(s, f);
    const double tan_half = std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
    eye = view.eye_world;
    forward = glm::vec3(f);
    right_extent = glm::vec3(s * (tan_half * double(view.aspect)));
    up_extent = glm::vec3(u * tan_half);
  }
  glm::vec3 direction(float ndc_x, float ndc_y) const {
    return glm::normalize(forward + ndc_x * right_extent + ndc_y * up_extent);
  }
};

}  // namespace

void PathTracer::render(const View& view, const PathTraceOptions& options, LinearImage& out) const {
  assert(impl_ && "build() must succeed first");
  assert(validate_view(view).ok());
  assert(options.width >= 1 && options.height >= 1 && options.samples_per_pixel >= 1);
  const uint32_t width = options.width, height = options.height, spp = options.samples_per_pixel;
  out.width = width;
  out.height = height;
  out.rgb.assign(size_t{width} * height, glm::vec3(0.0f));
  const PinholeCamera camera(view);
  const Impl& impl = *impl_;

  std::atomic<uint32_t> next_row{0};
  std::mutex progress_mutex;
  uint32_t rows_done = 0;  // guarded by progress_mutex
  // Texture filtering: a pixel's angle at the image centre, 2 tan(fov_y / 2) / height (Ray
  // Tracing Gems, ch. 20), for every pixel.
  const float pixel_spread = 2.0f * glm::length(camera.up_extent) / float(height);
  const pathtrace_detail::PathSettings settings{options.max_bounces, options.light_connections, impl.environment,
                                                pixel_spread, impl.linked_portals};
  const auto work = [&] {
    std::vector<pathtrace_detail::LightVertex> light_vertices;  // this thread's scratch
    for (uint32_t y; (y = next_row.fetch_add(1, std::memory_order_relaxed)) < height;) {
      for (uint32_t x = 0; x < width; ++x) {
        const uint64_t pixel = uint64_t{y} * width + x;
        pathtrace_detail::PixelRng rng(options.seed, pixel);
        glm::dvec3 sum(0.0);  // double: 256+ samples of very different size sum without drift
        for (uint32_t s = 0; s < spp; ++s) {
          const float jx = rng.uniform(), jy = rng.uniform();
          const float ndc_x = (float(x) + jx) / float(width) * 2.0f - 1.0f;
          const float ndc_y = 1.0f - (float(y) + jy) / float(height) * 2.0f;
          sum += glm::dvec3(pathtrace_detail::path_radiance(
              impl.scene, impl.lights, camera.eye, camera.direction(ndc_x, ndc_y), settings, rng, light_vertices));
        }
        out.rgb[pixel] = glm::vec3(sum / double(spp));
      }
      if (options.progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        options.progress(++rows_done, height);
      }
    }
  };

  unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
  threads = std::clamp(threads, 1u, height);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();  // the calling thread renders too
  for (std::thread& t : pool) t.join();
}

}  // namespace lintel
