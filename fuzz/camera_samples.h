// Camera placements where portal methods fail: eyes in and near doorways (on the portal plane,
// 1e-7 m to 1 m off it), views grazing a portal's plane, random orientations and lenses — with
// the eye's viewer cell known from the side of the portal it stands on.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <rapidcheck.h>

namespace lintel::fuzz {

struct CameraSample {
  View view;
  uint32_t start_cell = 0;  // the cell the eye is in
  uint32_t portal = 0;      // the portal it was placed at
  double offset_m = 0.0;    // signed distance from the portal plane (> 0: `to`'s side)
};

// A point of the portal polygon, pulled towards its centroid by `shrink` (0: centroid, 1: edge).
glm::dvec3 point_in_portal(const Portal& portal, double u, double v, double shrink);

// rapidcheck generator: eye at a portal of `world` (two_way_only: skip one-way portals), offset
// from its plane by a log-spread distance on either side, looking anywhere or grazing the plane.
rc::Gen<CameraSample> gen_camera_at_portal(const World& world, bool two_way_only);

// Inside a property: a direction to look along in a test world's layout (tests/visibility
// test_worlds.h), x and z in [-100, 100], y in [-60, 60], at least 10 long, and never straight up
// or down: the layout's up is the view's up, and validate_view refuses a view whose up is
// parallel to its direction (the soak drew (0, -60, 0) once in about 30,000 cases).
glm::vec3 pick_layout_look();

// Unsigned distance from `p` to the nearest shell triangle of any cell (brute force). A camera
// whose near plane reaches a wall sees through it, which no portal method models; the properties
// keep eyes farther than the near plane's corner distance from every wall.
double distance_to_nearest_shell(const World& world, const glm::dvec3& p);

// Whether a ray from `eye` along `dir` runs inside a portal's plane: eye within 1e-3 m of the
// plane and direction within 1e-3 rad of it. Such a ray travels along the seam where two cells'
// reveal quads meet at the wall's mid-plane; far from the origin that seam is a float-sized crack
// into the hollow wall, and what the ray sees through it is the crack, not the building.
bool ray_runs_in_portal_plane(const World& world, const glm::dvec3& eye, const glm::dvec3& dir);

// An upper bound in meters on the float error of the loaded geometry: a few ulps of the largest
// cell-space coordinate times the cell's scale, and of the largest world coordinate. Random
// scenes with cell frames 1e4 m from their rooms reach about a millimetre.
double geometry_error_bound(const World& world);

// Whether a world point lies within `tolerance_m` of a portal of `cell` (on its plane and inside
// its polygon grown by the tolerance): there the two cells' float geometry meet and a surface may
// belong to either side.
bool on_portal_seam(const World& world, uint32_t cell, const glm::dvec3& p_world, double tolerance_m);

// Direction (unnormalized) of the ray through NDC point `ndc`, as RayGroundTruth casts it.
glm::dvec3 pixel_ray_direction(const View& view, const glm::vec2& ndc);

// Distance from the eye to a corner of the near-plane rectangle.
double near_corner_distance(const View& view);

}  // namespace lintel::fuzz
