#include <lintel/reference/embree_mesh.h>

#include <string>

namespace lintel {

Status attach_embree_mesh(RTCDevice device, RTCScene scene, const Mesh& mesh, const glm::mat4& to_world,
                          EmbreeTriangles& out) {
  out = EmbreeTriangles{};
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
  const bool mirrored = glm::determinant(glm::mat3(to_world)) < 0.0f;
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    indices[i] = mesh.indices[i];
    indices[i + 1] = mesh.indices[mirrored ? i + 2 : i + 1];
    indices[i + 2] = mesh.indices[mirrored ? i + 1 : i + 2];
  }
  rtcCommitGeometry(geom);
  // The scene keeps the geometry (and so its buffers) alive after our reference is released.
  out.geometry = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  out.vertices = vertices;
  out.indices = indices;
  return {};
}

}  // namespace lintel
