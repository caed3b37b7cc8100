// The generators' common language. A building is planned in "building space" (meters, +Y up):
// rooms are prisms bounded by wall and slab MID-PLANES, openings are rectangles on those
// mid-planes, furniture and lights have rigid transforms. One rigid transform places the building
// in the world, and every cell gets its own frame; assemble_scene() (scene_assembly.h) turns the
// plan into a SceneDesc with the shells compensated for those frames.
#pragma once

#include <lintel/scene_desc.h>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace lintel::gen {

// Thick walls and slabs: each room's shell stops half a thickness short of the mid-plane, except
// around openings, where reveals line the opening up to the mid-plane. Neighbours never share a
// face, and a ray through an opening hits nothing until the next room.
inline constexpr double kWallThickness = 0.2;
inline constexpr double kSlabThickness = 0.2;
inline constexpr double kEyeHeight = 1.6;  // above the floor, for the timelines
inline constexpr double kDoorWidth = 0.9;
inline constexpr double kDoorHeight = 2.1;
inline constexpr double kWindowSize = 1.0;
inline constexpr double kWindowSill = 0.9;

inline const glm::dquat kNoRotation{1.0, 0.0, 0.0, 0.0};

// A cell node's transform in world space (glTF TRS); any rotation, positive scale.
struct CellFrame {
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
};

struct RoomPlan {
  std::string name;  // the cell name
  // Wall mid-plane outline in building (x, z), convex, counter-clockwise in the (x, z) plane
  // (positive shoelace area). Axis-aligned rectangles may have openings in floor and ceiling.
  std::vector<glm::dvec2> footprint;
  double floor_mid = 0.0;    // slab mid-plane below the room; for the exterior: the ground level
  double ceiling_mid = 0.0;  // slab mid-plane above; for the exterior: the roof slab's mid-plane
  // The outside of a building with a rectangular footprint: ground plane (out to ground_margin
  // beyond the facade), facade facing out, flat roof. Its volume is a big box with the house cut out.
  bool exterior = false;
  double ground_margin = 15.0;
  double sky_height = 12.0;  // exterior volume: how far above the roof it reaches
  CellFrame frame;
  bool volume = true;  // emit a volume node (the mid-plane prism) for this cell
  glm::vec4 color{0.85f, 0.83f, 0.78f, 1.0f};
};

// A rectangle on a wall or slab mid-plane: points origin + u * u_axis + v * v_axis for u in
// [u0, u1], v in [v0, v1]. Walls: v_axis = +Y (v is the height). Slabs: u_axis = +X, v_axis = +Z.
struct OpeningPlan {
  std::string name;
  int from = -1;  // room indices
  int to = -1;
  bool two_way = true;
  bool in_slab = false;
  glm::dvec3 origin{0.0};
  glm::dvec3 u_axis{1.0, 0.0, 0.0};
  glm::dvec3 v_axis{0.0, 1.0, 0.0};
  double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
  glm::dvec3 normal{0.0};  // unit, from `from` into `to`
  // A linked portal (two_way false): a mirror, or `link` names the target opening (a teleport).
  // It cuts no hole: it lies on the room's inner wall face, and the shells skip it.
  bool mirror = false;
  std::string link;
  bool linked() const { return mirror || !link.empty(); }

  glm::dvec3 point(double u, double v) const { return origin + u * u_axis + v * v_axis; }
  glm::dvec3 center() const { return point(0.5 * (u0 + u1), 0.5 * (v0 + v1)); }
};

struct InstancePlan {
  std::string name;
  int room = -1;
  int mesh = -1;             // index into BuildingPlan::meshes
  glm::dvec3 position{0.0};  // building space, where the mesh origin goes
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
};

struct LightPlan {
  int room = -1;
  LightDesc light;
  glm::dvec3 position{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // the light shines along the rotated -Z
};

struct BuildingPlan {
  std::vector<MeshDesc> meshes;  // furniture, shared by instances
  std::vector<RoomPlan> rooms;
  std::vector<OpeningPlan> openings;
  std::vector<InstancePlan> instances;
  std::vector<LightPlan> lights;
  std::vector<Timeline> timelines;       // keys in building space
  glm::dvec3 building_translation{0.0};  // building space -> world: translate(t) * rotate(r)
  glm::dquat building_rotation{1.0, 0.0, 0.0, 0.0};
};

// Helpers for axis-aligned plans.
// A room whose mid-plane outline is [x0, x1] x [z0, z1] between slab mid-planes y0 and y1.
RoomPlan box_room(std::string name, double x0, double x1, double z0, double z1, double y0, double y1);
// An opening in the wall on the plane x = x_mid, spanning z in [z0, z1] and y in [y0, y1];
// `toward_plus_x`: `to` lies on the +X side.
OpeningPlan opening_x(int from, int to, double x_mid, double z0, double z1, double y0, double y1, bool toward_plus_x);
// The same on the plane z = z_mid, spanning x in [x0, x1].
OpeningPlan opening_z(int from, int to, double z_mid, double x0, double x1, double y0, double y1, bool toward_plus_z);
// A hole in the slab y = y_mid over [x0, x1] x [z0, z1]; `upward`: `to` lies above.
OpeningPlan opening_slab(int from, int to, double y_mid, double x0, double x1, double z0, double z1, bool upward);

// Building space -> world for the plan's building transform.
glm::dmat4 building_to_world(const BuildingPlan& plan);

}  // namespace lintel::gen
