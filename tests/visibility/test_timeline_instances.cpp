// Timelines that move named instances (instance_keys): the JSON is read field by field, bad keys
// fail with one line naming the timeline, the key and the fault (and nothing is half-written),
// names resolve against a World, and sampling follows the documented transform rule.
#include "test_worlds.h"

#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace lintel {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "lintel_timeline_instances_" + name + ".json";
  std::ofstream(path) << text;
  return path;
}

const char* kHead = R"({"name": "carry", "fps": 10, "keys": [{"t": 0, "eye": [0, 1.6, 0], "target": [1, 1.6, 0]}], )";

TEST(TimelineInstances, KeysAreReadFieldByField) {
  Timeline t;
  const std::string path = write_temp("good", std::string(kHead) + R"("instance_keys": [
      {"t": 0, "instance": "crate", "translation": [1, 0.5, 2]},
      {"t": 1, "instance": "lamp", "rotation": [0, 0, 0, 1.0005]},
      {"t": 4, "instance": "crate", "translation": [9, 0.5, 2], "rotation": [0, 0.7071068, 0, 0.7071068]}]})");
  const Status s = load_timeline_file(path, t);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(t.instance_keys.size(), 3u);
  EXPECT_EQ(t.instance_keys[0].instance, "crate");
  EXPECT_TRUE(t.instance_keys[0].has_translation && !t.instance_keys[0].has_rotation);
  EXPECT_EQ(t.instance_keys[0].translation_world, glm::vec3(1, 0.5f, 2));
  EXPECT_DOUBLE_EQ(t.instance_keys[1].t, 1.0);
  EXPECT_TRUE(!t.instance_keys[1].has_translation && t.instance_keys[1].has_rotation);
  EXPECT_FLOAT_EQ(t.instance_keys[1].rotation_xyzw.w, 1.0f) << "stored normalized";
  EXPECT_NEAR(glm::length(t.instance_keys[2].rotation_xyzw), 1.0f, 1e-6f);
  EXPECT_NEAR(t.instance_keys[2].rotation_xyzw.y, 0.70710678f, 1e-6f);
}

struct BadKey {
  const char* name;
  const char* keys;
  const char* fault;
};

// Each fails naming the file, "timeline 'carry' instance key <k>" and the fault.
const BadKey kBadKeys[] = {
    {"not_unit", R"([{"t": 1, "instance": "lamp", "rotation": [0, 0, 0, 2]}])",
     "instance key 0: rotation is not a unit quaternion"},
    {"neither", R"([{"t": 1, "instance": "lamp"}])", "instance key 0: has neither 'translation' nor 'rotation'"},
    {"no_name", R"([{"t": 1, "translation": [0, 0, 0]}])", "instance key 0: 'instance' is missing"},
    {"no_t", R"([{"instance": "a", "translation": [0, 0, 0]}])", "instance key 0: 't' is missing"},
    {"short", R"([{"t": 0, "instance": "a", "translation": [0, 0]}])",
     "instance key 0: translation must have 3 numbers, has 2"},
    {"far", R"([{"t": 0, "instance": "a", "translation": [0, 2e6, 0]}])",
     "instance key 0: translation element 1 value 2000000 is farther than"},
    {"nan_rotation", R"([{"t": 0, "instance": "a", "rotation": [0, "x", 0, 1]}])", "instance key 0: rotation"},
    {"backwards",
     R"([{"t": 2, "instance": "a", "translation": [0, 0, 0]}, {"t": 1, "instance": "b", "translation": [0, 0, 0]}])",
     "instance key 1: t 1 is less than the previous instance key's t 2"},
    {"same_t",
     R"([{"t": 2, "instance": "a", "translation": [0, 0, 0]}, {"t": 2, "instance": "a", "translation": [1, 0, 0]}])",
     "instance key 1: t 2 is not greater than the previous key's t 2 of instance 'a'"},
    {"not_array", R"({"t": 2})", "instance_keys must be an array, got object"},
};

TEST(TimelineInstances, BadKeysFailWithOneLineNamingKeyAndFault) {
  for (const BadKey& c : kBadKeys) {
    const std::string path = write_temp(c.name, std::string(kHead) + "\"instance_keys\": " + c.keys + "}");
    Timeline t;
    t.name = "left over";
    const Status s = load_timeline_file(path, t);
    ASSERT_FALSE(s.ok()) << c.name;
    EXPECT_EQ(s.kind(), StatusKind::BadInput) << c.name;
    EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("timeline 'carry'"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find(c.fault), std::string::npos) << c.name << ": " << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
    EXPECT_TRUE(t.name.empty() && t.instance_keys.empty()) << "nothing half-written";
  }
}

// A translation-only key keeps the loaded orientation and scale exactly; translation is linear,
// rotation slerped; before the first key nothing is driven, after the last it holds; names resolve
// (unknown and shared names are errors naming the key).
TEST(TimelineInstances, ResolveAndSampleFollowTheDocumentedRule) {
  testing::TestWorld t = testing::make_chain(2, {.furnish = true});
  const glm::mat4 loaded = t.world.instances[1].mesh_to_world;
  Timeline timeline;
  timeline.name = "carry";
  TimelineInstanceKey a, b;
  a.t = 1.0;
  a.instance = b.instance = t.world.instances[1].name;
  a.has_translation = b.has_translation = true;
  a.translation_world = {1.0f, 2.0f, 3.0f};
  b.t = 3.0;
  b.translation_world = {5.0f, 2.0f, 3.0f};
  b.has_rotation = true;
  b.rotation_xyzw = {0.0f, 0.70710678f, 0.0f, 0.70710678f};  // 90 degrees about +Y
  timeline.instance_keys = {a, b};
  std::vector<InstanceTrack> tracks;
  ASSERT_TRUE(resolve_timeline_instances(t.world, timeline, tracks).ok());
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].instance, 1u);
  glm::mat4 m;
  EXPECT_FALSE(sample_instance_track(timeline, tracks[0], 0.5, m));
  ASSERT_TRUE(sample_instance_track(timeline, tracks[0], 1.0, m));
  for (int c = 0; c < 3; ++c) EXPECT_EQ(glm::vec3(m[c]), glm::vec3(loaded[c])) << "orientation and scale kept exactly";
  EXPECT_EQ(glm::vec3(m[3]), a.translation_world);
  ASSERT_TRUE(sample_instance_track(timeline, tracks[0], 2.0, m));
  EXPECT_NEAR(m[3].x, 3.0f, 1e-6f);
  const glm::mat3 half_turn =
      glm::mat3_cast(glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0))) * glm::mat3(loaded);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(m[c][r], half_turn[c][r], 1e-5f);
  glm::mat4 after;
  ASSERT_TRUE(sample_instance_track(timeline, tracks[0], 10.0, after));
  ASSERT_TRUE(sample_instance_track(timeline, tracks[0], 3.0, m));
  EXPECT_EQ(after, m);
  EXPECT_EQ(glm::vec3(m[3]), b.translation_world);

  timeline.instance_keys[1].instance = "no such thing";
  Status s = resolve_timeline_instances(t.world, timeline, tracks);
  EXPECT_EQ(s.kind(), StatusKind::BadInput);
  EXPECT_NE(s.message().find("timeline 'carry' instance key 1: no instance named 'no such thing'"), std::string::npos)
      << s.message();
  t.world.instances[0].name = t.world.instances[1].name;
  timeline.instance_keys[1].instance = a.instance;
  s = resolve_timeline_instances(t.world, timeline, tracks);
  EXPECT_NE(s.message().find("instance key 0: more than one instance is named"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace lintel
