// A room's shell and volume in building space. The shell faces the room's air: floor, ceiling and
// walls stopping half a wall (slab) short of the mid-planes, with holes and reveals for the
// room's openings; the exterior faces outwards instead. The volume is the closed mid-plane prism.
#pragma once

#include "generate/building_plan.h"
#include "generate/shell_mesh.h"
#include "generate/wall_panel.h"

#include <vector>

namespace lintel::gen {

// Indexed closed triangle mesh, outward facing; positions only (volumes are never drawn).
struct VolumeMesh {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
};

ShellMesh build_room_shell(const BuildingPlan& plan, int room);
VolumeMesh build_room_volume(const BuildingPlan& plan, int room);

// How room `room` sees opening `o`: an open hole, or (the far side of a one-way portal) plugged.
PanelHole::Kind hole_kind(const OpeningPlan& o, int room);
// True when the footprint is an axis-aligned rectangle (then floors and ceilings may have holes).
bool is_axis_aligned_box(const RoomPlan& room);

// The builders behind build_room_shell.
ShellMesh build_box_shell(const BuildingPlan& plan, int room);
ShellMesh build_exterior_shell(const BuildingPlan& plan, int room);
ShellMesh build_prism_shell(const BuildingPlan& plan, int room);

}  // namespace lintel::gen
