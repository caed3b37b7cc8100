// One frame, end to end, for `lintel cull <scene> --eye ... --target ... [--gpu|--cpu] [--json]`:
// the viewer cell, the visibility query, then the instance cull on the GPU pass or by the CPU
// reference, reported per draw group as the indirect command it draws with.
#pragma once

#include <lintel/gpu/cull_shared.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::gpu {

struct CullQueryOptions {
  View view;                     // validated: a bad camera is a Status, not an assert
  bool use_gpu = true;           // false: the CPU reference (lintel::cull_instances)
  VisibilityOptions visibility;  // cull_instances is forced on
  std::string device;            // as ContextOptions::device
  bool validation = false;       // Khronos validation for the GPU run; any message is an error
};

struct GroupDraw {
  uint32_t group = 0;
  uint32_t mesh = 0;
  std::string mesh_name;
  DrawIndexedCommand command{};     // firstInstance = the group's base; instanceCount = drawn
  std::vector<uint32_t> instances;  // World::instances indices drawn, ascending
};

// What one linked view (a mirror or teleport seen by the camera) draws: its cells and the
// instances the CPU cull finds visible through it (VisibleSet::linked_instances). Linked views are
// few and culled on the CPU by both methods; the GPU pass culls the plain view.
struct LinkedViewDraw {
  uint32_t transform = 0;           // VisibleSet::transforms index (>= 1)
  uint32_t portal = 0;              // the linked portal it is seen through
  uint32_t depth = 0;               // linked portals in its chain
  bool mirrored = false;            // seen through an odd number of mirrors
  std::vector<uint32_t> cells;      // its linked cells, ascending
  std::vector<uint32_t> instances;  // ascending
};

struct CullQueryResult {
  std::string method;  // "gpu" or "cpu"
  std::string device;  // the Vulkan device for "gpu"
  uint32_t start_cell = 0;
  std::vector<uint32_t> visible_cells;  // ascending
  uint32_t visible_instances = 0;
  std::vector<GroupDraw> groups;             // every draw group, in World::groups order
  std::vector<LinkedViewDraw> linked_views;  // views with at least one cell, in transform order
  uint32_t unresolved_links = 0;             // linked portals seen beyond the depth or budget
  VisibilityStats stats;
};

// Errors: invalid view or options, a world without cells, Vulkan device/feature errors (with
// use_gpu), validation messages (with validation).
Status cull_query(const World& world, const CullQueryOptions& options, CullQueryResult& out);

}  // namespace lintel::gpu
