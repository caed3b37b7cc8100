// Embree 3 scene of a World for the path tracer. Meshes go in through lintel/reference/embree_mesh.h, as for
// the ground truth, with two differences a shading renderer needs: triangles follow glTF's
// doubleSided (no "solid from behind" shells: a single-sided back face is passed through by
// nearest-hit rays, and blocks shadow rays like any face), and a hit carries its surface point,
// normal and albedo (textured: the uv interpolated with the hit's barycentrics, then
// lintel/reference/linear_texture.h at the ray cone's level of detail).
#include "embree_scene.h"

#include <lintel/reference/embree_mesh.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace lintel::pathtrace_detail {

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

Status EmbreeScene::add_mesh(const World& world, uint32_t mesh_index, const glm::mat4& to_world) {
  const Mesh& mesh = world.meshes[mesh_index];
  // The shared upload keeps the file's winding (front = counter-clockwise, glTF), and uvs follow
  // the stored indices.
  EmbreeTriangles added;
  if (Status s = attach_embree_mesh(device_, scene_, mesh, to_world, added); !s) return s;
  if (added.geometry == RTC_INVALID_GEOMETRY_ID) return {};
  const unsigned id = added.geometry;
  if (geometries_.size() <= id) geometries_.resize(id + 1);
  const float winding = glm::determinant(glm::mat3(to_world)) < 0.0f ? -1.0f : 1.0f;
  Geometry& g = geometries_[id];
  g = {};
  g.vertices = added.vertices;
  g.indices = added.indices;
  g.albedo = glm::vec3(mesh.base_color);
  g.single_sided = !mesh.double_sided;
  g.winding = winding;
  if (!mesh_colors_[mesh_index].empty()) g.colors = mesh_colors_[mesh_index].data();
  if (mesh.base_color_texture >= 0) {
    g.uvs = mesh_uvs_[mesh_index].data();
    g.texture = &textures_[size_t(mesh.base_color_texture)];
    g.sampler = mesh.base_color_sampler;
  }
  g.emission = mesh.emissive;
  if (mesh.emissive_texture >= 0) {
    g.uvs = mesh_uvs_[mesh_index].data();
    g.emissive_texture = &textures_[size_t(mesh.emissive_texture)];
    g.emissive_sampler = mesh.emissive_sampler;
  }
  g.cut = reference::cut_out_of(mesh, added.indices, g.uvs, g.texture,
                                g.colors);  // the copies: the World need not outlive this
  has_masks_ = has_masks_ || g.cut.masked;
  return {};
}

Status EmbreeScene::build(const World& world) {
  assert(!device_ && "build() once per EmbreeScene");
  device_ = rtcNewDevice("threads=0");  // build threads: as many as the machine has
  if (!device_) return Status::error("embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  // Robust traversal: watertight on shared edges, so a shadow ray cannot slip between two
  // triangles of a closed room (the sealed-room leak test depends on it).
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // A loaded World guarantees these; a hand-built one is checked rather than trusted.
  for (size_t t = 0; t < world.textures.size(); ++t) {
    const Texture& texture = world.textures[t];
    if (texture.width < 1 || texture.height < 1 || texture.rgba8.size() != size_t(texture.width) * texture.height * 4)
      return Status::error("path tracer: texture " + std::to_string(t) + " '" + texture.name +
                           "': rgba8 does not hold width * height * 4 bytes");
  }
  textures_.reserve(world.textures.size());
  for (const Texture& texture : world.textures) textures_.push_back(reference::to_linear(texture));
  mesh_uvs_.resize(world.meshes.size());
  for (size_t m = 0; m < world.meshes.size(); ++m) {
    const Mesh& mesh = world.meshes[m];
    for (const auto& [texture, field] : {std::pair{mesh.base_color_texture, "base_color_texture"},
                                         std::pair{mesh.emissive_texture, "emissive_texture"}}) {
      if (texture < 0) continue;
      if (size_t(texture) >= world.textures.size() || mesh.uvs.size() != mesh.positions.size())
        return Status::error("path tracer: mesh '" + mesh.name + "': " + field + " " + std::to_string(texture) +
                             " needs a texture and one uv per position");
      mesh_uvs_[m] = mesh.uvs;
    }
  }
  mesh_colors_.resize(world.meshes.size());
  for (size_t m = 0; m < world.meshes.size(); ++m) {
    const Mesh& mesh = world.meshes[m];
    if (mesh.colors.empty()) continue;
    if (mesh.colors.size() != mesh.positions.size())
      return Status::error("path tracer: mesh '" + mesh.name + "': colors needs one per position");
    mesh_colors_[m] = mesh.colors;
  }
  for (const Cell& cell : world.cells) {
    if (cell.shell_mesh < 0) continue;
    if (Status s = add_mesh(world, uint32_t(cell.shell_mesh), cell.cell_to_world); !s) return s;
  }
  for (const Instance& inst : world.instances) {
    if (Status s = add_mesh(world, inst.mesh, inst.mesh_to_world); !s) return s;
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) return Status::error("embree: scene build failed");
  return {};
}

namespace {

// Level of detail of a texture lookup on triangle (v0, v1, v2) with uvs (uv0, uv1, uv2) under a
// footprint `width_m` wide, seen along `dir` (unit normal `n`): log2 of the footprint's side in
// level-0 texels (EmbreeScene::intersect says how).
float footprint_lod(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2, const glm::vec2& uv0,
                    const glm::vec2& uv1, const glm::vec2& uv2, const reference::LinearTexture& texture,
                    const glm::vec3& n, const glm::vec3& dir, float width_m) {
  // Texels per square metre of this triangle (level 0), then the footprint's side in texels.
  const glm::vec2 du = uv1 - uv0, dv = uv2 - uv0;
  const float uv_area = 0.5f * std::abs(du.x * dv.y - du.y * dv.x);
  const float area = 0.5f * glm::length(glm::cross(v1 - v0, v2 - v0));
  const reference::LinearTexture::Level& base = texture.levels[0];
  const float texels_per_m2 = uv_area * float(base.width) * float(base.height) / area;
  const float cos_theta = std::abs(glm::dot(n, dir)) / glm::length(dir);
  const float side = width_m / std::max(cos_theta, 1e-6f);
  const float texels = texels_per_m2 * side * side;
  return texels > 0.0f ? 0.5f * std::log2(texels) : -std::numeric_limits<float>::infinity();
}

}  // namespace

bool EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& dir, const RayCone& cone, SurfaceHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xffffffffu;
  // Back faces of single-sided meshes and a cut-out's uncovered points are passed through: the
  // same ray again, starting just past that hit (Embree computes the same t for the same ray and
  // triangle, so it is not hit again). Bounded: a ray crosses few surfaces before a front face or
  // the sky.
  constexpr int kMaxBackFaces = 64;
  const Geometry* hit_geometry = nullptr;
  glm::vec3 v0, v1, v2;
  const uint32_t* tri = nullptr;
  for (int crossing = 0; crossing <= kMaxBackFaces; ++crossing) {
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    const Geometry& g = geometries_[rh.hit.geomID];
    tri = g.indices + 3 * size_t{rh.hit.primID};
    const auto vertex = [&g](uint32_t i) {
      return glm::vec3(g.vertices[3 * i], g.vertices[3 * i + 1], g.vertices[3 * i + 2]);
    };
    v0 = vertex(tri[0]);
    v1 = vertex(tri[1]);
    v2 = vertex(tri[2]);
    const bool front = g.winding * glm::dot(glm::cross(v1 - v0, v2 - v0), dir) < 0.0f;
    const auto lod = [&] {  // at this hit, as the albedo lookup below computes it
      if (!g.texture) return 0.0f;
      const glm::vec3 p = (1.0f - rh.hit.u - rh.hit.v) * v0 + rh.hit.u * v1 + rh.hit.v * v2;
      const glm::vec3 n = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
      return footprint_lod(v0, v1, v2, g.uvs[tri[0]], g.uvs[tri[1]], g.uvs[tri[2]], *g.texture, n, dir,
                           cone.width_m + cone.spread * glm::length(p - origin));
    };
    if ((front || !g.single_sided) && !(g.cut.masked && g.cut.cut_away(rh.hit.primID, rh.hit.u, rh.hit.v, lod()))) {
      hit_geometry = &g;
      break;
    }
    rh.ray.tnear = std::nextafter(rh.ray.tfar, std::numeric_limits<float>::infinity());
    rh.ray.tfar = std::numeric_limits<float>::infinity();
  }
  if (!hit_geometry) return false;
  const Geometry& g = *hit_geometry;
  // Barycentric interpolation keeps the point on the triangle to float precision of the vertices,
  // which the self-intersection offset (path_sampling.h) assumes; org + t * dir drifts with t.
  hit.position_world = (1.0f - rh.hit.u - rh.hit.v) * v0 + rh.hit.u * v1 + rh.hit.v * v2;
  glm::vec3 n = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
  if (glm::dot(n, dir) > 0.0f) n = -n;  // shade the side the ray came from (double-sided: either)
  hit.normal_world = n;
  hit.albedo = g.albedo;
  if (g.colors)  // COLOR_0, interpolated as the rasterizer does
    hit.albedo *= glm::vec3((1.0f - rh.hit.u - rh.hit.v) * g.colors[tri[0]] + rh.hit.u * g.colors[tri[1]] +
                            rh.hit.v * g.colors[tri[2]]);
  hit.cone_width_m = cone.width_m + cone.spread * glm::length(hit.position_world - origin);
  if (g.texture) {
    const glm::vec2 uv0 = g.uvs[tri[0]], uv1 = g.uvs[tri[1]], uv2 = g.uvs[tri[2]];
    const glm::vec2 uv = (1.0f - rh.hit.u - rh.hit.v) * uv0 + rh.hit.u * uv1 + rh.hit.v * uv2;
    const float lod = footprint_lod(v0, v1, v2, uv0, uv1, uv2, *g.texture, n, dir, hit.cone_width_m);
    hit.albedo *= reference::sample_texture(*g.texture, g.sampler, uv, lod);
  }
  hit.emission = g.emission;
  if (g.emissive_texture && g.emission != glm::vec3(0.0f)) {
    const glm::vec2 uv0 = g.uvs[tri[0]], uv1 = g.uvs[tri[1]], uv2 = g.uvs[tri[2]];
    const glm::vec2 uv = (1.0f - rh.hit.u - rh.hit.v) * uv0 + rh.hit.u * uv1 + rh.hit.v * uv2;
    const float lod = footprint_lod(v0, v1, v2, uv0, uv1, uv2, *g.emissive_texture, n, dir, hit.cone_width_m);
    hit.emission *= reference::sample_texture(*g.emissive_texture, g.emissive_sampler, uv, lod);
  }
  return true;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = 0.0f;
  ray.tfar = t_max;
  ray.mask = 0xffffffffu;
  if (!has_masks_) {
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on any hit
  }
  // Nearest hits in turn, past a cut-out's uncovered points (intersect's restart rule).
  RTCRayHit rh{};
  rh.ray = ray;
  constexpr int kMaxCutAways = 64;
  for (int crossing = 0; crossing <= kMaxCutAways; ++crossing) {
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    const Geometry& g = geometries_[rh.hit.geomID];
    if (!g.cut.cut_away(rh.hit.primID, rh.hit.u, rh.hit.v, -std::numeric_limits<float>::infinity())) return true;
    rh.ray.tnear = std::nextafter(rh.ray.tfar, std::numeric_limits<float>::infinity());
    rh.ray.tfar = t_max;
    if (!(rh.ray.tnear < t_max)) return false;
  }
  return true;  // more cut-outs in a row than the bound: blocked
}

}  // namespace lintel::pathtrace_detail
