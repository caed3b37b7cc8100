// Matrix -> TRS for the rooms importer and exporter (see rooms_trs.h).
#include "rooms/rooms_trs.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace lintel::rooms {

bool set_trs_from_matrix(const glm::dmat4& m, NodeDesc& node) {
  glm::dvec3 axis[3];
  glm::dvec3 scale;
  for (int i = 0; i < 3; ++i) {
    axis[i] = glm::dvec3(m[i]);
    scale[i] = glm::length(axis[i]);
    if (!(scale[i] > 0.0) || !std::isfinite(scale[i])) return false;
    axis[i] /= scale[i];
  }
  constexpr double kOrthogonal = 1e-5;
  if (std::fabs(glm::dot(axis[0], axis[1])) > kOrthogonal || std::fabs(glm::dot(axis[0], axis[2])) > kOrthogonal ||
      std::fabs(glm::dot(axis[1], axis[2])) > kOrthogonal)
    return false;
  // A mirror (left-handed axes) is a negative x scale of the right-handed rotation.
  if (glm::dot(glm::cross(axis[0], axis[1]), axis[2]) < 0.0) {
    axis[0] = -axis[0];
    scale[0] = -scale[0];
  }
  const glm::dquat rotation = glm::normalize(glm::quat_cast(glm::dmat3(axis[0], axis[1], axis[2])));
  node.translation = glm::vec3(glm::dvec3(m[3]));
  node.rotation = glm::quat(rotation);
  node.scale = glm::vec3(scale);
  return true;
}

}  // namespace lintel::rooms
