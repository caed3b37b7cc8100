// Rapidcheck properties of moving instances (mover_properties.h): boxes carried along random
// paths through the rooms of grids and rings (through doors, through walls, by jumps), with
// random door states. The ground truth is the ray walk of tests/visibility (closed doors are
// walls) plus a membership derived independently, by containment of each box's centre.
#include "mover_properties.h"

#include "camera_samples.h"
#include "ray_walk.h"
#include "test_worlds.h"

#include <lintel/cell_locate.h>
#include <lintel/dynamic_instances.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lintel::fuzz {
namespace {

constexpr float kPi = 3.14159265358979f;

// A grid (2..4 x 2..4) or ring (3..8) with random frames, winding and door states (each
// direction closed with probability 2/5), 1..5 box movers (half sizes 0.05..0.8 m) starting at
// random room centres, and per mover a path of waypoints: room centres of a random walk over
// neighbouring rooms (with jitter), now and then a random room (a jump), split into steps of at
// most 0.45 m except for jumps. The first waypoint is the start (deep inside its room).
struct MoverCase {
  testing::TestWorld t;
  std::vector<uint32_t> movers;               // instance indices
  std::vector<std::vector<glm::vec3>> paths;  // per mover, layout-space centres, [0] = start
  glm::vec3 eye_layout{0.0f};
  uint32_t rooms = 0;
};

glm::vec3 room_centre(bool grid, uint32_t w, uint32_t n, uint32_t room) {
  if (grid) return {4.0f * float(room % w) + 2.0f, 1.2f, 4.0f * float(room / w) + 2.0f};
  const float angle = (float(room) + 0.5f) * 2.0f * kPi / float(n);
  const float r = testing::ring_inner_radius(n) + 2.0f;
  return {r * std::cos(angle), 1.2f, r * std::sin(angle)};
}

MoverCase gen_mover_case() {
  testing::WorldOptions options;
  options.frame_seed = *rc::gen::inRange<uint64_t>(1, 1000);
  options.reverse_portal_winding = *rc::gen::arbitrary<bool>();
  MoverCase c;
  const bool grid = *rc::gen::arbitrary<bool>();
  uint32_t w = 0, n = 0;
  if (grid) {
    w = *rc::gen::inRange(2u, 5u);
    const uint32_t h = *rc::gen::inRange(2u, 5u);
    c.t = testing::make_grid(w, h, options);
    c.rooms = w * h;
  } else {
    n = *rc::gen::inRange(3u, 9u);
    c.t = testing::make_ring(n, options);
    c.rooms = n;
  }
  auto neighbour = [&](uint32_t room) {
    if (!grid) return (room + (*rc::gen::arbitrary<bool>() ? 1 : n - 1)) % n;
    const uint32_t h = c.rooms / w, x = room % w, z = room / w;
    switch (*rc::gen::inRange(0, 4)) {
      case 0:
        return x + 1 < w ? room + 1 : room;
      case 1:
        return x > 0 ? room - 1 : room;
      case 2:
        return z + 1 < h ? room + w : room;
      default:
        return z > 0 ? room - w : room;
    }
  };
  auto jitter = [] {
    return glm::vec3(*rc::gen::inRange(-40, 41), *rc::gen::inRange(-60, 61), *rc::gen::inRange(-40, 41)) * 0.01f;
  };
  const uint32_t count = *rc::gen::inRange(1u, 6u);
  for (uint32_t m = 0; m < count; ++m) {
    Mesh mesh;
    mesh.name = "mover" + std::to_string(m);
    const glm::vec3 half =
        glm::vec3(*rc::gen::inRange(5, 81), *rc::gen::inRange(5, 81), *rc::gen::inRange(5, 81)) * 0.01f;
    mesh.bounds_mesh.extend(-half);
    mesh.bounds_mesh.extend(half);
    c.t.world.meshes.push_back(mesh);
    c.t.world.groups.push_back({uint32_t(c.t.world.meshes.size() - 1), {}});
    uint32_t room = *rc::gen::inRange(0u, c.rooms);
    std::vector<glm::vec3> path{room_centre(grid, w, n, room) + jitter() * 0.5f};
    Instance inst;
    inst.name = mesh.name;
    inst.cell = room;
    inst.mesh = uint32_t(c.t.world.meshes.size() - 1);
    inst.group = uint32_t(c.t.world.groups.size() - 1);
    inst.mesh_to_world = glm::translate(c.t.layout_to_world, path[0]);
    c.movers.push_back(uint32_t(c.t.world.instances.size()));
    c.t.world.instances.push_back(inst);
    const uint32_t hops = *rc::gen::inRange(1u, 7u);
    for (uint32_t k = 0; k < hops; ++k) {
      const bool jump = *rc::gen::inRange(0, 6) == 0;
      room = jump ? *rc::gen::inRange(0u, c.rooms) : neighbour(room);
      const glm::vec3 next = room_centre(grid, w, n, room) + jitter();
      const glm::vec3 from = path.back();
      const int steps = jump ? 1 : std::max(1, int(std::ceil(glm::length(next - from) / 0.45f)));
      for (int s = 1; s <= steps; ++s) path.push_back(from + (next - from) * (float(s) / float(steps)));
    }
    c.paths.push_back(path);
  }
  RC_ASSERT(finalize_world(c.t.world).ok());
  for (uint32_t p = 0; p < c.t.world.portals.size(); ++p)
    for (PortalDirection d : {PortalDirection::FromTo, PortalDirection::ToFrom})
      c.t.world.set_portal_open(p, d, *rc::gen::inRange(0, 5) >= 2);
  c.eye_layout =
      room_centre(grid, w, n, *rc::gen::inRange(0u, c.rooms)) + jitter() * 0.5f + glm::vec3(0.0f, 0.3f, 0.0f);
  return c;
}

glm::mat4 placed(const MoverCase& c, const glm::vec3& centre_layout) {
  return glm::translate(c.t.layout_to_world, centre_layout);
}

// Ray-box slab intersection: the parameter interval where origin + t dir is in the box (closed),
// or an empty interval.
std::pair<double, double> ray_box(const glm::dvec3& o, const glm::dvec3& d, const Aabb& box) {
  double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (o[k] < box.min[k] || o[k] > box.max[k]) return {1.0, 0.0};
      continue;
    }
    double a = (double(box.min[k]) - o[k]) / d[k], b = (double(box.max[k]) - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return {t0, t1};
}

}  // namespace

bool check_moving_instances() {
  bool ok = true;

  // Movers, conservative: after every mover has walked its path (with the builder told through
  // instances_moved), every point of a mover's box that a view ray reaches through open portals
  // (the ray walk; closed doors are walls), in a cell the box reaches by the documented rule
  // computed from scratch with the cell that CONTAINS the box's centre (an independent
  // membership), lies behind the near plane or the instance is listed. A stale membership or reach
  // would miss such a point. Extra listed instances are accepted (the cull is conservative); rays
  // within a millimetre of a portal edge are not judged; a mover whose centre no cell contains
  // (it stands in a wall) is not judged.
  ok &= rc::check("moving instances with doors: never lose a box point a ray sees", [] {
    MoverCase c = gen_mover_case();
    DynamicInstances movers;
    RC_ASSERT(movers.reset(c.t.world).ok());
    VisibilityBuilder builder;
    VisibleSet visible;
    const CellLocation eye_cell = locate_cell(c.t.world, glm::dvec3(c.t.to_world(c.eye_layout)));
    RC_PRE(eye_cell.reason == LocateReason::Containment);
    const glm::vec3 look = pick_layout_look();
    const View view = c.t.view(c.eye_layout, c.eye_layout + look * 0.05f, float(*rc::gen::inRange(40, 120)));
    RC_ASSERT(builder.build(c.t.world, view, eye_cell.cell, {}, visible).ok());  // prepared before the moves
    size_t longest = 0;
    for (const auto& p : c.paths) longest = std::max(longest, p.size());
    for (size_t k = 1; k < longest; ++k) {  // the movers advance together, one waypoint a frame
      for (size_t m = 0; m < c.movers.size(); ++m)
        if (k < c.paths[m].size()) RC_ASSERT(movers.move(c.t.world, c.movers[m], placed(c, c.paths[m][k])).ok());
      movers.take_moved();
      builder.instances_moved(c.t.world, movers);
    }
    RC_ASSERT(builder.build(c.t.world, view, eye_cell.cell, {}, visible).ok());

    // Independent membership: the containing cell of each centre, and the reach from it.
    World truth = c.t.world;
    std::vector<uint8_t> judged(truth.instances.size(), 0);
    for (uint32_t i : c.movers) {
      const CellLocation where = locate_cell(truth, glm::dvec3(truth.instances[i].bounds_world.center()));
      if (where.reason != LocateReason::Containment) continue;
      truth.instances[i].cell = where.cell;
      judged[i] = 1;
    }
    RC_ASSERT(finalize_world(truth).ok());
    InstanceReach reach;
    reach.compute(truth);
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) {
        const glm::dvec2 ndc((i + 0.5) / 6.0 - 1.0, (j + 0.5) / 6.0 - 1.0);
        const testing::RayWalk walk = testing::walk_view_ray(c.t.world, view, eye_cell.cell, ndc);
        if (walk.ambiguous) continue;
        for (uint32_t m : c.movers) {
          if (!judged[m]) continue;
          const auto [b0, b1] = ray_box(walk.origin, walk.direction, truth.instances[m].bounds_world);
          for (const testing::RayWalk::Stretch& s : walk.stretches) {
            if (std::find(reach.begin(m), reach.end(m), s.cell) == reach.end(m)) continue;
            const double lo = std::max({b0, s.enter, walk.t_near}), hi = std::min(b1, s.leave);
            if (!(hi - lo > 1e-4)) continue;
            if (!std::binary_search(visible.instances.begin(), visible.instances.end(), m)) {
              RC_LOG() << "pixel " << ndc.x << "," << ndc.y << " sees mover " << m << " in cell " << s.cell
                       << " over t [" << lo << ", " << hi << "]; tracked cell " << c.t.world.instances[m].cell
                       << ", containing cell " << truth.instances[m].cell << "\n";
              RC_FAIL("a box point a ray sees through open portals is not listed");
            }
          }
        }
      }
  });

  // Movers, membership: after each move along the paths (through doors, through walls, jumps), a
  // mover whose centre lies more than 1 cm outside its tracked cell's volume has a centre that no
  // cell's volume contains (found_elsewhere_m = 1 cm is above every hysteresis band): a centre
  // inside some room is never left in a stale one. Afterwards its reach equals a fresh
  // InstanceReach::compute and Cell::instances equal what finalize_world() derives.
  ok &= rc::check("moving instances: membership follows the centre, reach and lists stay derived", [] {
    MoverCase c = gen_mover_case();
    DynamicInstances movers;
    RC_ASSERT(movers.reset(c.t.world).ok());
    for (size_t m = 0; m < c.movers.size(); ++m)
      for (size_t k = 1; k < c.paths[m].size(); ++k) {
        const uint32_t i = c.movers[m];
        RC_ASSERT(movers.move(c.t.world, i, placed(c, c.paths[m][k])).ok());
        const glm::dvec3 centre(c.t.world.instances[i].bounds_world.center());
        if (cell_volume_distance_m(c.t.world, c.t.world.instances[i].cell, centre) > 0.01)
          RC_ASSERT(locate_cell(c.t.world, centre).reason == LocateReason::Nearest);
      }
    World fresh = c.t.world;
    RC_ASSERT(finalize_world(fresh).ok());
    for (size_t cell = 0; cell < fresh.cells.size(); ++cell)
      RC_ASSERT(c.t.world.cells[cell].instances == fresh.cells[cell].instances);
    InstanceReach reach;
    reach.compute(c.t.world);
    for (uint32_t i = 0; i < c.t.world.instances.size(); ++i)
      RC_ASSERT(std::vector<uint32_t>(reach.begin(i), reach.end(i)) ==
                std::vector<uint32_t>(movers.reach().begin(i), movers.reach().end(i)));
  });

  // Locating through the cell grid (cell_locate.h, CellGrid) gives locate_cell's answer -- the
  // same cell, reason and distance -- for points anywhere in and around the building: uniform in
  // its bounds widened by 1 m, on the corners and faces of cells' volume boxes and on portal
  // polygons (where volumes meet, and ties between cells are decided by volume and index).
  ok &= rc::check("the cell grid locates every point as locate_cell does", [] {
    MoverCase c = gen_mover_case();
    const World& world = c.t.world;
    CellGrid grid;
    grid.build(world);
    const std::vector<double> volumes = cell_volumes_m3(world);
    Aabb bounds;
    std::vector<glm::dvec3> points;
    for (const Cell& cell : world.cells) {
      const Aabb box = transform_aabb(cell.cell_to_world, cell.volume_box_cell);
      bounds.extend(box);
      for (int k = 0; k < 8; ++k)
        points.push_back(glm::dvec3(cell.cell_to_world *
                                    glm::vec4(k & 1 ? cell.volume_box_cell.max.x : cell.volume_box_cell.min.x,
                                              k & 2 ? cell.volume_box_cell.max.y : cell.volume_box_cell.min.y,
                                              k & 4 ? cell.volume_box_cell.max.z : cell.volume_box_cell.min.z, 1.0f)));
    }
    for (const Portal& p : world.portals) {
      points.push_back(glm::dvec3(p.centroid_world));
      for (const glm::vec3& v : p.polygon_world) points.push_back(glm::dvec3(v));
    }
    const auto u =
        *rc::gen::container<std::vector<std::array<uint16_t, 3>>>(40, rc::gen::arbitrary<std::array<uint16_t, 3>>());
    for (const auto& r : u) {
      const glm::dvec3 t = glm::dvec3(r[0], r[1], r[2]) / 65535.0;
      points.push_back(glm::mix(glm::dvec3(bounds.min) - 1.0, glm::dvec3(bounds.max) + 1.0, t));
    }
    for (const glm::dvec3& p : points) {
      const CellLocation a = locate_cell(world, p, volumes), b = locate_cell(world, grid, p, volumes);
      RC_ASSERT(a.cell == b.cell);
      RC_ASSERT(a.reason == b.reason);
      RC_ASSERT(a.distance_m == b.distance_m);
    }
  });

  // Movers, deterministic and reversible: walking every mover along its path and back along the
  // reversed path restores the World's instances (transform, bounds, cell), the cells' instance
  // lists and the reach bit for bit (the start is a room centre, deep inside its room, so the
  // crossings and containment agree there), and the builder told through instances_moved gives a
  // VisibleSet equal to the one before the walk (instances_tested aside: a moved instance is tested
  // in the mover slots) and to a fresh builder's.
  ok &= rc::check("moving instances: moving there and back restores the state; deterministic", [] {
    MoverCase c = gen_mover_case();
    const World before = c.t.world;
    DynamicInstances movers;
    RC_ASSERT(movers.reset(c.t.world).ok());
    const InstanceReach reach_before = movers.reach();
    const CellLocation eye_cell = locate_cell(c.t.world, glm::dvec3(c.t.to_world(c.eye_layout)));
    const View view = c.t.view(c.eye_layout, c.eye_layout + glm::vec3(3.0f, -0.5f, 2.0f), 90.0f);
    VisibilityBuilder builder, fresh;
    VisibleSet start, end, fresh_end;
    RC_ASSERT(builder.build(c.t.world, view, eye_cell.cell, {}, start).ok());
    for (size_t m = 0; m < c.movers.size(); ++m) {
      const auto& p = c.paths[m];
      for (size_t k = 1; k < p.size(); ++k) RC_ASSERT(movers.move(c.t.world, c.movers[m], placed(c, p[k])).ok());
      for (size_t k = p.size() - 1; k-- > 0;) RC_ASSERT(movers.move(c.t.world, c.movers[m], placed(c, p[k])).ok());
    }
    movers.take_moved();
    builder.instances_moved(c.t.world, movers);
    for (size_t i = 0; i < before.instances.size(); ++i) {
      RC_ASSERT(c.t.world.instances[i].mesh_to_world == before.instances[i].mesh_to_world);
      RC_ASSERT(c.t.world.instances[i].bounds_world.min == before.instances[i].bounds_world.min);
      RC_ASSERT(c.t.world.instances[i].bounds_world.max == before.instances[i].bounds_world.max);
      RC_ASSERT(c.t.world.instances[i].cell == before.instances[i].cell);
      RC_ASSERT(std::vector<uint32_t>(movers.reach().begin(uint32_t(i)), movers.reach().end(uint32_t(i))) ==
                std::vector<uint32_t>(reach_before.begin(uint32_t(i)), reach_before.end(uint32_t(i))));
    }
    for (size_t cell = 0; cell < before.cells.size(); ++cell)
      RC_ASSERT(c.t.world.cells[cell].instances == before.cells[cell].instances);
    RC_ASSERT(builder.build(c.t.world, view, eye_cell.cell, {}, end).ok());
    RC_ASSERT(fresh.build(c.t.world, view, eye_cell.cell, {}, fresh_end).ok());
    RC_ASSERT(end.instances == fresh_end.instances);
    end.stats.instances_tested = start.stats.instances_tested;
    RC_ASSERT(end == start);
  });
  return ok;
}

}  // namespace lintel::fuzz
