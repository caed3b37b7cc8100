// One World mesh into an Embree 3 scene, in world space: shared by the ray-cast ground truth and
// the path tracer (tests and benchmarks only; includes Embree's header).
#pragma once

#include <lintel/status.h>
#include <lintel/world.h>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>

namespace lintel {

struct EmbreeTriangles {
  unsigned geometry = RTC_INVALID_GEOMETRY_ID;  // the id rtcAttachGeometry gave (none for an empty mesh)
  const float* vertices = nullptr;              // world space, xyz per vertex (Embree's buffer, alive with the scene)
  const uint32_t* indices = nullptr;            // 3 per triangle (Embree's buffer)
};

// Transforms `mesh` by `to_world` into a new triangle geometry of `scene` (committed, attached).
// A mirroring transform (negative determinant) has its winding swapped, so the glTF front face
// stays the front face. An empty mesh adds nothing (out.geometry stays RTC_INVALID_GEOMETRY_ID).
// Errors: Embree out of memory.
Status attach_embree_mesh(RTCDevice device, RTCScene scene, const Mesh& mesh, const glm::mat4& to_world,
                          EmbreeTriangles& out);

}  // namespace lintel
