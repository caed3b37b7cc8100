// Axis-aligned bounding boxes: the real extent of meshes, instances and cell volumes.
#pragma once

#include <glm/glm.hpp>

#include <limits>

namespace lintel {

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    if (b.empty()) return;
    extend(b.min);
    extend(b.max);
  }
  bool contains(const glm::vec3& p) const {
    return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
};

// Box of the 8 transformed corners of `box` (conservative for any affine `m`). Empty stays empty.
Aabb transform_aabb(const glm::mat4& m, const Aabb& box);

}  // namespace lintel
