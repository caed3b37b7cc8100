// Convex floor pieces of a Doom map from its BSP: each subsector's polygon is the map's bounding
// box clipped by the partition lines from the root down to it (keeping its side), then by the
// lines of its own segs (the subsector lies to their right). Sectors are the union of their
// subsectors' pieces, holes and non-convex outlines included, so floors and ceilings need no
// polygon triangulation: each convex piece is a fan. The approach of Doom Legacy's and other GL
// ports' subsector polygon generation for vanilla node builds.
#pragma once

#include "doom/doom_map.h"

#include <glm/glm.hpp>

#include <vector>

namespace lintel::doom {

struct FloorPiece {
  std::vector<glm::dvec2> polygon;  // convex, counter-clockwise (map x, y), >= 3 corners
  uint16_t sector = 0;
};

// One piece per subsector that clips to a polygon of non-negligible area (in subsector order).
std::vector<FloorPiece> subsector_polygons(const Map& map);

// The subsector whose BSP leaf holds `p` (Doom's R_PointInSubsector: on the line counts as back).
uint16_t subsector_at(const Map& map, const glm::dvec2& p);

// Signed area (counter-clockwise positive) and area centroid of a polygon.
double polygon_area(const std::vector<glm::dvec2>& polygon);
glm::dvec2 polygon_centroid(const std::vector<glm::dvec2>& polygon);

}  // namespace lintel::doom
