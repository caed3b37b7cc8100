// Standalone timeline files (load_timeline_file): the valid one is read field by field; each bad
// one (tests/scene/fixtures/timelines/bad) fails with one line naming the file, the timeline or
// key, and the fault, and leaves the output empty.
#include "fixture_support.h"

#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include <gtest/gtest.h>

namespace lintel {
namespace {

TEST(TimelineFile, ValidFileIsReadFieldByField) {
  Timeline t;
  const Status s = load_timeline_file(test::fixture("timelines/orbit.json"), t);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(t.name, "orbit");
  EXPECT_DOUBLE_EQ(t.fps, 24.0);
  EXPECT_DOUBLE_EQ(t.fov_y_deg, 75.0);
  EXPECT_DOUBLE_EQ(t.aspect, 2.0);
  ASSERT_EQ(t.keys.size(), 3u);
  EXPECT_DOUBLE_EQ(t.keys[0].t, 0.5);
  EXPECT_EQ(t.keys[1].eye_world, glm::vec3(5, 1, 0));
  EXPECT_EQ(t.keys[2].target_world, glm::vec3(0, 1, 0));
  EXPECT_EQ(timeline_frame_count(t), 61u);  // 2.5 s at 24 fps, both ends included
}

struct BadTimeline {
  const char* file;
  const char* element;
  const char* fault;
};

std::ostream& operator<<(std::ostream& out, const BadTimeline& c) { return out << c.file; }

const BadTimeline kBadTimelines[] = {
    {"no_keys", "timeline 'orbit'", "keys is empty"},
    {"keys_missing", "timeline 'orbit'", "'keys' is missing"},
    {"keys_not_array", "timeline 'orbit'", "keys must be an array, got object"},
    {"t_not_increasing", "timeline 'orbit' key 2", "t 1.5 is not greater than the previous key's t 1.5"},
    {"fps_zero", "timeline 'orbit'", "fps 0 is outside (0, 1000]"},
    {"fps_negative", "timeline 'orbit'", "fps -30 is outside (0, 1000]"},
    {"fps_not_number", "timeline 'orbit'", "fps must be a number, got string"},
    {"fov_zero", "timeline 'orbit'", "fov_y_deg 0 is outside (0, 180)"},
    {"fov_180", "timeline 'orbit'", "fov_y_deg 180 is outside (0, 180)"},
    {"eye_not_finite", "timeline 'orbit' key 1", "eye element 0 value 1e+39 is not finite as a 32-bit float"},
    {"eye_too_short", "timeline 'orbit' key 1", "eye must have 3 numbers, has 2"},
    {"eye_equals_target", "timeline 'orbit' key 1", "eye and target coincide"},
    {"name_missing", "timeline 0", "'name' is missing"},
    {"not_json", "", "not valid JSON"},
    {"not_object", "timeline 0", "must be an object, got array"},
};

class BadTimelineFile : public ::testing::TestWithParam<BadTimeline> {};

TEST_P(BadTimelineFile, FailsWithOneLineNamingFileElementAndFault) {
  const BadTimeline& c = GetParam();
  const std::string path = test::fixture(std::string("timelines/bad/") + c.file + ".json");
  Timeline t;
  t.name = "left over";
  const Status s = load_timeline_file(path, t);
  ASSERT_FALSE(s.ok());
  const std::string& m = s.message();
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  const std::string head = *c.element ? path + ": " + c.element + ": " : path + ": ";
  EXPECT_EQ(m.rfind(head, 0), 0u) << m;
  EXPECT_NE(m.find(c.fault), std::string::npos) << m;
  EXPECT_TRUE(t.name.empty());
  EXPECT_TRUE(t.keys.empty());
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadTimelineFile, ::testing::ValuesIn(kBadTimelines),
                         [](const ::testing::TestParamInfo<BadTimeline>& param) {
                           return std::string(param.param.file);
                         });

TEST(TimelineFile, MissingFileAndDirectoryAreErrors) {
  Timeline t;
  const std::string missing = test::fixture("timelines/none.json");
  EXPECT_EQ(load_timeline_file(missing, t).message(), missing + ": No such file or directory");
  const std::string dir = test::fixture("timelines");
  EXPECT_EQ(load_timeline_file(dir, t).message(), dir + ": is a directory");
}

}  // namespace
}  // namespace lintel
