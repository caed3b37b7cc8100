// CPU path tracer (Embree 3) that renders the reference images the realtime renderer's images are
// compared against (RMSE). Tests and benchmarks only: nothing a game links pulls it in.
//
// Conventions — the realtime renderer (render/) uses exactly these, so that the only difference
// between the two images is the realtime approximation, never a different model:
//   * Geometry: every cell's shell (World::meshes[cell.shell_mesh] under cell_to_world) and every
//     instance (under mesh_to_world). Portals are openings: they add no geometry. Every triangle
//     is opaque. Sidedness follows glTF as in the renderer: camera and bounce rays pass through
//     back faces of single-sided meshes (Mesh::double_sided false), shadow rays are blocked by
//     both faces. The shading normal is the triangle's geometric normal, flipped to face the
//     incoming ray (vertex normals are not used).
//   * Material: Lambertian, albedo = Mesh::base_color.rgb (linear), BRDF = albedo / pi. A mesh
//     with a base_color_texture multiplies that by the texture at the hit: the uv interpolated
//     from the triangle's vertex uvs with the hit's barycentrics, texels decoded from sRGB to
//     linear before filtering, uv (0, 0) = the image's top-left corner (the lintel::Texture
//     convention in world.h; alpha is ignored), read through the mesh's glTF sampler (wrap modes,
//     filters, mip mode: Mesh::base_color_sampler) as the renderer's g-buffer reads it, at the
//     level of detail of a ray cone: spread 2 tan(fov_y / 2) / height per metre from the eye
//     (from the light for light connections), kept through bounces (docs/rendering.md). Nothing
//     emits; a ray
//     that leaves the scene sees the uniform sky World::environment (0 unless the file names one
//     or has no lights), so otherwise light reaches a surface only from lights.
//   * Camera: lintel::View with the basis of view_projection() (view.h): forward = target - eye,
//     right = forward x up, up' = right x forward. Pixel (x, y) looks through NDC
//     ((x + u) / W * 2 - 1, 1 - (y + v) / H * 2) with (u, v) uniform in [0, 1)^2 per sample (the
//     pixel centre is u = v = 0.5); row 0 is the top. Rays start at the eye itself: near_m and
//     far_m do not clip (the only difference from a rasterizer, for geometry within near_m).
//   * Mirrors and teleports (linked portals, Portal::link_world): a camera ray that meets the
//     front of a linked portal's polygon before its hit goes on from link_world * x along
//     link_world * d (up to kMaxLinkDepth links), as the renderer draws the linked view; the
//     surface it then meets is lit as where it really is. Light, shadow and bounce rays treat
//     linked portals as the wall they hang on, as the renderer's lights and GI do
//     (Cell::linked_portals are not in Cell::links).
//   * Lights (KHR_lights_punctual, World::lights), radiant intensity I = color * intensity:
//       point:  E(x, n) = I * window(d) / d^2 * max(0, n.l), l = unit vector from x to the light,
//               d = distance, window(d) = range > 0 ? clamp(1 - (d / range)^4, 0, 1)^2 : 1;
//       spot:   the point formula times clamp(cd * scale + offset, 0, 1)^2 with
//               cd = dot(direction_world, -l), scale = 1 / max(0.001, cos(inner) - cos(outer)),
//               offset = -cos(outer) * scale;
//       directional: E(x, n) = color * intensity * max(0, n.l), l = -direction_world.
//     Every light is sampled at every path vertex with a shadow ray (next-event estimation); any
//     triangle blocks it. Lights are points: a camera or bounce ray never hits one.
//   * Indirect: cosine-weighted hemisphere sampling about the shading normal, up to max_bounces
//     bounces; no Russian roulette (max_bounces is small, and it would only add noise).
//     Outgoing radiance L(x) = albedo / pi * (E_direct(x) + E_indirect(x)).
//   * Noise, not the model: with light_connections (the default) every point and spot light also
//     emits one ray per sample and each path vertex connects to where it landed, weighted against
//     the cosine bounce by multiple importance sampling. The expected image is the same; the
//     noise of light that bounced off a surface close to a lamp (the ceiling 0.2 m above the
//     cottage's living-room lamp) drops several-fold (numbers in pathtrace/README.md).
// The result is linear radiance (no exposure, no tone mapping), the mean of samples_per_pixel
// jittered paths per pixel.
#pragma once

#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lintel {

struct PathTraceOptions {
  uint32_t width = 160, height = 90;  // pixels, >= 1 each
  uint32_t samples_per_pixel = 256;   // >= 1
  uint32_t max_bounces = 4;           // diffuse bounces after the first hit; 0 = direct light only
  // Each pixel's random numbers come from (seed, pixel index) alone, so an image is bit-for-bit
  // the same for a given seed whatever the thread count or scheduling.
  uint64_t seed = 1;
  unsigned threads = 0;  // 0 = std::thread::hardware_concurrency()
  // Light-vertex connections with MIS (see the conventions above). false: the plain cosine-bounce
  // path tracer with next-event estimation; same expectation, more noise.
  bool light_connections = true;
  // Optional. Called after each finished row, never concurrently (from worker threads, under a
  // lock), with rows_done increasing by one from 1 to rows_total.
  std::function<void(uint32_t rows_done, uint32_t rows_total)> progress;
};

// Linear radiance per pixel, row-major, row 0 = top: width * height entries.
struct LinearImage {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> rgb;
};

// Owns the Embree device and scene built from one World. Movable, not copyable.
class PathTracer {
 public:
  PathTracer();
  ~PathTracer();
  PathTracer(PathTracer&&) noexcept;
  PathTracer& operator=(PathTracer&&) noexcept;

  // Builds the acceleration structure and copies the materials, textures and lights of `world`
  // (which need not outlive this object). Fails on Embree errors, on non-finite light data and on
  // a textured mesh without one uv per position or with a texture index out of range.
  Status build(const World& world);

  // Renders `view` into `out` (resized to options.width x options.height). Allocates only `out`,
  // the threads and one light-vertex array per thread. Preconditions (asserted): build()
  // succeeded, validate_view(view).ok(), width, height and samples_per_pixel >= 1.
  void render(const View& view, const PathTraceOptions& options, LinearImage& out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lintel
