// `lintel optimize`: cells merged where a finer split buys no culling (steps of a stair, light-level
// sectors, slivers, cells whose portal openings cover most of their shared walls), so that the
// builder walks fewer cells and portals. Works on a loaded World (any scene the loader accepts) and
// writes a SceneDesc; every rule: docs/levels.md, "Optimize".
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel {

struct OptimizeOptions {
  // Two cells merge when their portals' area is at least this fraction of the wall they share
  // (the union of both cells' volume boundaries in the portal planes): a stair step of 16 in 128
  // units is 0.875, a light-level sector 1.0, a door in a wall far less. Horizontal portals
  // (hatches) are not judged.
  double min_open_fraction = 0.75;
  // A sliver (volume below sliver_volume_m3, or 3 volume / surface below sliver_thickness_m: a
  // Doom door sector is 0.3 m) merges into the neighbour it shares the most portal area with.
  double sliver_volume_m3 = 0.5;
  double sliver_thickness_m = 0.35;
  // A merged cell stays within these: parts, and the largest extent of its world bounds (m).
  uint32_t max_parts = 64;
  double max_extent_m = 40.0;
};

struct OptimizeReport {
  uint32_t cells_before = 0, cells_after = 0, portals_before = 0, portals_after = 0;
  uint32_t open_wall_merges = 0;         // pairs merged by min_open_fraction
  uint32_t sliver_merges = 0;            // slivers merged into a neighbour
  uint32_t closable_portals = 0;         // portals never merged across (closed, one-way, or a timeline door)
  std::vector<uint32_t> merged_cell_of;  // per input cell: its cell in the output (cell order kept by first part)
};

// Writes `world` with merged cells to `out`. A merged cell is named after its first part (lowest
// index), keeps that part's frame, and is the union of its parts: shells concatenated into one
// mesh (parts of different colours keep them as vertex colours under a white base colour; parts
// with different textures, samplers or sidedness never merge), volumes concatenated (the loader's winding-number point-in-volume takes a union of
// closed pieces), its portals the parts' outer portals; portals inside it are dropped. Never merges
// across a closable portal: closed in either direction, one-way, or named by a timeline event.
// Instances, lights, textures (with their samplers), timelines and the sky are kept (world-space
// timelines need no remapping; door events name portals that are never dropped). Status::unsupported when a transform relative to a
// merged cell is sheared (a non-uniformly scaled cell frame). `out` is empty on error.
Status optimize_world(const World& world, const OptimizeOptions& options, SceneDesc& out,
                      OptimizeReport* report = nullptr);

// The same on a scene description: loads it through the validating loader (`label` names it in
// messages) and optimizes the World.
Status optimize_scene(const SceneDesc& scene, const std::string& label, const OptimizeOptions& options, SceneDesc& out,
                      OptimizeReport* report = nullptr);

}  // namespace lintel
