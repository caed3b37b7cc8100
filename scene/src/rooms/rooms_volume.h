// A room's volume as the rooms importer sees it, in world space: either a closed triangle mesh (its
// '-bound', or the convex hull of its shell) or a box in the room node's own frame. Answers "is this
// point inside, grown or shrunk by a margin", which both the portal links and the overlap check use.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace lintel::rooms {

struct RoomVolume {
  // Box form (triangles_world empty): the box [box_min, box_max] in the frame `room_to_world`.
  glm::dmat4 room_to_world{1.0};
  glm::dmat4 world_to_room{1.0};
  glm::dvec3 box_min{0.0}, box_max{0.0};
  // Mesh form: a closed triangle mesh in world space, 3 vertices per triangle.
  std::vector<glm::dvec3> triangles_world;
  // World-space bounds of either form.
  glm::dvec3 bounds_min{0.0}, bounds_max{0.0};
};

// Fills room_to_world/world_to_room and the bounds for a box volume.
void set_box_volume(const glm::dmat4& room_to_world, const glm::dvec3& box_min, const glm::dvec3& box_max,
                    RoomVolume& out);
// Takes a closed mesh (world space, 3 vertices per triangle) and fills the bounds.
void set_mesh_volume(std::vector<glm::dvec3> triangles_world, RoomVolume& out);

// True when `p` (world) is inside the volume grown by `margin` metres (margin < 0: shrunk, i.e.
// at least -margin inside). Mesh volumes: inside by ray parity, and the margin against the
// distance to the nearest triangle. Box volumes: the margin is taken along each frame axis.
bool volume_contains(const RoomVolume& volume, const glm::dvec3& p, double margin);

// Diagonal of the world bounds.
double volume_size(const RoomVolume& volume);

// Looks for a point at least `tolerance` inside both volumes: a 7 x 7 x 7 grid over the
// intersection of their world bounds (bounds apart or overlapping by less than the tolerance: no
// test). Returns true with the point in `witness`. A sampled test: an overlap thinner than about
// 2/7 of the bounds' intersection can be missed; for two boxes in the same axes the grid's middle
// point lies in the overlap, so any overlap over 2 x tolerance deep is found.
bool volumes_overlap(const RoomVolume& a, const RoomVolume& b, double tolerance, glm::dvec3& witness);

}  // namespace lintel::rooms
