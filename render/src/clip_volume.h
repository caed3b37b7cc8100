// Whether a world box may meet a view's clip volume (-w <= x, y <= w, 0 <= z <= w): conservative,
// false only when all 8 corners lie beyond one clip plane. Perspective and orthographic alike.
// Used to pick the cells a frustum-only camera draws and a sun view's casters.
#pragma once

#include <lintel/aabb.h>

#include <glm/glm.hpp>

namespace lintel::render {

inline bool box_may_meet_clip_volume(const glm::dmat4& world_to_clip, const Aabb& b) {
  if (b.empty()) return false;
  int outside[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 c = world_to_clip * glm::dvec4((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                                    (i & 4) ? b.max.z : b.min.z, 1.0);
    outside[0] += c.x < -c.w;
    outside[1] += c.x > c.w;
    outside[2] += c.y < -c.w;
    outside[3] += c.y > c.w;
    outside[4] += c.z < 0.0;
    outside[5] += c.z > c.w;
  }
  for (int k = 0; k < 6; ++k)
    if (outside[k] == 8) return false;
  return true;
}

}  // namespace lintel::render
