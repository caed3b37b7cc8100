// The Lintel data in glTF `extras.lintel`: what a node is (cell, portal, volume or nothing) and
// the scene-level keys (format version, timelines). Wrong JSON types are errors; unknown keys are
// warnings, so that files written by a newer tool still load.
#pragma once

#include "read/load_context.h"

#include <lintel/world.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lintel::scene_read {

struct NodeTag {
  enum class Kind { None, Cell, Portal, Volume };
  Kind kind = Kind::None;
  std::string cell_name;  // Kind::Cell
  std::string from, to;   // Kind::Portal
  bool two_way = true;    // Kind::Portal
  bool open = true;       // Kind::Portal: the door state at load (both directions)
  bool two_way_given = false;
  // Kind::Portal links (docs/scene-format.md, "Linked portals"): a mirror, a target portal's
  // name, or a 4x4 column-major matrix. `to` may be absent for a mirror or a named link.
  bool mirror = false;
  std::string link_target;
  bool link_matrix_given = false;
  glm::dmat4 link_matrix{1.0};
};

// Reads node_json.extras.lintel (absent: Kind::None). `element` names the node in messages.
Status read_node_tag(const LoadContext& ctx, const std::string& element, const nlohmann::json& node_json, NodeTag& out);

struct SceneTag {
  int version = 1;
  bool version_given = false;
  std::vector<Timeline> timelines;
  bool environment_given = false;
  glm::vec3 environment{0.0f};  // extras.lintel.environment: color x intensity
};

// Reads scene_json.extras.lintel: version (missing: a warning, 1 assumed), timelines and the
// environment ({"color": [r, g, b], "intensity": i}, each finite and >= 0; color defaults to
// white, intensity to 1).
// `scene_json` may be null (a file without scenes).
Status read_scene_tag(const LoadContext& ctx, const std::string& element, const nlohmann::json* scene_json,
                      SceneTag& out);

}  // namespace lintel::scene_read
