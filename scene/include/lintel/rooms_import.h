// The rooms convention (Godot 3 rooms and portals, authored in Blender): a plain glTF whose node
// names say what they are ('Hall-room', 'Door-portal', 'Window-portal-oneway', 'Hall-bound').
// import_rooms turns such a file into a Lintel scene, export_rooms a Lintel World back into one.
// Every rule and message: docs/rooms.md.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lintel {

// Name suffixes (an optional Blender duplicate tail ".001" may follow each).
inline constexpr const char* kRoomSuffix = "-room";
inline constexpr const char* kPortalSuffix = "-portal";
inline constexpr const char* kOneWayPortalSuffix = "-portal-oneway";
inline constexpr const char* kMirrorSuffix = "-mirror";  // its face looks into the room it reflects
inline constexpr const char* kBoundSuffix = "-bound";

struct RoomsImportStats {
  uint32_t rooms = 0, bounds = 0, portals = 0, one_way = 0, instances = 0, lights = 0;
};

// Reads `path` (.gltf with its buffers, or .glb; the same safety checks and limits as load_world)
// and builds the Lintel scene. Bad input: a one-line Status::error naming the file, the node and
// the fault ("in.glb: node 4 'Door-portal': portal touches only one room ('Hall'); ..."); `out`
// is then empty. Usable oddities (a mesh outside every room) add lines to `warnings`.
Status import_rooms(const std::string& path, SceneDesc& out, std::vector<std::string>* warnings = nullptr,
                    RoomsImportStats* stats = nullptr);

// The same on an in-memory file; `label` names it in messages, `base_dir` resolves external
// buffers (empty: embedded buffers only).
Status import_rooms_from_memory(const uint8_t* bytes, size_t size, const std::string& label,
                                const std::string& base_dir, SceneDesc& out,
                                std::vector<std::string>* warnings = nullptr, RoomsImportStats* stats = nullptr);

// A World in the rooms convention: every cell a root node '<cell>-room' with the cell's frame and
// shell, its volume (the volume mesh, or its box when the file gave none) as '<cell>-bound', its
// instances and lights below it; every portal a root node '<portal>-portal' (or
// '-portal-oneway') whose polygon winds from `from` into `to`. Timelines, the sky and door states
// are not part of the convention and are dropped. Status::unsupported when a transform cannot be stored
// as translation/rotation/scale (shear).
Status export_rooms(const World& world, SceneDesc& out);

// The documentation example: a small house authored in the rooms convention (docs/rooms.md).
SceneDesc generate_rooms_example();

}  // namespace lintel
