// libFuzzer target for camera timelines (the JSON object of scene.extras.lintel.timelines and of
// standalone timeline files, scene/src/read/timeline_json.cpp), followed by what `lintel walk` does with
// an accepted one: count its frames and place the camera at every frame.
// Property: any input either fails with one proper error line, or yields a timeline whose keys
// are non-empty, strictly increasing in t and finite, whose lens is in range, whose frame count is
// within kMaxTimelineFrames, and whose sampled eyes and targets are finite and inside the keys'
// bounding box (linear interpolation never leaves it).
#include "read/json_bounded.h"
#include "read/load_context.h"
#include "read/timeline_json.h"
#include "world_invariants.h"

#include <lintel/timeline.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void broken(const std::string& why) {
  std::fprintf(stderr, "timeline invariant broken: %s\n", why.c_str());
  std::abort();
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_accepted(const lintel::Timeline& tl) {
  using lintel::scene_read::kMaxTimelineFrames;
  if (tl.keys.empty()) broken("no keys");
  if (tl.name.empty()) broken("empty name");
  if (!(tl.fps > 0.0 && tl.fps <= lintel::scene_read::kMaxTimelineFps)) broken("fps out of range");
  if (!(tl.fov_y_deg > 0.0 && tl.fov_y_deg < 180.0)) broken("fov out of range");
  if (!(tl.aspect > 0.0 && tl.aspect <= lintel::scene_read::kMaxTimelineAspect)) broken("aspect out of range");
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (size_t k = 0; k < tl.keys.size(); ++k) {
    const lintel::TimelineKey& key = tl.keys[k];
    if (!std::isfinite(key.t) || !finite(key.eye_world) || !finite(key.target_world)) broken("non-finite key");
    if (k > 0 && !(key.t > tl.keys[k - 1].t)) broken("keys not strictly increasing");
    if (key.eye_world == key.target_world) broken("eye == target in a key");
    lo = glm::min(lo, glm::min(key.eye_world, key.target_world));
    hi = glm::max(hi, glm::max(key.eye_world, key.target_world));
  }
  const size_t frames = lintel::timeline_frame_count(tl);
  if (frames < 1 || double(frames) > kMaxTimelineFrames + 1.0) broken("frame count " + std::to_string(frames));
  // Every frame for short timelines, else a sample (the fuzzer must stay fast).
  const size_t step = std::max<size_t>(1, frames / 256);
  auto inside = [&](const glm::vec3& p) {
    // One float ulp of slack per coordinate: a + s * (b - a) may round just outside [a, b].
    const glm::vec3 slack = glm::max(glm::abs(lo), glm::abs(hi)) * 1e-6f;
    return glm::all(glm::greaterThanEqual(p, lo - slack)) && glm::all(glm::lessThanEqual(p, hi + slack));
  };
  for (size_t f = 0; f < frames; f += step) {
    const double t = tl.keys.front().t + double(f) / tl.fps;
    const lintel::CameraPose pose = lintel::sample_timeline(tl, t);
    if (!finite(pose.eye_world) || !finite(pose.target_world)) broken("non-finite pose at frame " + std::to_string(f));
    if (!inside(pose.eye_world) || !inside(pose.target_world))
      broken("pose outside the keys' bounds at frame " + std::to_string(f));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  nlohmann::json doc;
  if (!lintel::scene_read::parse_json_bounded(reinterpret_cast<const char*>(data), size, doc).empty()) return 0;
  std::vector<std::string> warnings;
  const lintel::scene_read::LoadContext ctx("fuzz", &warnings);
  lintel::Timeline timeline;
  lintel::Status s;
  try {  // load_timeline_file's boundary does the same
    s = lintel::scene_read::parse_timeline(ctx, doc, 0, timeline);
  } catch (const std::exception& e) {
    broken(std::string("parse_timeline threw: ") + e.what());
  }
  if (!s.ok()) {
    if (std::string why = lintel::fuzz::error_message_violation(s.message(), "fuzz"); !why.empty()) broken(why);
    return 0;
  }
  for (const std::string& w : warnings)
    if (std::string why = lintel::fuzz::error_message_violation(w, "fuzz"); !why.empty()) broken("warning: " + why);
  check_accepted(timeline);
  return 0;
}
