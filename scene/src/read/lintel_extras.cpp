// Parsing of extras.lintel on nodes and scenes (docs/scene-format.md, "Lintel data").
#include "read/lintel_extras.h"

#include <cmath>

#include "read/json_fields.h"
#include "read/load_limits.h"
#include "read/timeline_json.h"

#include <lintel/version.h>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// extras that are not an object cannot hold Lintel data (glTF allows any type there).
const json* lintel_object(const json& owner) {
  const json* extras = member(owner, "extras");
  return extras ? member(*extras, "lintel") : nullptr;
}

// extras.lintel.portal.link: a target portal's name, or 16 numbers (a column-major 4x4 matrix).
Status read_link(const LoadContext& ctx, const std::string& element, const json& link, NodeTag& out) {
  if (link.is_string()) {
    if (std::string why = read_string(link, out.link_target); !why.empty())
      return ctx.fail(element, "extras.lintel.portal.link " + why);
    if (out.link_target.empty()) return ctx.fail(element, "extras.lintel.portal.link is an empty name");
    return {};
  }
  if (!link.is_array() || link.size() != 16)
    return ctx.fail(element,
                    "extras.lintel.portal.link must be a portal name or 16 numbers (a column-major 4x4 matrix)");
  for (size_t i = 0; i < 16; ++i) {
    double v = 0.0;
    if (std::string why = read_number(link[i], v); !why.empty())
      return ctx.fail(element, "extras.lintel.portal.link[" + std::to_string(i) + "] " + why);
    out.link_matrix[int(i / 4)][int(i % 4)] = v;
  }
  out.link_matrix_given = true;
  return {};
}

Status read_portal(const LoadContext& ctx, const std::string& element, const json& portal, NodeTag& out) {
  if (!portal.is_object()) return ctx.fail(element, "extras.lintel.portal must be an object, got " + json_kind(portal));
  if (const json* mirror = member(portal, "mirror"))
    if (std::string why = read_bool(*mirror, out.mirror); !why.empty())
      return ctx.fail(element, "extras.lintel.portal.mirror " + why);
  const json* link = member(portal, "link");
  if (link && out.mirror) return ctx.fail(element, "extras.lintel.portal has both 'mirror' and 'link'");
  if (link)
    if (Status s = read_link(ctx, element, *link, out); !s) return s;
  for (const char* end : {"from", "to"}) {
    const json* name = member(portal, end);
    std::string& target = end[0] == 'f' ? out.from : out.to;
    // A mirror leads into its own cell; a named link into the target portal's `from` cell.
    if (!name && end[0] == 't' && (out.mirror || !out.link_target.empty())) continue;
    if (!name) return ctx.fail(element, std::string("extras.lintel.portal.") + end + " is missing");
    if (std::string why = read_string(*name, target); !why.empty())
      return ctx.fail(element, std::string("extras.lintel.portal.") + end + " " + why);
    if (target.empty()) return ctx.fail(element, std::string("extras.lintel.portal.") + end + " is empty");
  }
  const bool linked = out.mirror || link;
  if (linked) out.two_way = false;  // a linked portal is one-way unless the file insists (an error later)
  if (const json* two_way = member(portal, "two_way")) {
    if (std::string why = read_bool(*two_way, out.two_way); !why.empty())
      return ctx.fail(element, "extras.lintel.portal.two_way " + why);
    out.two_way_given = true;
  }
  if (linked && out.two_way)
    return ctx.fail(element, std::string("extras.lintel.portal: a ") + (out.mirror ? "mirror" : "linked portal") +
                                 " is one-way (two_way must be false; give the way back its own portal)");
  if (const json* open = member(portal, "open"))
    if (std::string why = read_bool(*open, out.open); !why.empty())
      return ctx.fail(element, "extras.lintel.portal.open " + why);
  for (const auto& [key, value] : portal.items())
    if (key != "from" && key != "to" && key != "two_way" && key != "open" && key != "link" && key != "mirror")
      ctx.warn(element, "unknown key '" + key + "' in extras.lintel.portal (ignored)");
  return {};
}

}  // namespace

Status read_node_tag(const LoadContext& ctx, const std::string& element, const json& node_json, NodeTag& out) {
  out = {};
  const json* lintel = lintel_object(node_json);
  if (!lintel) return {};
  if (!lintel->is_object()) return ctx.fail(element, "extras.lintel must be an object, got " + json_kind(*lintel));

  int kinds = 0;
  if (const json* cell = member(*lintel, "cell")) {
    if (std::string why = read_string(*cell, out.cell_name); !why.empty())
      return ctx.fail(element, "extras.lintel.cell " + why);
    if (out.cell_name.empty()) return ctx.fail(element, "extras.lintel.cell is an empty name");
    out.kind = NodeTag::Kind::Cell;
    ++kinds;
  }
  if (const json* portal = member(*lintel, "portal")) {
    if (Status s = read_portal(ctx, element, *portal, out); !s) return s;
    out.kind = NodeTag::Kind::Portal;
    ++kinds;
  }
  if (const json* volume = member(*lintel, "volume")) {
    bool is_volume = false;
    if (std::string why = read_bool(*volume, is_volume); !why.empty())
      return ctx.fail(element, "extras.lintel.volume " + why);
    if (is_volume) {
      out.kind = NodeTag::Kind::Volume;
      ++kinds;
    }
  }
  if (kinds > 1) return ctx.fail(element, "extras.lintel has more than one of 'cell', 'portal' and 'volume'");
  for (const auto& [key, value] : lintel->items())
    if (key != "cell" && key != "portal" && key != "volume")
      ctx.warn(element, "unknown key '" + key + "' in extras.lintel (ignored)");
  return {};
}

Status read_scene_tag(const LoadContext& ctx, const std::string& element, const json* scene_json, SceneTag& out) {
  out = {};
  const json* lintel = scene_json ? lintel_object(*scene_json) : nullptr;
  if (lintel && !lintel->is_object())
    return ctx.fail(element, "extras.lintel must be an object, got " + json_kind(*lintel));
  const json* version = lintel ? member(*lintel, "version") : nullptr;
  if (!version) {
    ctx.warn(element, "extras.lintel.version is missing; assuming scene format version 1");
  } else {
    int64_t v = 0;
    if (std::string why = read_integer(*version, v); !why.empty())
      return ctx.fail(element, "extras.lintel.version " + why);
    if (v != LINTEL_SCENE_FORMAT_VERSION)
      return ctx.fail(element, "unsupported scene format version " + std::to_string(v) + " (this build reads version " +
                                   std::to_string(LINTEL_SCENE_FORMAT_VERSION) + ")");
    out.version = static_cast<int>(v);
    out.version_given = true;
  }
  if (!lintel) return {};

  if (const json* timelines = member(*lintel, "timelines")) {
    if (!timelines->is_array())
      return ctx.fail(element, "extras.lintel.timelines must be an array, got " + json_kind(*timelines));
    if (timelines->size() > kMaxTimelines)
      return ctx.fail(element, "more than " + std::to_string(kMaxTimelines) + " timelines");
    for (size_t i = 0; i < timelines->size(); ++i) {
      Timeline t;
      if (Status s = parse_timeline(ctx, (*timelines)[i], i, t); !s) return s;
      for (const Timeline& earlier : out.timelines)
        if (earlier.name == t.name) return ctx.fail("timeline '" + t.name + "'", "duplicate timeline name");
      out.timelines.push_back(std::move(t));
    }
  }
  if (const json* env = member(*lintel, "environment")) {
    if (!env->is_object())
      return ctx.fail(element, "extras.lintel.environment must be an object, got " + json_kind(*env));
    glm::vec3 color(1.0f);
    float intensity = 1.0f;
    if (const json* c = member(*env, "color")) {
      if (!c->is_array() || c->size() != 3)
        return ctx.fail(element, "extras.lintel.environment.color must be an array of 3 numbers");
      for (size_t k = 0; k < 3; ++k) {
        const json& v = (*c)[k];
        if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0)
          return ctx.fail(element, "extras.lintel.environment.color[" + std::to_string(k) +
                                       "] must be a finite number >= 0, got " + v.dump());
        color[int(k)] = float(v.get<double>());
      }
    }
    if (const json* i = member(*env, "intensity")) {
      if (!i->is_number() || !std::isfinite(i->get<double>()) || i->get<double>() < 0.0 || i->get<double>() > 1e6)
        return ctx.fail(element,
                        "extras.lintel.environment.intensity must be a finite number in [0, 1e6], got " + i->dump());
      intensity = float(i->get<double>());
    }
    for (const auto& [key, value] : env->items())
      if (key != "color" && key != "intensity")
        ctx.warn(element, "unknown key '" + key + "' in extras.lintel.environment (ignored)");
    out.environment_given = true;
    out.environment = color * intensity;
  }
  for (const auto& [key, value] : lintel->items())
    if (key != "version" && key != "timelines" && key != "environment")
      ctx.warn(element, "unknown key '" + key + "' in extras.lintel (ignored)");
  return {};
}

}  // namespace lintel::scene_read
