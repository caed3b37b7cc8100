// Two 4 x 2.5 x 4 m rooms side by side along +X, each with its own walls (a 0.2 m gap between
// them), a crate in each and a point light in room "A" only, built as a SceneDesc so it goes
// through the writer and the validating loader like every other scene. `door`: a 1 x 2 m door
// through both walls (with reveals) and a two-way portal between the rooms; without it the
// rooms are sealed and share nothing. Cell frames are not the identity (B is turned 90 degrees),
// so the shaders' cell-space paths are exercised.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

namespace lintel::render::test {

SceneDesc two_rooms(bool door);

// From across room A at eye height towards its crate, which is in the middle of the frame.
View towards_crate_a(float aspect);
// Room A's crate mesh ("room_A_crate") in a two_rooms scene; throws (the test fails) unless there
// is exactly one.
MeshDesc& crate_a(SceneDesc& desc);
// `desc` through build_world (GLB, then the validating loader); a load error fails the test.
World built_world(const SceneDesc& desc);

// Interior boxes in world space (air of each room) and the light's position.
inline constexpr float kRoomAMinX = 0.0f, kRoomAMaxX = 4.0f;
inline constexpr float kRoomBMinX = 4.2f, kRoomBMaxX = 8.2f;
inline constexpr float kRoomDepth = 4.0f, kRoomHeight = 2.5f;
inline const glm::vec3 kLightA{2.0f, 2.0f, 2.0f};

}  // namespace lintel::render::test
