// Timeline objects: {"name", "fps", "fov_y_deg", "aspect", "keys": [{"t", "eye", "target"}],
// "events": [{"t", "portal", "open"}], "instance_keys": [{"t", "instance", "translation", "rotation"}]}
// (events and instance keys optional; their portal and instance names are resolved later).
// Also load_timeline_file(), the public entry point for standalone timeline files.
#include "read/timeline_json.h"

#include "read/file_read.h"
#include "read/json_bounded.h"
#include "read/json_fields.h"
#include "read/load_limits.h"

#include <lintel/scene_io.h>

#include <cmath>
#include <map>
#include <utility>
#include <exception>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

Status read_optional_number(const LoadContext& ctx, const std::string& element, const json& obj, const char* key,
                            double& value) {
  if (const json* v = member(obj, key))
    if (std::string why = read_number(*v, value); !why.empty()) return ctx.fail(element, std::string(key) + " " + why);
  return {};
}

Status parse_key(const LoadContext& ctx, const std::string& element, const json& value, TimelineKey& out) {
  if (!value.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(value));
  const json* t = member(value, "t");
  if (!t) return ctx.fail(element, "'t' is missing");
  if (std::string why = read_number(*t, out.t); !why.empty()) return ctx.fail(element, "t " + why);
  for (const char* name : {"eye", "target"}) {
    const json* v = member(value, name);
    if (!v) return ctx.fail(element, std::string("'") + name + "' is missing");
    glm::vec3& target = name[0] == 'e' ? out.eye_world : out.target_world;
    if (std::string why = read_vec3(*v, target); !why.empty()) return ctx.fail(element, std::string(name) + " " + why);
  }
  // Far-away cameras are named as such (in float, |eye| of 3e38 overflows to inf and every
  // distance test after it reads as "coincide").
  for (const auto& [name, p] : {std::pair{"eye", out.eye_world}, std::pair{"target", out.target_world}})
    for (int i = 0; i < 3; ++i)
      if (!(std::fabs(double(p[i])) <= kMaxTimelineCoordinate))
        return ctx.fail(element, std::string(name) + " element " + std::to_string(i) + " value " + number_text(p[i]) +
                                     " is farther than " + number_text(kMaxTimelineCoordinate) + " m from the origin");
  // A camera needs a direction: eye == target leaves the view matrix undefined.
  const double scale = std::max(1.0, glm::length(glm::dvec3(out.eye_world)));
  if (glm::length(glm::dvec3(out.target_world) - glm::dvec3(out.eye_world)) <= 1e-6 * scale)
    return ctx.fail(element, "eye and target coincide (no view direction)");
  return {};
}

Status parse_event(const LoadContext& ctx, const std::string& element, const json& value, TimelineEvent& out) {
  if (!value.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(value));
  const json* t = member(value, "t");
  if (!t) return ctx.fail(element, "'t' is missing");
  if (std::string why = read_number(*t, out.t); !why.empty()) return ctx.fail(element, "t " + why);
  const json* portal = member(value, "portal");
  if (!portal) return ctx.fail(element, "'portal' is missing");
  if (std::string why = read_string(*portal, out.portal); !why.empty()) return ctx.fail(element, "portal " + why);
  const json* open = member(value, "open");
  if (!open) return ctx.fail(element, "'open' is missing");
  if (std::string why = read_bool(*open, out.open); !why.empty()) return ctx.fail(element, "open " + why);
  for (const auto& [key, v] : value.items())
    if (key != "t" && key != "portal" && key != "open") ctx.warn(element, "unknown key '" + key + "' (ignored)");
  return {};
}

Status parse_events(const LoadContext& ctx, const std::string& element, const json& events, Timeline& out) {
  if (!events.is_array()) return ctx.fail(element, "events must be an array, got " + json_kind(events));
  if (events.size() > kMaxTimelineKeys)
    return ctx.fail(element, "more than " + std::to_string(kMaxTimelineKeys) + " events");
  out.events.resize(events.size());
  for (size_t k = 0; k < events.size(); ++k) {
    const std::string event_element = element + " event " + std::to_string(k);
    if (Status s = parse_event(ctx, event_element, events[k], out.events[k]); !s) return s;
    if (k > 0 && out.events[k].t < out.events[k - 1].t)
      return ctx.fail(event_element, "t " + number_text(out.events[k].t) + " is less than the previous event's t " +
                                         number_text(out.events[k - 1].t));
  }
  return {};
}

// {"t", "instance", "translation"?, "rotation"?}: at least one of the two; rotation a unit
// quaternion [x, y, z, w] (within 1e-3 of unit length; stored normalized).
Status parse_instance_key(const LoadContext& ctx, const std::string& element, const json& value,
                          TimelineInstanceKey& out) {
  if (!value.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(value));
  const json* t = member(value, "t");
  if (!t) return ctx.fail(element, "'t' is missing");
  if (std::string why = read_number(*t, out.t); !why.empty()) return ctx.fail(element, "t " + why);
  const json* instance = member(value, "instance");
  if (!instance) return ctx.fail(element, "'instance' is missing");
  if (std::string why = read_string(*instance, out.instance); !why.empty()) return ctx.fail(element, "instance " + why);
  const json* translation = member(value, "translation");
  const json* rotation = member(value, "rotation");
  if (!translation && !rotation) return ctx.fail(element, "has neither 'translation' nor 'rotation'");
  if (translation) {
    out.has_translation = true;
    if (std::string why = read_vec3(*translation, out.translation_world); !why.empty())
      return ctx.fail(element, "translation " + why);
    for (int i = 0; i < 3; ++i)
      if (!(std::fabs(double(out.translation_world[i])) <= kMaxTimelineCoordinate))
        return ctx.fail(element, "translation element " + std::to_string(i) + " value " +
                                     number_text(out.translation_world[i]) + " is farther than " +
                                     number_text(kMaxTimelineCoordinate) + " m from the origin");
  }
  if (rotation) {
    out.has_rotation = true;
    float q[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    if (std::string why = read_float_array(*rotation, 4, q); !why.empty()) return ctx.fail(element, "rotation " + why);
    const double norm =
        std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(std::fabs(norm - 1.0) <= 1e-3))
      return ctx.fail(element, "rotation is not a unit quaternion [x, y, z, w] (length " + number_text(norm) + ")");
    out.rotation_xyzw = glm::vec4(float(q[0] / norm), float(q[1] / norm), float(q[2] / norm), float(q[3] / norm));
  }
  for (const auto& [key, v] : value.items())
    if (key != "t" && key != "instance" && key != "translation" && key != "rotation")
      ctx.warn(element, "unknown key '" + key + "' (ignored)");
  return {};
}

Status parse_instance_keys(const LoadContext& ctx, const std::string& element, const json& keys, Timeline& out) {
  if (!keys.is_array()) return ctx.fail(element, "instance_keys must be an array, got " + json_kind(keys));
  if (keys.size() > kMaxTimelineKeys)
    return ctx.fail(element, "more than " + std::to_string(kMaxTimelineKeys) + " instance keys");
  out.instance_keys.resize(keys.size());
  std::map<std::string, double> last_t;  // per instance name
  for (size_t k = 0; k < keys.size(); ++k) {
    const std::string key_element = element + " instance key " + std::to_string(k);
    TimelineInstanceKey& key = out.instance_keys[k];
    if (Status s = parse_instance_key(ctx, key_element, keys[k], key); !s) return s;
    if (k > 0 && key.t < out.instance_keys[k - 1].t)
      return ctx.fail(key_element, "t " + number_text(key.t) + " is less than the previous instance key's t " +
                                       number_text(out.instance_keys[k - 1].t));
    const auto [at, fresh] = last_t.emplace(key.instance, key.t);
    if (!fresh) {
      if (!(key.t > at->second))
        return ctx.fail(key_element, "t " + number_text(key.t) + " is not greater than the previous key's t " +
                                         number_text(at->second) + " of instance '" + one_line(key.instance, 64) + "'");
      at->second = key.t;
    }
  }
  return {};
}

}  // namespace

Status parse_timeline(const LoadContext& ctx, const json& value, size_t index, Timeline& out) {
  out = Timeline{};
  std::string element = "timeline " + std::to_string(index);
  if (!value.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(value));
  const json* name = member(value, "name");
  if (!name) return ctx.fail(element, "'name' is missing");
  if (std::string why = read_string(*name, out.name); !why.empty()) return ctx.fail(element, "name " + why);
  if (out.name.empty()) return ctx.fail(element, "name is empty");
  element = "timeline '" + one_line(out.name, 64) + "'";

  if (Status s = read_optional_number(ctx, element, value, "fps", out.fps); !s) return s;
  if (Status s = read_optional_number(ctx, element, value, "fov_y_deg", out.fov_y_deg); !s) return s;
  if (Status s = read_optional_number(ctx, element, value, "aspect", out.aspect); !s) return s;
  if (!(out.fps > 0.0 && out.fps <= kMaxTimelineFps))
    return ctx.fail(element, "fps " + number_text(out.fps) + " is outside (0, " + number_text(kMaxTimelineFps) + "]");
  if (!(out.fov_y_deg > 0.0 && out.fov_y_deg < 180.0))
    return ctx.fail(element, "fov_y_deg " + number_text(out.fov_y_deg) + " is outside (0, 180)");
  if (!(out.aspect > 0.0 && out.aspect <= kMaxTimelineAspect))
    return ctx.fail(element,
                    "aspect " + number_text(out.aspect) + " is outside (0, " + number_text(kMaxTimelineAspect) + "]");

  const json* keys = member(value, "keys");
  if (!keys) return ctx.fail(element, "'keys' is missing");
  if (!keys->is_array()) return ctx.fail(element, "keys must be an array, got " + json_kind(*keys));
  if (keys->empty()) return ctx.fail(element, "keys is empty (a timeline needs at least one key)");
  if (keys->size() > kMaxTimelineKeys)
    return ctx.fail(element, "more than " + std::to_string(kMaxTimelineKeys) + " keys");
  out.keys.resize(keys->size());
  for (size_t k = 0; k < keys->size(); ++k) {
    const std::string key_element = element + " key " + std::to_string(k);
    if (Status s = parse_key(ctx, key_element, (*keys)[k], out.keys[k]); !s) return s;
    if (k > 0 && !(out.keys[k].t > out.keys[k - 1].t))
      return ctx.fail(key_element, "t " + number_text(out.keys[k].t) + " is not greater than the previous key's t " +
                                       number_text(out.keys[k - 1].t));
  }
  const double frames = (out.keys.back().t - out.keys.front().t) * out.fps;
  if (!(frames <= kMaxTimelineFrames))
    return ctx.fail(element,
                    "spans " + number_text(frames) + " frames, over the limit of " + number_text(kMaxTimelineFrames));
  if (const json* events = member(value, "events"))
    if (Status s = parse_events(ctx, element, *events, out); !s) return s;
  if (const json* instance_keys = member(value, "instance_keys"))
    if (Status s = parse_instance_keys(ctx, element, *instance_keys, out); !s) return s;
  for (const auto& [key, v] : value.items())
    if (key != "name" && key != "fps" && key != "fov_y_deg" && key != "aspect" && key != "keys" && key != "events" &&
        key != "instance_keys")
      ctx.warn(element, "unknown key '" + key + "' (ignored)");
  return {};
}

}  // namespace lintel::scene_read

namespace lintel {

namespace {

Status read_timeline_file(const scene_read::LoadContext& ctx, const std::string& path, Timeline& out) {
  std::vector<uint8_t> bytes;
  if (std::string why = scene_read::read_file_bounded(path, scene_read::kMaxTimelineFileBytes, bytes); !why.empty())
    return ctx.fail("", why);
  nlohmann::json doc;
  if (std::string why = scene_read::parse_json_bounded(reinterpret_cast<const char*>(bytes.data()), bytes.size(), doc);
      !why.empty())
    return ctx.fail("", why);
  return scene_read::parse_timeline(ctx, doc, 0, out);
}

}  // namespace

Status load_timeline_file(const std::string& path, Timeline& out) {
  out = Timeline{};
  const scene_read::LoadContext ctx(path, nullptr);
  Timeline parsed;
  Status status;
  try {  // the boundary: nothing thrown below (bad_alloc included) leaves this function
    status = read_timeline_file(ctx, path, parsed);
  } catch (const std::exception& e) {
    status = ctx.fail("", std::string("internal error while loading: ") + e.what());
  }
  if (status) out = std::move(parsed);
  return status;
}

}  // namespace lintel
