// The rooms importer's pieces (scene/src/rooms_*): node-name roles, point-in-volume with margins,
// the sampled overlap test, portal hulls and probe links.
#include "rooms/rooms_assemble.h"
#include "rooms/rooms_hull.h"
#include "rooms/rooms_portal.h"
#include "rooms/rooms_trs.h"
#include "rooms/rooms_volume.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace lintel::rooms {
namespace {

TEST(RoomsNames, SuffixesAndBlenderTails) {
  EXPECT_EQ(role_of_name("Hall-room").role, Role::Room);
  EXPECT_EQ(role_of_name("Hall-room").base, "Hall");
  EXPECT_EQ(role_of_name("Hall-room.001").base, "Hall.001");
  EXPECT_EQ(role_of_name("Door-portal").role, Role::Portal);
  EXPECT_EQ(role_of_name("Win-portal-oneway").role, Role::OneWayPortal);
  EXPECT_EQ(role_of_name("Win-portal-oneway").base, "Win");
  EXPECT_EQ(role_of_name("Hall-bound.002").role, Role::Bound);
  EXPECT_EQ(role_of_name("Sofa").role, Role::Plain);
  EXPECT_EQ(role_of_name("room").role, Role::Plain);          // no dash: not a suffix
  EXPECT_EQ(role_of_name("Hall-room.x1").role, Role::Plain);  // the tail must be digits
  EXPECT_EQ(role_of_name("-room").base, "");
}

std::vector<glm::dvec3> box_triangles(glm::dvec3 lo, glm::dvec3 hi) {
  const uint32_t idx[] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                          2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  std::vector<glm::dvec3> t;
  for (uint32_t i : idx) t.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
  return t;
}

TEST(RoomsVolume, BoxAndMeshFormsAgreeOnMargins) {
  // The same 2 x 2 x 2 box as a box in a scaled, moved frame and as a closed mesh.
  RoomVolume as_box, as_mesh;
  const glm::dmat4 frame = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0)), glm::dvec3(2, 1, 0.5));
  set_box_volume(frame, {-0.5, -1, -2}, {0.5, 1, 2}, as_box);
  set_mesh_volume(box_triangles({9, -1, -1}, {11, 1, 1}), as_mesh);
  for (const RoomVolume* v : {&as_box, &as_mesh}) {
    EXPECT_TRUE(volume_contains(*v, {10, 0, 0}, 0.0));
    EXPECT_TRUE(volume_contains(*v, {10.95, 0, 0}, -0.01));  // 5 cm inside
    EXPECT_FALSE(volume_contains(*v, {10.95, 0, 0}, -0.1));  // not 10 cm inside
    EXPECT_FALSE(volume_contains(*v, {11.05, 0, 0}, 0.01));  // 5 cm outside
    EXPECT_TRUE(volume_contains(*v, {11.05, 0, 0}, 0.1));    // within a 10 cm growth
    EXPECT_FALSE(volume_contains(*v, {10, 0, 1.5}, 0.0));
  }
}

TEST(RoomsVolume, OverlapFoundBeyondToleranceOnlyAndNotForNestedLShapes) {
  RoomVolume a, b, touching;
  set_box_volume(glm::dmat4(1.0), {0, 0, 0}, {4, 3, 4}, a);
  set_box_volume(glm::dmat4(1.0), {3.9, 0, 0}, {8, 3, 4}, b);
  set_box_volume(glm::dmat4(1.0), {4, 0, 0}, {8, 3, 4}, touching);
  glm::dvec3 witness;
  EXPECT_TRUE(volumes_overlap(a, b, 0.004, witness));  // 10 cm deep
  EXPECT_TRUE(volume_contains(a, witness, -0.004) && volume_contains(b, witness, -0.004));
  EXPECT_FALSE(volumes_overlap(a, b, 0.06, witness));  // under 2 x tolerance
  EXPECT_FALSE(volumes_overlap(a, touching, 0.004, witness));
  // An L (mesh: two boxes sharing a face would not be closed by position, so use the L's
  // bounding pieces): a box filling the L's notch overlaps the L's box but not the L.
  std::vector<glm::dvec3> l_shape = box_triangles({0, 0, 0}, {4, 3, 4});
  const std::vector<glm::dvec3> arm = box_triangles({4, 0, 2}, {8, 3, 4});
  l_shape.insert(l_shape.end(), arm.begin(), arm.end());  // two closed boxes touching: parity still right
  RoomVolume l, notch;
  set_mesh_volume(l_shape, l);
  set_box_volume(glm::dmat4(1.0), {4, 0, 0}, {8, 3, 2}, notch);
  EXPECT_FALSE(volumes_overlap(l, notch, 0.004, witness));
}

// The hull of a box room's shell (walls with a door hole: many coplanar vertices) and of random
// points: closed (every directed edge has its reverse), wound outwards (every input point on the
// inner side of every face), built from input points only.
TEST(RoomsHull, ClosedOutwardAndContainsEveryPoint) {
  std::vector<std::vector<glm::dvec3>> inputs;
  inputs.push_back({{0, 0, 0},
                    {4, 0, 0},
                    {4, 3, 0},
                    {0, 3, 0},
                    {0, 0, 4},
                    {4, 0, 4},
                    {4, 3, 4},
                    {0, 3, 4},
                    {1.5, 0, 0},
                    {2.5, 0, 0},
                    {1.5, 2.1, 0},
                    {2.5, 2.1, 0},
                    {2, 1.5, 4},
                    {2, 3, 2}});
  uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  };
  std::vector<glm::dvec3> cloud;
  for (int i = 0; i < 300; ++i) cloud.emplace_back(next() * 5 - 2, next() * 3, next() * 7 + 100);
  inputs.push_back(cloud);
  for (const std::vector<glm::dvec3>& points : inputs) {
    std::vector<glm::dvec3> t;
    ASSERT_TRUE(convex_hull_3d(points, 1e-9, t));
    ASSERT_EQ(t.size() % 3, 0u);
    std::vector<glm::vec3> soup(t.begin(), t.end());
    for (size_t i = 0; i < t.size(); i += 3) {
      const glm::dvec3 n = glm::cross(t[i + 1] - t[i], t[i + 2] - t[i]);
      for (const glm::dvec3& p : points) EXPECT_LE(glm::dot(n, p - t[i]), 1e-7 * glm::length(n));
      for (int k = 0; k < 3; ++k) EXPECT_NE(std::find(points.begin(), points.end(), t[i + size_t(k)]), points.end());
    }
    RoomVolume v;
    set_mesh_volume(t, v);
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& p : points) centre += p;
    EXPECT_TRUE(volume_contains(v, centre / double(points.size()), 0.0));
  }
  const size_t box_triangles = [&] {
    std::vector<glm::dvec3> t;
    EXPECT_TRUE(convex_hull_3d(inputs[0], 1e-9, t));
    return t.size() / 3;
  }();
  EXPECT_GE(box_triangles, 12u);  // 12 for the corners alone; coplanar points may split faces
}

TEST(RoomsHull, FlatOrTooFewPointsRefused) {
  std::vector<glm::dvec3> t;
  EXPECT_FALSE(convex_hull_3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 1e-9, t));
  EXPECT_FALSE(convex_hull_3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 1e-12}}, 1e-9, t));
  EXPECT_TRUE(t.empty());
}

TEST(RoomsPortal, HullDropsInteriorAndEdgeVerticesAndKeepsTheFaceNormal) {
  // A 2 x 1 door in the plane x = 4, subdivided (a vertex mid-edge and one inside), facing +X.
  const std::vector<glm::dvec3> p = {{4, 0, 0}, {4, 0, 2}, {4, 1, 2}, {4, 1, 0}, {4, 0, 1}, {4, 0.5, 1}};
  const std::vector<uint32_t> idx = {0, 3, 5, 3, 2, 5, 2, 1, 5, 1, 4, 5, 4, 0, 5};
  HullPolygon h;
  ASSERT_EQ(hull_polygon(p, idx, 0.0, h), "");
  EXPECT_EQ(h.corners_world.size(), 4u);
  const glm::dvec3 winding =
      glm::cross(h.corners_world[1] - h.corners_world[0], h.corners_world[2] - h.corners_world[0]);
  const glm::dvec3 face = glm::cross(p[3] - p[0], p[5] - p[0]);
  EXPECT_GT(glm::dot(winding, face), 0.0);
  EXPECT_GT(glm::dot(h.normal, face), 0.0);
}

TEST(RoomsPortal, NonPlanarRefusedAtTheScaleAwareTolerance) {
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  HullPolygon h;
  // 1 mm out of plane on a 2.24 m door: under 1e-3 x size, accepted.
  EXPECT_EQ(hull_polygon({{0, 0, 0}, {1, 0, 0}, {1, 2, 0.001}, {0, 2, 0}}, idx, 0.0, h), "");
  EXPECT_NE(hull_polygon({{0, 0, 0}, {1, 0, 0}, {1, 2, 0.05}, {0, 2, 0}}, idx, 0.0, h).find("is not planar"),
            std::string::npos);
  // The same 5 cm accepted when the coordinates' rounding floor is larger (far from the origin).
  EXPECT_EQ(hull_polygon({{0, 0, 0}, {1, 0, 0}, {1, 2, 0.05}, {0, 2, 0}}, idx, 0.1, h), "");
}

TEST(RoomsPortal, LinkFromBehindToFrontAndTheFaultsOtherwise) {
  std::vector<RoomVolume> rooms(3);
  set_box_volume(glm::dmat4(1.0), {0, 0, 0}, {4, 3, 4}, rooms[0]);
  set_box_volume(glm::dmat4(1.0), {4, 0, 0}, {8, 3, 2}, rooms[1]);
  set_box_volume(glm::dmat4(1.0), {4, 0, 2}, {8, 3, 4}, rooms[2]);
  const std::vector<std::string> names = {"A", "B", "C"};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  HullPolygon door;
  // Facing -X (from B into A): z 0.5..1.5 lies against B only.
  ASSERT_EQ(hull_polygon({{4, 0, 0.5}, {4, 0, 1.5}, {4, 2, 1.5}, {4, 2, 0.5}}, idx, 0.0, door), "");
  ASSERT_LT(door.normal.x, -0.99);
  PortalLinkResult link;
  EXPECT_EQ(link_portal(door, rooms, names, link), "");
  EXPECT_EQ(link.from, 1);
  EXPECT_EQ(link.to, 0);
  HullPolygon straddling;  // z 1.5..2.5: both B and C lie behind it
  ASSERT_EQ(hull_polygon({{4, 0, 1.5}, {4, 2, 1.5}, {4, 2, 2.5}, {4, 0, 2.5}}, idx, 0.0, straddling), "");
  EXPECT_NE(link_portal(straddling, rooms, names, link).find("touches 3 rooms ('A', 'B', 'C')"), std::string::npos);
  HullPolygon outer;  // x = 0: only A
  ASSERT_EQ(hull_polygon({{0, 0, 1}, {0, 2, 1}, {0, 2, 2}, {0, 0, 2}}, idx, 0.0, outer), "");
  EXPECT_NE(link_portal(outer, rooms, names, link).find("touches only one room ('A')"), std::string::npos);
}

TEST(RoomsTrs, ShearRefusedRotationScaleAndMirrorKept) {
  NodeDesc node;
  const glm::dmat4 trs = glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), {1, 2, 3}), 0.7, glm::dvec3(0, 1, 0)),
                                    glm::dvec3(2, 1, 0.5));
  ASSERT_TRUE(set_trs_from_matrix(trs, node));
  EXPECT_NEAR(node.scale.x, 2.0f, 1e-6f);
  EXPECT_NEAR(node.scale.z, 0.5f, 1e-6f);
  EXPECT_NEAR(node.translation.y, 2.0f, 1e-6f);
  glm::dmat4 sheared = trs;
  sheared[1][0] += 0.3;
  EXPECT_FALSE(set_trs_from_matrix(sheared, node));
  // A mirror (here in y) is kept as a negative x scale of a rotation: the TRS composes back to it.
  const glm::dmat4 mirrored = glm::scale(trs, glm::dvec3(1, -1, 1));
  ASSERT_TRUE(set_trs_from_matrix(mirrored, node));
  EXPECT_LT(node.scale.x, 0.0f);
  const glm::dmat4 back = glm::translate(glm::dmat4(1.0), glm::dvec3(node.translation)) *
                          glm::mat4_cast(glm::dquat(node.rotation)) *
                          glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(back[c][r], mirrored[c][r], 1e-5) << c << ", " << r;
}

}  // namespace
}  // namespace lintel::rooms
