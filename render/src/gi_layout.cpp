// Deterministic surfel sampling (area-weighted triangle picks with a fixed-seed splitmix) and probe
// placement at cell-centred grid points of each cell's volume box.
#include "gi_layout.h"

#include "base_color.h"
#include "segment_occluders.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <cstring>

namespace lintel::render {
namespace {

// The coverage below which the GI takes a point as no surface (no surfel, light passes): a
// cut-out's alphaCutoff; for a see-through surface (BLEND), which the camera and the shadow maps
// draw through a screen-door dither, one half: the probes hold one value per point, so glass that
// mostly lets light through lets all of it through, and glass that mostly stops it stops it all.
float gi_alpha_cutoff(const Mesh& mesh) { return mesh.alpha_mode == Mesh::AlphaMode::Blend ? 0.5f : mesh.alpha_cutoff; }

uint64_t splitmix(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
float uniform01(uint64_t& state) { return float(splitmix(state) >> 40) * (1.0f / 16777216.0f); }

float bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

struct Triangle {
  glm::vec3 a, b, c, normal;
  float area;
  const Mesh* mesh = nullptr;  // for the base colour (texture) at the sample; null for portals
  glm::vec2 uv_a{0.0f}, uv_b{0.0f}, uv_c{0.0f};
  glm::vec4 color_a{1.0f}, color_b{1.0f}, color_c{1.0f};  // COLOR_0 (white without it)
  const TextureMips* texture = nullptr;                   // the mesh's base colour texture, or null
  float texels_per_m2 = 0.0f;                             // level-0 texels of `texture` per square metre here
  const TextureMips* emissive_texture = nullptr;          // the mesh's emissive texture, or null
  float emissive_texels_per_m2 = 0.0f;                    // the same for `emissive_texture`
};

// The world's textures as mip chains, each built the first time a surfel needs it. Sized once,
// so the pointers it hands out stay valid.
class TextureCache {
 public:
  explicit TextureCache(const World& world) : world_(world), mips_(world.textures.size()) {}
  const TextureMips* mips_of(int texture) {
    if (texture < 0 || size_t(texture) >= mips_.size()) return nullptr;
    const Texture& t = world_.textures[size_t(texture)];
    if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4) return nullptr;
    TextureMips& m = mips_[size_t(texture)];
    if (m.sizes.empty()) m = texture_mips(t);
    return &m;
  }

 private:
  const World& world_;
  std::vector<TextureMips> mips_;
};

void add_mesh_triangles(const World& world, uint32_t mesh_index, const glm::mat4& to_world, TextureCache& textures,
                        std::vector<Triangle>& out) {
  const Mesh& mesh = world.meshes[mesh_index];
  const bool has_uvs = mesh.uvs.size() == mesh.positions.size();
  const TextureMips* texture = has_uvs ? textures.mips_of(mesh.base_color_texture) : nullptr;
  const TextureMips* emissive_texture = has_uvs ? textures.mips_of(mesh.emissive_texture) : nullptr;
  const glm::mat3 nmat = glm::transpose(glm::inverse(glm::mat3(to_world)));
  // A mirroring transform turns the front faces clockwise (glTF 2.0, 3.7.4).
  const float winding = glm::determinant(glm::mat3(to_world)) < 0.0f ? -1.0f : 1.0f;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    Triangle tri;
    tri.a = glm::vec3(to_world * glm::vec4(mesh.positions[i0], 1.0f));
    tri.b = glm::vec3(to_world * glm::vec4(mesh.positions[i1], 1.0f));
    tri.c = glm::vec3(to_world * glm::vec4(mesh.positions[i2], 1.0f));
    const glm::vec3 cr = glm::cross(tri.b - tri.a, tri.c - tri.a);
    tri.area = 0.5f * glm::length(cr);
    if (!(tri.area > 1e-10f)) continue;
    tri.normal = winding * cr / (2.0f * tri.area);
    // Single-sided (glTF's default): the front face is the surface, the side the camera can see.
    // Double-sided: one surfel side, the one the file's normals face.
    if (mesh.double_sided && !mesh.normals.empty()) {
      const glm::vec3 vn = nmat * (mesh.normals[i0] + mesh.normals[i1] + mesh.normals[i2]);
      if (glm::dot(vn, tri.normal) < 0.0f) tri.normal = -tri.normal;
    }
    tri.mesh = &mesh;
    if (mesh.uvs.size() == mesh.positions.size()) {
      tri.uv_a = mesh.uvs[i0];
      tri.uv_b = mesh.uvs[i1];
      tri.uv_c = mesh.uvs[i2];
    }
    if (mesh.colors.size() == mesh.positions.size()) {
      tri.color_a = mesh.colors[i0];
      tri.color_b = mesh.colors[i1];
      tri.color_c = mesh.colors[i2];
    }
    const glm::vec2 du = tri.uv_b - tri.uv_a, dv = tri.uv_c - tri.uv_a;
    const float uv_area = 0.5f * std::abs(du.x * dv.y - du.y * dv.x);
    if (emissive_texture) {
      tri.emissive_texture = emissive_texture;
      tri.emissive_texels_per_m2 =
          uv_area * float(emissive_texture->sizes[0].x) * float(emissive_texture->sizes[0].y) / tri.area;
    }
    if (texture) {
      tri.texture = texture;
      tri.texels_per_m2 = uv_area * float(texture->sizes[0].x) * float(texture->sizes[0].y) / tri.area;
    }
    out.push_back(tri);
  }
}

// A uniform point on the triangle, as barycentric weights of b and c.
glm::vec2 sample_triangle(uint64_t& rng) {
  float u = uniform01(rng), v = uniform01(rng);
  if (u + v > 1.0f) {
    u = 1.0f - u;
    v = 1.0f - v;
  }
  return {u, v};
}

void add_surface_surfels(const std::vector<Triangle>& tris, uint32_t cell, uint32_t count, uint64_t& rng,
                         std::vector<GpuSurfel>& out) {
  if (tris.empty() || count == 0) return;
  std::vector<float> cdf(tris.size());
  float total = 0.0f;
  for (size_t i = 0; i < tris.size(); ++i) cdf[i] = (total += tris[i].area);
  for (uint32_t k = 0; k < count; ++k) {
    // Stratified picks along the area CDF: every large wall gets its share.
    const float x = (float(k) + uniform01(rng)) / float(count) * total;
    const size_t i = std::min(size_t(std::lower_bound(cdf.begin(), cdf.end(), x) - cdf.begin()), tris.size() - 1);
    const Triangle& t = tris[i];
    const glm::vec2 w = sample_triangle(rng);
    GpuSurfel s{};
    s.position_cell = glm::vec4(t.a + w.x * (t.b - t.a) + w.y * (t.c - t.a), bits(cell));
    const float area = total / float(count);
    s.normal_area = glm::vec4(t.normal, area);
    glm::vec3 albedo = t.mesh ? glm::vec3(t.mesh->base_color) : glm::vec3(0.0f);
    // The vertex colour at the sample, as the g-buffer interpolates it.
    const glm::vec4 color = t.color_a + w.x * (t.color_b - t.color_a) + w.y * (t.color_c - t.color_a);
    albedo *= glm::vec3(color);
    glm::vec4 texel(1.0f);
    if (t.texture) {
      // The surfel stands for `area` of the surface: its albedo is the texture over that
      // footprint, read from the mip level whose texels are about that size (the g-buffer's
      // lookup, base_color.h), not the one texel under its centre.
      const glm::vec2 uv = t.uv_a + w.x * (t.uv_b - t.uv_a) + w.y * (t.uv_c - t.uv_a);
      texel = sample_texture_rgba(*t.texture, t.mesh->base_color_sampler, uv, footprint_lod(area, t.texels_per_m2));
      albedo *= glm::vec3(texel);
    }
    // A cut-out has no surface where its coverage is below the cutoff: no surfel there (the
    // stratified picks of the others stay where they were). A see-through surface counts as one
    // with a cutoff of one half (gi_alpha_cutoff).
    if (t.mesh && t.mesh->alpha_mode != Mesh::AlphaMode::Opaque &&
        t.mesh->base_color.a * texel.a * color.a < gi_alpha_cutoff(*t.mesh))
      continue;
    s.albedo = glm::vec4(albedo, 1.0f);
    // What it gives off by itself: the emissive factor times the emissive texture over the
    // surfel's footprint (as the albedo above).
    glm::vec3 emission = t.mesh ? t.mesh->emissive : glm::vec3(0.0f);
    if (t.emissive_texture && emission != glm::vec3(0.0f)) {
      const glm::vec2 uv = t.uv_a + w.x * (t.uv_b - t.uv_a) + w.y * (t.uv_c - t.uv_a);
      emission *= sample_texture(*t.emissive_texture, t.mesh->emissive_sampler, uv,
                                 footprint_lod(area, t.emissive_texels_per_m2));
    }
    s.emission = glm::vec4(emission, 0.0f);
    out.push_back(s);
  }
}

void add_portal_surfels(const World& world, uint32_t cell, uint32_t per_portal, uint64_t& rng,
                        std::vector<GpuSurfel>& out) {
  for (const PortalLink& link : world.cells[cell].links) {
    const Portal& p = world.portals[link.portal];
    std::vector<Triangle> fan;
    for (size_t i = 1; i + 1 < p.polygon_world.size(); ++i) {
      Triangle t{p.polygon_world[0], p.polygon_world[i], p.polygon_world[i + 1], {}, 0.0f};
      t.area = 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a));
      if (t.area > 0.0f) fan.push_back(t);
    }
    const size_t first = out.size();
    add_surface_surfels(fan, cell, per_portal, rng, out);
    // Light comes through the portal from the neighbour, travelling into this cell.
    const glm::vec3 into_cell = p.from == cell ? -p.normal_world : p.normal_world;
    for (size_t i = first; i < out.size(); ++i) {
      out[i].normal_area = glm::vec4(into_cell, out[i].normal_area.w);
      out[i].albedo = glm::vec4(0.0f);
      // z: where the renderer writes whether the neighbour sees into this cell through the portal
      // (light travels as sight does, per direction: a closed door is a wall for light too).
      const uint32_t open_flag = uint32_t(world.cells.size()) + 2 * link.portal + (p.from == link.neighbour ? 0u : 1u);
      out[i].portal = glm::uvec4(link.neighbour, link.portal, open_flag, 0);
    }
  }
}

// World-space box of the cell's volume from its vertices (volume triangles, else the shell), not
// from the cell-space box, whose world image grows with the frame's rotation.
Aabb cell_volume_world(const World& world, const Cell& cell) {
  Aabb box;
  for (const glm::vec3& v : cell.volume_triangles_cell) box.extend(glm::vec3(cell.cell_to_world * glm::vec4(v, 1.0f)));
  if (box.empty() && cell.shell_mesh >= 0)
    for (const glm::vec3& v : world.meshes[size_t(cell.shell_mesh)].positions)
      box.extend(glm::vec3(cell.cell_to_world * glm::vec4(v, 1.0f)));
  if (box.empty() && !cell.volume_box_cell.empty()) box = transform_aabb(cell.cell_to_world, cell.volume_box_cell);
  if (box.empty()) box.extend(glm::vec3(cell.cell_to_world[3]));
  return box;
}

// Where a segment from a probe to a surfel ends: a little off the surfel's surface, so that
// surface cannot hide it, the lift scaled with the coordinates so float rounding far from the
// origin cannot put the end behind the surface. With, per end, whether it lies well inside the
// occluders' boundary planes (segment_occluders.h): computed once per cell, not per probe.
struct SurfelEnds {
  std::vector<glm::vec3> at;
  std::vector<uint8_t> inside;
};

SurfelEnds surfel_ends(const SegmentOccluders& scene, const GpuSurfel* surfels, uint32_t count) {
  SurfelEnds ends;
  ends.at.resize(count);
  ends.inside.resize(count);
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec3 at(surfels[k].position_cell), n(surfels[k].normal_area), a = glm::abs(at);
    ends.at[k] = at + n * std::max(1e-2f, 4e-6f * std::max(a.x, std::max(a.y, a.z)));
    ends.inside[k] = scene.inside_boundary(ends.at[k]);
  }
  return ends;
}

// Whether the surfel faces `x` (the gather skips it otherwise, and no segment is cast).
bool faces(const GpuSurfel& s, const glm::vec3& x) {
  return glm::dot(glm::vec3(s.normal_area), x - glm::vec3(s.position_cell)) > 0.0f;
}

// A probe is buried when more than this share of its rays leave through the back of a face.
constexpr float kBuriedBackShare = 0.2f;

// Whether more than kBuriedBackShare of the rays from `x` to the surfels facing it meet the back of
// a face first, over an even sample of about 64 of them: so for a probe inside a wall or a piece of
// furniture, or outside the room where the cell's box holds more than the room. It stops as soon
// as the sample's answer is sure.
bool buried(const SegmentOccluders& scene, const glm::vec3& x, const GpuSurfel* surfels, const SurfelEnds& ends,
            uint32_t count) {
  const uint32_t stride = std::max(1u, count / 64);
  const uint32_t sample = (count + stride - 1) / stride;
  const bool x_inside = scene.inside_boundary(x);
  uint32_t facing = 0, back = 0;
  for (uint32_t k = 0; k < count; k += stride) {
    if (!faces(surfels[k], x)) continue;
    ++facing;
    if (scene.first_hit(x, ends.at[k], x_inside && ends.inside[k]) == SegmentOccluders::Hit::Back &&
        float(++back) > kBuriedBackShare * float(sample))
      return true;
  }
  return facing == 0 || float(back) > kBuriedBackShare * float(facing);
}

// Which of the cell's surfels each of its probes sees (GiLayout::probe_visibility): rooms are not
// convex once they hold furniture, a door leaf or a mirror, and a probe that gathers through them
// brings light from behind them into the room (docs/rendering.md, "Global illumination").
// A buried probe is moved, within its own grid cell, to a nearby point that is not (its light then
// stands for the grid point, as DDGI's relocation does); where there is none (the whole grid cell
// lies outside the room), it keeps its place and gathers without visibility, as before.
// Cells are independent: this runs on several threads, each writing only its cell's probes.
std::vector<glm::uvec4> probe_visibility(const std::vector<SegmentOccluders::Triangle>& triangles,
                                         std::vector<SegmentOccluders::CutOut> cut_outs, const GpuCellProbes& cp,
                                         const std::vector<GpuSurfel>& all_surfels, std::vector<GpuProbe>& probes) {
  const SegmentOccluders scene(triangles, std::move(cut_outs));
  const uint32_t first = cp.surfels.x, count = cp.surfels.z + cp.surfels.w - cp.surfels.x;
  const uint32_t probe_count = cp.dims.x * cp.dims.y * cp.dims.z;
  const uint32_t texels = (count + 127) / 128;
  const GpuSurfel* surfels = all_surfels.data() + first;
  const SurfelEnds ends = surfel_ends(scene, surfels, count);
  const glm::vec3 step(cp.step_grid);
  std::vector<glm::uvec4> out(size_t(texels) * probe_count), bits(texels);
  for (uint32_t p = cp.dims.w; p < cp.dims.w + probe_count; ++p) {
    GpuProbe& probe = probes[p];
    glm::vec3 x(probe.position_world);
    bool see_all = false;
    if (buried(scene, x, surfels, ends, count)) {
      see_all = true;
      // The six faces' and eight corners' directions of the probe's grid cell, nearer first.
      static const glm::vec3 kOffsets[] = {{1, 0, 0},  {-1, 0, 0},  {0, 1, 0},   {0, -1, 0},  {0, 0, 1},
                                           {0, 0, -1}, {1, 1, 1},   {1, 1, -1},  {1, -1, 1},  {1, -1, -1},
                                           {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}};
      for (const float reach : {0.25f, 0.45f}) {
        for (const glm::vec3& offset : kOffsets) {
          const glm::vec3 y = x + reach * step * offset;
          if (buried(scene, y, surfels, ends, count)) continue;
          x = y;
          probe.position_world = glm::vec4(y, probe.position_world.w);
          see_all = false;
          break;
        }
        if (!see_all) break;
      }
    }
    std::fill(bits.begin(), bits.end(), glm::uvec4(see_all ? ~0u : 0u));
    if (!see_all) {
      const bool x_inside = scene.inside_boundary(x);
      for (uint32_t k = 0; k < count; ++k)
        if (faces(surfels[k], x) && !scene.blocked(x, ends.at[k], x_inside && ends.inside[k]))
          bits[k / 128][(k / 32) % 4] |= 1u << (k % 32);
    }
    std::copy(bits.begin(), bits.end(), out.begin() + ptrdiff_t(p - cp.dims.w) * texels);
  }
  return out;
}

}  // namespace

GiLayout build_gi_layout(const RenderScene& scene, const GiOptions& options, bool with_visibility) {
  const World& world = scene.drawables;
  GiLayout out;
  uint64_t rng = options.seed * 0x2545f4914f6cdd1dull + 1;
  TextureCache textures(world);
  std::vector<std::vector<Triangle>> cell_triangles(world.cells.size());
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    GpuCellProbes cp{};
    // The grid spans the cell's volume as it lies in the world (axis-aligned there), so it is the
    // same whatever frame the file gives the cell. A grid over the cell-space box put a rotated
    // frame's probes outside the room, behind its walls, where they saw only the walls' backs: the
    // GI came out 25-30 % darker.
    cp.world_to_grid = glm::mat4(1.0f);
    const Aabb box = cell_volume_world(world, cell);
    const glm::vec3 extent = glm::max(box.extent(), glm::vec3(1e-3f));
    glm::uvec3 dims;
    for (int a = 0; a < 3; ++a)
      dims[a] = uint32_t(
          std::clamp(std::ceil(extent[a] / options.probe_spacing_m), 1.0f, float(options.max_probes_per_axis)));
    const glm::vec3 step = extent / glm::vec3(dims);
    cp.origin_grid = glm::vec4(box.min + 0.5f * step, 0.0f);
    cp.step_grid = glm::vec4(step, 0.0f);
    cp.dims = glm::uvec4(dims, uint32_t(out.probes.size()));
    for (uint32_t z = 0; z < dims.z; ++z)
      for (uint32_t y = 0; y < dims.y; ++y)
        for (uint32_t x = 0; x < dims.x; ++x) {
          GpuProbe p{};
          p.position_world = glm::vec4(glm::vec3(cp.origin_grid) + glm::vec3(x, y, z) * step, bits(c));
          out.probes.push_back(p);
        }

    std::vector<Triangle>& tris = cell_triangles[c];
    for (uint32_t i : cell.instances)
      add_mesh_triangles(world, world.instances[i].mesh, world.instances[i].mesh_to_world, textures, tris);
    cp.surfels.x = uint32_t(out.surfels.size());
    add_surface_surfels(tris, c, options.surfels_per_cell, rng, out.surfels);
    cp.surfels.y = uint32_t(out.surfels.size()) - cp.surfels.x;
    cp.surfels.z = uint32_t(out.surfels.size());
    add_portal_surfels(world, c, options.surfels_per_portal, rng, out.surfels);
    cp.surfels.w = uint32_t(out.surfels.size()) - cp.surfels.z;
    out.cells.push_back(cp);
  }
  // Probe visibility, cells shared out among threads (the CPU cost of a large level's load).
  std::vector<std::vector<glm::uvec4>> bits(world.cells.size());
  std::atomic<uint32_t> next{0};
  auto work = [&] {
    for (uint32_t c; (c = next++) < world.cells.size();) {
      std::vector<SegmentOccluders::Triangle> triangles;
      std::vector<SegmentOccluders::CutOut> cut_outs;
      triangles.reserve(cell_triangles[c].size());
      if (with_visibility)
        for (const Triangle& t : cell_triangles[c]) {
          triangles.push_back({t.a, t.b, t.c, t.normal});
          if (!t.mesh || t.mesh->alpha_mode == Mesh::AlphaMode::Opaque) continue;
          // Light passes a cut-out where it has no surface, as sight does.
          const float base = t.mesh->base_color.a;
          triangles.back().cut = int32_t(cut_outs.size());
          cut_outs.push_back({t.uv_a, t.uv_b, t.uv_c, base * t.color_a.a, base * t.color_b.a, base * t.color_c.a,
                              t.texture, t.mesh->base_color_sampler, gi_alpha_cutoff(*t.mesh)});
        }
      bits[c] = probe_visibility(triangles, std::move(cut_outs), out.cells[c], out.surfels, out.probes);
    }
  };
  std::vector<std::thread> threads(std::min(7u, std::max(1u, std::thread::hardware_concurrency()) - 1));
  for (std::thread& t : threads) t = std::thread(work);
  work();
  for (std::thread& t : threads) t.join();
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const GpuCellProbes& cp = out.cells[c];
    const uint32_t probe_count = cp.dims.x * cp.dims.y * cp.dims.z;
    const uint32_t texels = probe_count > 0 ? uint32_t(bits[c].size()) / probe_count : 0;
    for (uint32_t p = 0; p < probe_count; ++p)
      out.probes[cp.dims.w + p].visibility.x = uint32_t(out.probe_visibility.size()) + p * texels;
    out.probe_visibility.insert(out.probe_visibility.end(), bits[c].begin(), bits[c].end());
  }
  return out;
}

}  // namespace lintel::render
