// `random`: cyclic cell graphs for property tests. Rooms fill a random connected part of a
// lattice with random column widths, row depths and storey heights; the growth order gives a
// spanning tree of doors (and stairwell-like holes between storeys), extra doors, windows and
// holes close cycles, some of them one-way. Cell frames are arbitrary (any rotation axis, offsets
// up to max_offset_m, non-uniform scales) and the building sits under a random rigid transform.
#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"
#include "generate/gen_random.h"
#include "write/portable_math.h"
#include "generate/random_lattice.h"
#include "generate/scene_assembly.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace lintel {
namespace {

using gen::Adjacency;
using gen::Lattice;

constexpr uint32_t kTimelineCrossings = 12;
constexpr double kWallMargin = 0.25;  // from a wall's mid-plane end to an opening
constexpr double kSlabMargin = 0.4;   // from a slab's mid-plane edge to a hole

struct Edge {
  Adjacency adjacency;
  std::vector<int> openings;  // indices into plan.openings
};

gen::OpeningPlan place_opening(const Lattice& lattice, const Adjacency& adj, int slot, int slots, bool window,
                               gen::GenRandom& rng) {
  const gen::LatticeCell& a = lattice.cells[size_t(adj.a)];
  if (adj.axis == 1) {  // a hole in the slab above room a
    const double x0 = lattice.x[a.ix] + kSlabMargin, x1 = lattice.x[a.ix + 1] - kSlabMargin;
    const double z0 = lattice.z[a.iz] + kSlabMargin, z1 = lattice.z[a.iz + 1] - kSlabMargin;
    const double slot_w = (x1 - x0) / slots, sx0 = x0 + slot * slot_w;
    const double w = std::min(rng.uniform(0.8, 1.4), slot_w - 0.1), d = rng.uniform(0.8, 1.4);
    const double hx = rng.uniform(sx0, sx0 + slot_w - w), hz = rng.uniform(z0, z1 - d);
    return gen::opening_slab(adj.a, adj.b, lattice.y[a.iy + 1], hx, hx + w, hz, hz + d, true);
  }
  const bool x_wall = adj.axis == 0;
  const double along0 = x_wall ? lattice.z[a.iz] : lattice.x[a.ix];
  const double along1 = x_wall ? lattice.z[a.iz + 1] : lattice.x[a.ix + 1];
  const double u0 = along0 + kWallMargin, slot_w = (along1 - along0 - 2 * kWallMargin) / slots;
  const double su0 = u0 + slot * slot_w;
  const double floor = lattice.y[a.iy] + 0.5 * gen::kSlabThickness;
  double w = gen::kDoorWidth, v0 = floor, v1 = floor + gen::kDoorHeight;
  if (window) {
    w = std::min(rng.uniform(0.6, 1.4), slot_w - 0.1);
    v0 = floor + rng.uniform(0.5, 1.0);
    v1 = v0 + rng.uniform(0.5, 1.2);
  }
  const double start = rng.uniform(su0, su0 + slot_w - w);
  if (x_wall) return gen::opening_x(adj.a, adj.b, lattice.x[a.ix + 1], start, start + w, v0, v1, true);
  return gen::opening_z(adj.a, adj.b, lattice.z[a.iz + 1], start, start + w, v0, v1, true);
}

// Openings for every edge: the tree edge's door or hole first, then the extras.
void add_openings(gen::BuildingPlan& plan, const Lattice& lattice, std::vector<Edge>& edges,
                  const std::vector<std::vector<bool>>& kinds, const RandomOptions& o, gen::GenRandom& rng) {
  for (size_t e = 0; e < edges.size(); ++e) {
    const int slots = int(kinds[e].size());
    for (int s = 0; s < slots; ++s) {
      const bool tree = kinds[e][size_t(s)];
      const bool window = !tree && edges[e].adjacency.axis != 1 && rng.chance(o.window_fraction);
      gen::OpeningPlan opening = place_opening(lattice, edges[e].adjacency, s, slots, window, rng);
      if (!tree && rng.chance(o.one_way_fraction)) opening.two_way = false;
      // The tree's openings lead away from the root (the walk relies on it); the others either way.
      const bool reverse = tree ? edges[e].adjacency.tree_parent_is_b : rng.chance(0.5);
      if (reverse) {
        std::swap(opening.from, opening.to);
        opening.normal = -opening.normal;
      }
      opening.name = "portal_" + std::to_string(plan.openings.size());
      edges[e].openings.push_back(int(plan.openings.size()));
      plan.openings.push_back(opening);
    }
  }
}

void add_frames(gen::BuildingPlan& plan, const RandomOptions& o, gen::GenRandom& rng) {
  const glm::dmat4 to_world = gen::building_to_world(plan);
  for (gen::RoomPlan& room : plan.rooms) {
    const glm::dvec2 c = 0.5 * (room.footprint[0] + room.footprint[2]);
    const glm::dvec3 offset(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    room.frame.translation = glm::dvec3(to_world * glm::dvec4(c.x, room.floor_mid, c.y, 1.0)) + o.max_offset_m * offset;
    room.frame.rotation = rng.rotation();
    const double s = rng.log_uniform(o.min_scale, o.max_scale);
    room.frame.scale = rng.chance(0.5) ? glm::dvec3(s)
                                       : glm::dvec3(s, rng.log_uniform(o.min_scale, o.max_scale),
                                                    rng.log_uniform(o.min_scale, o.max_scale));
    room.volume = rng.chance(o.volume_fraction);
    room.color = {float(rng.uniform(0.6, 0.95)), float(rng.uniform(0.6, 0.95)), float(rng.uniform(0.6, 0.95)), 1.0f};
  }
}

// Low furniture (below the eye line of the walks) in the room's quadrants, clear of floor holes.
void add_furniture(gen::BuildingPlan& plan, gen::GenRandom& rng) {
  for (size_t r = 0; r < plan.rooms.size(); ++r) {
    const gen::RoomPlan& room = plan.rooms[r];
    const double hw = 0.5 * gen::kWallThickness;
    const double x0 = room.footprint[0].x + hw, x1 = room.footprint[2].x - hw;
    const double z0 = room.footprint[0].y + hw, z1 = room.footprint[2].y - hw;
    const double floor = room.floor_mid + 0.5 * gen::kSlabThickness;
    for (int q = 0; q < 4; ++q) {
      if (!rng.chance(0.4)) continue;
      const int mesh = int(rng.below(uint32_t(plan.meshes.size())));
      const double yaw = 0.5 * gen::kPi * rng.below(4) + gen::degrees(rng.uniform(-10, 10));
      const glm::dvec3 e = gen::mesh_extent(plan.meshes[size_t(mesh)]);
      const double c = std::fabs(gen::portable_cos(yaw)), s = std::fabs(gen::portable_sin(yaw));
      const double ex = e.x * c + e.z * s + 0.05, ez = e.x * s + e.z * c + 0.05;
      const double qx0 = (q & 1) ? 0.5 * (x0 + x1) : x0, qz0 = (q & 2) ? 0.5 * (z0 + z1) : z0;
      const double qx1 = qx0 + 0.5 * (x1 - x0), qz1 = qz0 + 0.5 * (z1 - z0);
      if (2 * ex > qx1 - qx0 || 2 * ez > qz1 - qz0) continue;
      const double px = 0.5 * (qx0 + qx1), pz = 0.5 * (qz0 + qz1);
      bool over_hole = false;
      for (const gen::OpeningPlan& o : plan.openings)
        if (o.in_slab && (o.from == int(r) || o.to == int(r)) && o.u0 < px + ex && o.u1 > px - ex && o.v0 < pz + ez &&
            o.v1 > pz - ez)
          over_hole = true;
      if (over_hole) continue;
      plan.instances.push_back({room.name + "_" + plan.meshes[size_t(mesh)].name + "_" + std::to_string(q),
                                int(r),
                                mesh,
                                {px, floor, pz},
                                gen::rotation_about({0, 1, 0}, yaw)});
    }
    if (rng.chance(1.0 / 3.0)) {
      LightDesc lamp{room.name + "_lamp", Light::Type::Point, {1.0f, 0.9f, 0.8f}, 20.0f, 10.0f};
      plan.lights.push_back(
          {int(r), lamp, {0.5 * (x0 + x1), room.ceiling_mid - 0.4, 0.5 * (z0 + z1)}, gen::kNoRotation});
    }
  }
}

// Depth-first walk over the tree's openings from the root, there and back, up to a cap.
Timeline doorway_walk(const gen::BuildingPlan& plan, const std::vector<Edge>& edges) {
  std::vector<std::vector<int>> children(plan.rooms.size());  // tree openings leaving each room
  for (const Edge& e : edges) {
    const gen::OpeningPlan& o = plan.openings[size_t(e.openings[0])];
    children[size_t(o.from)].push_back(e.openings[0]);
  }
  std::vector<glm::dvec3> waypoints{gen::room_eye_point(plan.rooms[0])};
  uint32_t crossings = 0;
  int here = 0;
  struct Frame {
    int room;
    size_t next;
    int via;
  };
  std::vector<Frame> stack{{0, 0, -1}};
  while (!stack.empty() && crossings < kTimelineCrossings) {
    Frame& f = stack.back();
    if (f.next < children[size_t(f.room)].size()) {
      const int o = children[size_t(f.room)][f.next++];
      gen::add_crossing(plan, plan.openings[size_t(o)], f.room, waypoints);
      here = plan.openings[size_t(o)].to;
      stack.push_back({here, 0, o});
      ++crossings;
    } else {
      if (f.via >= 0) {
        gen::add_crossing(plan, plan.openings[size_t(f.via)], f.room, waypoints);
        here = plan.openings[size_t(f.via)].from;
        ++crossings;
      }
      stack.pop_back();
    }
  }
  waypoints.push_back(gen::room_eye_point(plan.rooms[size_t(here)]));
  return gen::walk_timeline("doorway", 60.0, waypoints);
}

}  // namespace

SceneDesc generate_random(const RandomOptions& options) {
  assert(options.cells >= 2 && options.storeys >= 1 && options.min_scale > 0 && options.min_scale <= options.max_scale);
  gen::GenRandom rng(options.seed);
  const Lattice lattice = gen::grow_lattice(options.cells, options.storeys, rng);

  gen::BuildingPlan plan;
  plan.building_rotation = options.global_rotation ? rng.rotation() : gen::kNoRotation;
  plan.building_translation =
      options.max_global_offset_m * glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  plan.meshes = {gen::make_table({0.55f, 0.36f, 0.20f, 1}), gen::make_chair({0.62f, 0.42f, 0.26f, 1}),
                 gen::make_crate({0.72f, 0.60f, 0.40f, 1})};
  for (size_t i = 0; i < lattice.cells.size(); ++i) {
    const gen::LatticeCell& c = lattice.cells[i];
    plan.rooms.push_back(gen::box_room("cell_" + std::to_string(i), lattice.x[c.ix], lattice.x[c.ix + 1],
                                       lattice.z[c.iz], lattice.z[c.iz + 1], lattice.y[c.iy], lattice.y[c.iy + 1]));
  }

  // Tree edges get one opening; a share of the other neighbour pairs an extra one. With no extra
  // pair to use (a path-like tree), a tree edge gets a second opening: a cycle of two portals.
  std::vector<Edge> edges;
  std::vector<std::vector<bool>> kinds;  // per edge, per opening: true for the tree's opening
  std::vector<size_t> non_tree;
  for (const Adjacency& adj : lattice.adjacencies) {
    edges.push_back({adj, {}});
    kinds.push_back(adj.tree ? std::vector<bool>{true} : std::vector<bool>{});
    if (!adj.tree) non_tree.push_back(edges.size() - 1);
  }
  bool any_extra = false;
  for (size_t e : non_tree)
    if (rng.chance(options.extra_portal_fraction)) kinds[e].push_back(false), any_extra = true;
  if (!any_extra) {
    if (!non_tree.empty()) {
      kinds[non_tree[rng.below(uint32_t(non_tree.size()))]].push_back(false);
    } else {
      kinds[rng.below(uint32_t(edges.size()))].push_back(false);
    }
  }
  // Only edges with openings stay.
  std::vector<Edge> used;
  std::vector<std::vector<bool>> used_kinds;
  for (size_t e = 0; e < edges.size(); ++e)
    if (!kinds[e].empty()) used.push_back(edges[e]), used_kinds.push_back(kinds[e]);
  add_openings(plan, lattice, used, used_kinds, options, rng);

  add_frames(plan, options, rng);
  add_furniture(plan, rng);
  std::vector<Edge> tree_edges;
  for (size_t e = 0; e < used.size(); ++e)
    if (used_kinds[e][0]) tree_edges.push_back(used[e]);
  plan.timelines.push_back(doorway_walk(plan, tree_edges));
  return gen::assemble_scene(plan);
}

}  // namespace lintel
