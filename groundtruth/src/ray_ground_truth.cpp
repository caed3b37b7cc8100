// Embree 3 ray casting over a World: each shell and each instance is one triangle geometry in
// world space, so a hit's geometry id maps straight back to (cell, instance). A second scene holds
// a thin box around every portal edge: the rims where the truth is undecidable (see the header).
#include <lintel/reference/ray_ground_truth.h>

#include <lintel/reference/cut_out.h>
#include <lintel/reference/embree_mesh.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace lintel {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The first surface along a ray: its owner, its ray parameter, and whether it is a shell seen
// from behind (then `owner` is kNone).
struct FirstHit {
  RayHitId owner;
  float t = std::numeric_limits<float>::infinity();
  bool blocked = false;
};

struct RayGroundTruth::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  RTCScene rims = nullptr;  // boxes around portal edges
  std::vector<RayHitId> owner_of_geometry;
  std::vector<reference::CutOut> cut_of_geometry;  // by geometry id: a cut-out's coverage test
  // The base colour textures of cut-outs, decoded when first needed (one slot per World texture,
  // sized once: the CutOuts point into it).
  std::vector<reference::LinearTexture> textures;
  const World* source = nullptr;   // the World built from (it outlives this: RayGroundTruth::build)
  std::vector<double> rim_radius;  // per portal
  size_t cell_count = 0, instance_count = 0;

  ~Impl() {
    if (rims) rtcReleaseScene(rims);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  FirstHit first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max) const;
  bool crosses_rim(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max) const;
  Status add_rim_boxes(const World& world);

  Status add_mesh(const Mesh& mesh, const glm::mat4& to_world, RayHitId owner) {
    EmbreeTriangles added;
    if (Status s = attach_embree_mesh(device, scene, mesh, to_world, added); !s) return s;
    if (added.geometry == RTC_INVALID_GEOMETRY_ID) return {};
    if (owner_of_geometry.size() <= added.geometry) {
      owner_of_geometry.resize(added.geometry + 1);
      cut_of_geometry.resize(added.geometry + 1);
    }
    owner_of_geometry[added.geometry] = owner;
    const reference::LinearTexture* texture = nullptr;
    if (mesh.alpha_mode == Mesh::AlphaMode::Mask && mesh.base_color_texture >= 0 &&
        size_t(mesh.base_color_texture) < textures.size() && mesh.uvs.size() == mesh.positions.size()) {
      reference::LinearTexture& t = textures[size_t(mesh.base_color_texture)];
      const Texture& file = source->textures[size_t(mesh.base_color_texture)];
      if (file.width < 1 || file.height < 1 || file.rgba8.size() != size_t(file.width) * file.height * 4)
        return Status::error("ground truth: texture '" + file.name + "' does not hold width * height * 4 bytes");
      if (t.levels.empty()) t = reference::to_linear(file);
      texture = &t;
    }
    // The World outlives this (build()), so its uvs can be pointed at.
    reference::CutOut& cut = cut_of_geometry[added.geometry];
    cut = reference::cut_out_of(mesh, added.indices, texture ? mesh.uvs.data() : nullptr, texture,
                                mesh.colors.size() == mesh.positions.size() ? mesh.colors.data() : nullptr);
    if (cut.blend) {
      // What lies behind glass is seen, wherever the screen-door shows it: every ray passes.
      cut.blend = false;
      cut.cutoff = std::numeric_limits<float>::infinity();
    }
    return {};
  }
};

// One geometry of 12 triangles per portal edge: the box of half-width r around the edge (along
// the portal normal and across the edge within the plane), reaching r past both ends.
Status RayGroundTruth::Impl::add_rim_boxes(const World& world) {
  std::vector<double> error;
  scene_float_error_m(world, &error);
  rim_radius.assign(world.portals.size(), 0.0);
  rims = rtcNewScene(device);
  rtcSetSceneFlags(rims, RTC_SCENE_FLAG_ROBUST);
  static constexpr uint32_t kBoxTriangles[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                                    {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  for (size_t p = 0; p < world.portals.size(); ++p) {
    const Portal& portal = world.portals[p];
    const double r = std::max(error[portal.from], error[portal.to]);  // see the header
    rim_radius[p] = r;
    const glm::dvec3 n = glm::normalize(glm::dvec3(portal.normal_world));
    const size_t count = portal.polygon_world.size();
    for (size_t e = 0; e < count; ++e) {
      const glm::dvec3 a(portal.polygon_world[e]), b(portal.polygon_world[(e + 1) % count]);
      if (glm::length(b - a) <= 0.0 || r <= 0.0) continue;
      const glm::dvec3 along = glm::normalize(b - a), across = glm::normalize(glm::cross(n, along));
      RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 8));
      auto* idx = static_cast<uint32_t*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), 12));
      if (!v || !idx) {
        rtcReleaseGeometry(geom);
        return Status::error("embree: out of memory for the rim of portal '" + portal.name + "'");
      }
      for (int k = 0; k < 8; ++k) {  // bit 2: end, bit 1: side along n, bit 0: side across
        const glm::dvec3 end = (k & 4) ? b + r * along : a - r * along;
        const glm::dvec3 q = end + ((k & 2) ? r : -r) * n + ((k & 1) ? r : -r) * across;
        v[3 * k] = float(q.x), v[3 * k + 1] = float(q.y), v[3 * k + 2] = float(q.z);
      }
      for (int t = 0; t < 12; ++t)
        for (int c = 0; c < 3; ++c) idx[3 * t + c] = kBoxTriangles[t][c];
      rtcCommitGeometry(geom);
      rtcAttachGeometry(rims, geom);
      rtcReleaseGeometry(geom);
    }
  }
  rtcCommitScene(rims);
  return {};
}

FirstHit RayGroundTruth::Impl::first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_min,
                                         float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x;
  rh.ray.dir_y = direction.y;
  rh.ray.dir_z = direction.z;
  rh.ray.tnear = t_min;
  rh.ray.tfar = t_max;
  rh.ray.mask = 0xffffffffu;
  // A cut-out's uncovered points are no surface: the same ray again from just past such a hit
  // (Embree gives the same t for the same ray and triangle). Bounded: a few cut-outs in a row.
  constexpr int kMaxCutAways = 64;
  FirstHit out;
  for (int crossing = 0;; ++crossing) {
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
    const reference::CutOut& cut = cut_of_geometry[rh.hit.geomID];
    // Level 0 with the magnification filter: the texture as authored, what an eye sees up close.
    if (crossing == kMaxCutAways || !cut.cut_away(rh.hit.primID, rh.hit.u, rh.hit.v, -kInfinity)) break;
    rh.ray.tnear = std::nextafter(rh.ray.tfar, kInfinity);
    rh.ray.tfar = t_max;
    if (!(rh.ray.tnear <= t_max)) return out;
  }
  out.owner = owner_of_geometry[rh.hit.geomID];
  out.owner.depth = rh.ray.tfar;
  out.t = rh.ray.tfar;
  // Embree's unnormalized geometric normal Ng points to the side from which v0, v1, v2 appear
  // counter-clockwise (glTF's front; checked by tests/groundtruth): a front face has Ng against
  // the ray. A shell seen from behind is solid and opaque (see the header).
  const float along = rh.ray.dir_x * rh.hit.Ng_x + rh.ray.dir_y * rh.hit.Ng_y + rh.ray.dir_z * rh.hit.Ng_z;
  if (out.owner.instance == RayHitId::kNone && along >= 0.0f) {
    out.blocked = true;
    out.owner = {};
  }
  return out;
}

bool RayGroundTruth::Impl::crosses_rim(const glm::vec3& origin, const glm::vec3& direction, float t_min,
                                       float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tnear = t_min;
  ray.tfar = t_max;
  ray.mask = 0xffffffffu;
  rtcOccluded1(rims, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf when something occludes
}

RayGroundTruth::RayGroundTruth() = default;
RayGroundTruth::~RayGroundTruth() = default;
RayGroundTruth::RayGroundTruth(RayGroundTruth&&) noexcept = default;
RayGroundTruth& RayGroundTruth::operator=(RayGroundTruth&&) noexcept = default;

glm::vec2 pixel_center_ndc(uint32_t i, uint32_t j, uint32_t resolution) {
  const float r = static_cast<float>(resolution);
  return {(2.0f * (static_cast<float>(i) + 0.5f)) / r - 1.0f, 1.0f - (2.0f * (static_cast<float>(j) + 0.5f)) / r};
}

Status RayGroundTruth::build(const World& world) {
  auto impl = std::make_unique<Impl>();
  impl->device = rtcNewDevice("threads=0");  // 0: as many threads as the machine has
  if (!impl->device) return Status::error("embree: cannot create a device");
  impl->scene = rtcNewScene(impl->device);
  rtcSetSceneFlags(impl->scene, RTC_SCENE_FLAG_ROBUST);  // no accuracy-for-speed shortcuts
  rtcSetSceneBuildQuality(impl->scene, RTC_BUILD_QUALITY_HIGH);
  impl->cell_count = world.cells.size();
  impl->instance_count = world.instances.size();
  impl->source = &world;
  impl->textures.resize(world.textures.size());
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    if (cell.shell_mesh < 0) continue;
    if (Status s = impl->add_mesh(world.meshes[cell.shell_mesh], cell.cell_to_world, {c, RayHitId::kNone}); !s)
      return s;
  }
  for (uint32_t i = 0; i < world.instances.size(); ++i) {
    const Instance& inst = world.instances[i];
    if (Status s = impl->add_mesh(world.meshes[inst.mesh], inst.mesh_to_world, {inst.cell, i}); !s) return s;
  }
  rtcCommitScene(impl->scene);
  if (Status s = impl->add_rim_boxes(world); !s) return s;
  if (rtcGetDeviceError(impl->device) != RTC_ERROR_NONE) return Status::error("embree: scene build failed");
  impl_ = std::move(impl);
  return {};
}

RayHitId RayGroundTruth::cast_ray(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max,
                                  bool* blocked) const {
  assert(impl_);
  const FirstHit hit = impl_->first_hit(origin, direction, t_min, t_max);
  if (blocked) *blocked = hit.blocked;
  return hit.owner;
}

bool RayGroundTruth::passes_portal_rim(const glm::vec3& origin, const glm::vec3& direction, float t_min,
                                       float t_max) const {
  assert(impl_);
  return impl_->crosses_rim(origin, direction, t_min, t_max);
}

double RayGroundTruth::rim_radius_m(uint32_t portal) const {
  assert(impl_ && portal < impl_->rim_radius.size());
  return impl_->rim_radius[portal];
}

void RayGroundTruth::cast(const RayCamera& camera, uint32_t resolution, GroundTruth& out) const {
  assert(impl_ && resolution >= 1);
  const glm::vec3 forward = glm::normalize(camera.target_world - camera.eye_world);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up_world));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
  out.resolution = resolution;
  out.blocked_pixels = 0;
  out.pixels.assign(size_t{resolution} * resolution, RayHitId{});
  out.rim_pixels = 0;
  out.cell_visible.assign(impl_->cell_count, 0);
  out.instance_visible.assign(impl_->instance_count, 0);
  out.past_rim_cell_visible.assign(impl_->cell_count, 0);
  out.past_rim_instance_visible.assign(impl_->instance_count, 0);
  for (uint32_t j = 0; j < resolution; ++j) {
    for (uint32_t i = 0; i < resolution; ++i) {
      const glm::vec2 ndc = pixel_center_ndc(i, j, resolution);
      // Unnormalized so that t = view depth: the near plane is at t = near_m for every pixel.
      const glm::vec3 dir = forward + (ndc.x * tan_half * camera.aspect) * right + (ndc.y * tan_half) * up;
      const FirstHit hit =
          impl_->first_hit(camera.eye_world, dir, camera.near_m, std::numeric_limits<float>::infinity());
      if (impl_->crosses_rim(camera.eye_world, dir, camera.near_m, hit.t)) {
        ++out.rim_pixels;  // judged as seeing nothing; what it hit is reported apart
        if (hit.owner.cell != RayHitId::kNone) out.past_rim_cell_visible[hit.owner.cell] = 1;
        if (hit.owner.instance != RayHitId::kNone) out.past_rim_instance_visible[hit.owner.instance] = 1;
        continue;
      }
      out.blocked_pixels += hit.blocked;
      out.pixels[size_t{j} * resolution + i] = hit.owner;
      // `dir` has unit length along the view direction, so the ray parameter is the view depth.
      if (hit.owner.cell != RayHitId::kNone) out.cell_visible[hit.owner.cell] = 1;
      if (hit.owner.instance != RayHitId::kNone) out.instance_visible[hit.owner.instance] = 1;
    }
  }
  for (size_t c = 0; c < out.cell_visible.size(); ++c) out.past_rim_cell_visible[c] &= uint8_t(!out.cell_visible[c]);
  for (size_t k = 0; k < out.instance_visible.size(); ++k)
    out.past_rim_instance_visible[k] &= uint8_t(!out.instance_visible[k]);
}

}  // namespace lintel
