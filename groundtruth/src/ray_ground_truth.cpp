// Embree 3 ray casting over a World: each shell and each instance is one triangle geometry in
// world space, so a hit's geometry id maps straight back to (cell, instance).
#include <lintel/ray_ground_truth.h>

#include <embree3/rtcore.h>

#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace lintel {

struct RayGroundTruth::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<RayHitId> owner_of_geometry;
  size_t cell_count = 0, instance_count = 0;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  Status add_mesh(const Mesh& mesh, const glm::mat4& to_world, RayHitId owner) {
    if (mesh.indices.empty()) return {};
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), mesh.indices.size() / 3));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geom);
      return Status::error("embree: out of memory for mesh '" + mesh.name + "'");
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3 p = glm::vec3(to_world * glm::vec4(mesh.positions[v], 1.0f));
      vertices[3 * v + 0] = p.x;
      vertices[3 * v + 1] = p.y;
      vertices[3 * v + 2] = p.z;
    }
    // A transform that mirrors (negative determinant) flips winding; keep the front face in front.
    const bool mirrored = glm::determinant(glm::mat3(to_world)) < 0.0f;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
      indices[i] = mesh.indices[i];
      indices[i + 1] = mesh.indices[mirrored ? i + 2 : i + 1];
      indices[i + 2] = mesh.indices[mirrored ? i + 1 : i + 2];
    }
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    if (owner_of_geometry.size() <= id) owner_of_geometry.resize(id + 1);
    owner_of_geometry[id] = owner;
    return {};
  }
};

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
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    if (cell.shell_mesh < 0) continue;
    if (Status s = impl->add_mesh(world.meshes[cell.shell_mesh], cell.cell_to_world, {c, RayHitId::kNone}); !s) return s;
  }
  for (uint32_t i = 0; i < world.instances.size(); ++i) {
    const Instance& inst = world.instances[i];
    if (Status s = impl->add_mesh(world.meshes[inst.mesh], inst.mesh_to_world, {inst.cell, i}); !s) return s;
  }
  rtcCommitScene(impl->scene);
  if (rtcGetDeviceError(impl->device) != RTC_ERROR_NONE) return Status::error("embree: scene build failed");
  impl_ = std::move(impl);
  return {};
}

RayHitId RayGroundTruth::cast_ray(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max,
                                  bool* blocked) const {
  assert(impl_);
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
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (blocked) *blocked = false;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  RayHitId owner = impl_->owner_of_geometry[rh.hit.geomID];
  owner.depth = rh.ray.tfar;
  // Embree's unnormalized geometric normal Ng points to the side from which v0, v1, v2 appear
  // counter-clockwise (glTF's front; checked by tests/groundtruth): a front face has Ng against
  // the ray. A shell seen from behind is solid and opaque (see the header).
  const float along = rh.ray.dir_x * rh.hit.Ng_x + rh.ray.dir_y * rh.hit.Ng_y + rh.ray.dir_z * rh.hit.Ng_z;
  if (owner.instance == RayHitId::kNone && along >= 0.0f) {
    if (blocked) *blocked = true;
    return {};
  }
  return owner;
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
  out.cell_visible.assign(impl_->cell_count, 0);
  out.instance_visible.assign(impl_->instance_count, 0);
  for (uint32_t j = 0; j < resolution; ++j) {
    for (uint32_t i = 0; i < resolution; ++i) {
      const glm::vec2 ndc = pixel_center_ndc(i, j, resolution);
      // Unnormalized so that t = view depth: the near plane is at t = near_m for every pixel.
      const glm::vec3 dir = forward + (ndc.x * tan_half * camera.aspect) * right + (ndc.y * tan_half) * up;
      bool blocked = false;
      const RayHitId hit =
          cast_ray(camera.eye_world, dir, camera.near_m, std::numeric_limits<float>::infinity(), &blocked);
      out.blocked_pixels += blocked;
      out.pixels[size_t{j} * resolution + i] = hit;
      // `dir` has unit length along the view direction, so the ray parameter is the view depth.
      if (hit.cell != RayHitId::kNone) out.cell_visible[hit.cell] = 1;
      if (hit.instance != RayHitId::kNone) out.instance_visible[hit.instance] = 1;
    }
  }
}

}  // namespace lintel
