// Look-ups on the loaded World and the AABB transform every culling path shares.
#include <lintel/world.h>

#include <lintel/portal_link.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <numeric>
#include <string>

namespace lintel {

// A corner's coordinate r is (m0r*x + m1r*y) + (m2r*z + m3r), in float, in that order (glm's
// mat4 * vec4). Float addition and multiplication round monotonically, so the smallest value over
// the 8 corners is that same sum with each product at its own smaller choice, and likewise the
// largest: the result is bit-identical to transforming the 8 corners (test_transform_aabb) at 6
// products per row instead of 32. Movers call this once per move (mover_bench).
Aabb transform_aabb(const glm::mat4& m, const Aabb& box) {
  Aabb out;
  if (box.empty()) return out;
  for (int r = 0; r < 3; ++r) {
    const float x0 = m[0][r] * box.min.x, x1 = m[0][r] * box.max.x;
    const float y0 = m[1][r] * box.min.y, y1 = m[1][r] * box.max.y;
    const float z0 = m[2][r] * box.min.z, z1 = m[2][r] * box.max.z;
    const float t = m[3][r] * 1.0f;
    out.min[r] = (std::min(x0, x1) + std::min(y0, y1)) + (std::min(z0, z1) + t);
    out.max[r] = (std::max(x0, x1) + std::max(y0, y1)) + (std::max(z0, z1) + t);
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

bool World::portal_open(uint32_t portal, PortalDirection direction) const {
  assert(portal < portals.size());
  return direction == PortalDirection::FromTo ? portals[portal].open_from_to : portals[portal].open_to_from;
}

void World::set_portal_open(uint32_t portal, PortalDirection direction, bool open) {
  assert(portal < portals.size());
  (direction == PortalDirection::FromTo ? portals[portal].open_from_to : portals[portal].open_to_from) = open;
}

void World::set_portal_open(uint32_t portal, bool open) {
  set_portal_open(portal, PortalDirection::FromTo, open);
  set_portal_open(portal, PortalDirection::ToFrom, open);
}

int World::find_portal(std::string_view name) const {
  for (size_t i = 0; i < portals.size(); ++i)
    if (portals[i].name == name) return static_cast<int>(i);
  return -1;
}

bool World::has_light_sources() const {
  if (!lights.empty()) return true;
  for (const Mesh& m : meshes)
    if (m.emissive.r > 0.0f || m.emissive.g > 0.0f || m.emissive.b > 0.0f) return true;
  return false;
}

Status finalize_world(World& world) {
  // Unique in the process, not just one more than before: a World object assigned another,
  // separately finalized World (`world = load_level(...)`) must not show a revision a cache
  // already saw at that address. An atomic counter is the one process-wide state Lintel keeps
  // (thread-safe; docs/architecture.md).
  static std::atomic<uint64_t> last_revision{0};
  world.revision = std::max(world.revision, last_revision.fetch_add(1, std::memory_order_relaxed)) + 1;
  const size_t cells = world.cells.size();
  const std::string where = world.source.empty() ? std::string("world") : world.source;
  for (Cell& c : world.cells) {
    c.links.clear();
    c.linked_portals.clear();
    c.instances.clear();
    c.lights.clear();
  }
  for (DrawGroup& g : world.groups) {
    g.instances.clear();
    if (g.mesh >= world.meshes.size())
      return Status::internal(where + ": draw group of mesh " + std::to_string(g.mesh) + " out of range");
  }
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    const Portal& portal = world.portals[p];
    if (portal.from >= cells || portal.to >= cells)
      return Status::internal(where + ": portal '" + portal.name + "' names a cell out of range");
    if (portal.polygon_world.size() < 3 || portal.polygon_world.size() > kMaxPortalVertices)
      return Status::internal(where + ": portal '" + portal.name + "' has " +
                              std::to_string(portal.polygon_world.size()) + " vertices");
    if (portal.linked()) {  // not in `links`: readers that do not follow links see a wall
      if (std::string why = check_portal_link(world, p); !why.empty())
        return Status::error(where + ": portal '" + portal.name + "': " + why);
      world.cells[portal.from].linked_portals.push_back(p);
      continue;
    }
    world.cells[portal.from].links.push_back({p, portal.to});
    if (portal.two_way) world.cells[portal.to].links.push_back({p, portal.from});
  }
  for (uint32_t i = 0; i < world.instances.size(); ++i) {
    Instance& inst = world.instances[i];
    if (inst.cell >= cells || inst.mesh >= world.meshes.size() || inst.group >= world.groups.size())
      return Status::internal(where + ": instance '" + inst.name + "' names a cell, mesh or group out of range");
    inst.bounds_world = transform_aabb(inst.mesh_to_world, world.meshes[inst.mesh].bounds_mesh);
    world.cells[inst.cell].instances.push_back(i);
    world.groups[inst.group].instances.push_back(i);
  }
  for (uint32_t i = 0; i < world.lights.size(); ++i) {
    if (world.lights[i].cell >= cells)
      return Status::internal(where + ": light '" + world.lights[i].name + "' names a cell out of range");
    world.cells[world.lights[i].cell].lights.push_back(i);
  }
  return {};
}

int World::find_timeline(std::string_view name) const {
  for (size_t i = 0; i < timelines.size(); ++i)
    if (timelines[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace lintel
