// Link transforms of teleport and mirror portals (docs/visibility.md, "Linked portals"): the
// reflection in a portal's plane, the rigid map of one portal's polygon onto a congruent target
// portal, and the checks finalize_world() and the loader run on a linked portal.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>

namespace lintel {

// Depth of link recursion the traversal follows: a view seen through more than this many linked
// portals in a row is not resolved (the traversal reports the pixels: VisibleSet::unresolved).
inline constexpr uint32_t kMaxLinkDepth = 8;

// x -> x - 2 (n.x - d) n: the reflection in the portal's plane (determinant -1).
glm::dmat4 mirror_transform(const Portal& portal);

// The rigid map (rotation + translation, determinant +1) taking `source`'s polygon onto
// `target`'s, with source's normal going to minus target's (a ray entering `source` from its
// `from` side comes out of `target` into target's `from` cell). Vertex i of source goes to vertex
// (j - i) mod n of target for the j that fits every vertex within 1e-4 x the polygon's size
// (plus 1e-6 x its largest coordinate); of several (a square has four), the one that keeps world
// +Y most upright, then the lowest j. Returns an empty string, or why not ("has 4 vertices, the
// target 3", "is not congruent to the target (off by 0.2 m)").
std::string link_onto_target(const Portal& source, const Portal& target, glm::dmat4& link_world);

// Whether `m` is rigid: finite, last row (0, 0, 0, 1), columns of its 3x3 part orthonormal within
// 1e-5. `determinant` receives that part's determinant (+1 rotation, -1 reflection).
bool is_rigid(const glm::dmat4& m, double& determinant);

// Where the ray o + t d (t in (0, t_max], with a slack of 1e-3 (1 + t_max) past it) first meets
// the front of a linked portal's polygon (a mirror or teleport among `portals`), or -1; `t_out`
// receives that t. Linked portals lie on a wall's inner face, so a ray that ignores links meets
// the wall at about that t: pass the wall hit's distance as t_max to ask whether the ray should
// have gone through the link instead (the renderer shows what lies beyond it). Linear in the
// portal count: for tests and references, not for a frame's hot path.
int linked_portal_on_ray(std::span<const Portal> portals, const glm::dvec3& o, const glm::dvec3& d, double t_max,
                         double& t_out);

// The checks on a linked portal of `world` (indices already valid): one-way; teleport: rigid with
// determinant +1; mirror: `to` == `from` and link_world the reflection in its plane (within 1e-5
// relative). Empty string when fine, else the fault, for a message naming the portal.
std::string check_portal_link(const World& world, uint32_t portal);

}  // namespace lintel
