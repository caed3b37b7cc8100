// Look-ups on the loaded World and the AABB transform every culling path shares.
#include <lintel/world.h>

#include <numeric>

namespace lintel {

Aabb transform_aabb(const glm::mat4& m, const Aabb& box) {
  Aabb out;
  if (box.empty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z};
    out.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
  }
  return out;
}

int World::find_cell(std::string_view name) const {
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i].name == name) return static_cast<int>(i);
  return -1;
}

size_t World::portal_graph_cycles() const {
  std::vector<uint32_t> parent(cells.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&parent](uint32_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  size_t components = cells.size();
  for (const Portal& p : portals) {
    const uint32_t a = root(p.from), b = root(p.to);
    if (a != b) {
      parent[a] = b;
      --components;
    }
  }
  return portals.size() + components - cells.size();
}

int World::find_timeline(std::string_view name) const {
  for (size_t i = 0; i < timelines.size(); ++i)
    if (timelines[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace lintel
