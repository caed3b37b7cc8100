// The generated `teleport` and `mirror` scenes through the real writer and loader: links resolved
// by name, mirrors, bad link data refused with one line naming the portal node, and the `ring`
// timeline walked with the camera carried through the seam (docs/visibility.md, "Linked portals").
#include <lintel/cell_locate.h>
#include <lintel/portal_link.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

#include "run_process.h"

namespace lintel {
namespace {

int node_named(const SceneDesc& scene, const std::string& name) {
  for (size_t i = 0; i < scene.nodes.size(); ++i)
    if (scene.nodes[i].name == name) return int(i);
  return -1;
}

TEST(LinkScenes, TeleportLinksResolveByName) {
  World world;
  ASSERT_TRUE(build_world(generate_teleport({4}), "teleport", world).ok());
  const int seam = world.find_portal("seam_east"), west = world.find_portal("seam_west");
  const int a = world.find_portal("teleporter_a"), b = world.find_portal("teleporter_b");
  ASSERT_TRUE(seam >= 0 && west >= 0 && a >= 0 && b >= 0);
  const Portal& p = world.portals[size_t(seam)];
  EXPECT_EQ(p.link, PortalLinkKind::Teleport);
  EXPECT_EQ(p.link_target, west);
  EXPECT_EQ(world.cells[p.from].name, "room_3");
  EXPECT_EQ(world.cells[p.to].name, "room_0");
  EXPECT_FALSE(p.two_way);
  // The seam's centre maps onto the west seam's centre; its normal onto minus the target's.
  const glm::dvec3 c(p.link_world * glm::dvec4(glm::dvec3(p.centroid_world), 1.0));
  EXPECT_LT(glm::length(c - glm::dvec3(world.portals[size_t(west)].centroid_world)), 1e-4);
  const glm::dvec3 n(p.link_world * glm::dvec4(glm::dvec3(p.normal_world), 0.0));
  EXPECT_NEAR(glm::dot(n, -glm::dvec3(world.portals[size_t(west)].normal_world)), 1.0, 1e-5);
  EXPECT_EQ(world.cells[world.portals[size_t(a)].to].name, "room_3");
  EXPECT_EQ(world.cells[world.portals[size_t(b)].to].name, "room_1");
  EXPECT_EQ(world.cells[p.from].linked_portals.size(), 2u);  // the seam and teleporter_b
}

TEST(LinkScenes, MirrorsLoadAsReflections) {
  World world;
  ASSERT_TRUE(build_world(generate_mirror({}), "mirror", world).ok());
  const Portal& m = world.portals[size_t(world.find_portal("mirror_east"))];
  EXPECT_EQ(m.link, PortalLinkKind::Mirror);
  EXPECT_EQ(m.from, m.to);
  EXPECT_LT(glm::determinant(glm::dmat3(m.link_world)), 0.0);
  // A point 1 m in front of the mirror is reflected 1 m behind it.
  const glm::dvec3 front = glm::dvec3(m.centroid_world) - glm::dvec3(m.normal_world);
  const glm::dvec3 back(m.link_world * glm::dvec4(front, 1.0));
  EXPECT_LT(glm::length(back - (glm::dvec3(m.centroid_world) + glm::dvec3(m.normal_world))), 1e-5);
  // The hall with facing mirrors: linked cells up to the depth, then unresolved.
  VisibilityBuilder builder;
  VisibleSet v;
  View view = timeline_view(world.timelines[0], world.timelines[0].keys.front().t);
  view.target_world = view.eye_world + glm::vec3(m.normal_world);
  ASSERT_TRUE(builder.build(world, view, uint32_t(world.find_cell("hall")), {}, v).ok());
  EXPECT_GE(v.linked_cells.size(), size_t(kMaxLinkDepth));
  EXPECT_FALSE(v.unresolved.empty());
  EXPECT_LE(v.stats.pops, pop_bound(world, {}));
}

TEST(LinkScenes, BadLinksAreOneLineErrorsNamingTheNode) {
  struct Case {
    const char* what;
    void (*edit)(SceneDesc&);
    const char* expected;
  };
  const Case cases[] = {
      {"unknown target", [](SceneDesc& s) { s.nodes[size_t(node_named(s, "seam_east"))].portal_link = "nowhere"; },
       "link names unknown portal 'nowhere'"},
      {"two-way", [](SceneDesc& s) { s.nodes[size_t(node_named(s, "seam_east"))].two_way = true; }, "one-way"},
      {"not congruent", [](SceneDesc& s) { s.nodes[size_t(node_named(s, "seam_west"))].scale = glm::vec3(0.5f); },
       "not congruent"},
      {"wrong to", [](SceneDesc& s) { s.nodes[size_t(node_named(s, "seam_east"))].portal_to = "room_2"; },
       "but its link target"},
      {"mirror and link", [](SceneDesc& s) { s.nodes[size_t(node_named(s, "seam_east"))].portal_mirror = true; },
       "both 'mirror' and 'link'"},
  };
  for (const Case& c : cases) {
    SceneDesc scene = generate_teleport({4});
    c.edit(scene);
    World world;
    const Status s = build_world(scene, "bad.glb", world);
    EXPECT_FALSE(s.ok()) << c.what;
    EXPECT_NE(s.message().find(c.expected), std::string::npos) << c.what << ": " << s.message();
    EXPECT_NE(s.message().find("bad.glb"), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
    EXPECT_EQ(exit_code_of(s), 2) << c.what;
  }
}

// The `ring` timeline walks east through every door and the seam: with the camera carried by the
// teleport (as `lintel walk` does) the tracker reports exactly one teleport, into room_0, the
// tracked cell holds the eye on every frame, and the seam's far side is drawn as linked cells.
TEST(LinkScenes, TheRingTimelineCarriesTheCameraThroughTheSeam) {
  World world;
  ASSERT_TRUE(build_world(generate_teleport({4}), "teleport", world).ok());
  const Timeline& timeline = world.timelines[size_t(world.find_timeline("ring"))];
  ViewerTracker tracker;
  VisibilityBuilder builder;
  VisibleSet v;
  glm::dmat4 carried(1.0);
  size_t teleports = 0, frames_with_linked = 0;
  const double t0 = timeline.keys.front().t, t1 = timeline.keys.back().t;
  const size_t frames = size_t((t1 - t0) * timeline.fps) + 1;
  for (size_t f = 0; f < frames; ++f) {
    View view = timeline_view(timeline, t0 + double(f) / timeline.fps);
    view.eye_world = glm::vec3(carried * glm::dvec4(glm::dvec3(view.eye_world), 1.0));
    view.target_world = glm::vec3(carried * glm::dvec4(glm::dvec3(view.target_world), 1.0));
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    if (tracker.teleported()) {
      ++teleports;
      ASSERT_EQ(tracker.transitions().back().reason, TransitionReason::Teleport);
      EXPECT_EQ(world.cells[tracker.cell()].name, "room_0");
      carried = tracker.teleport() * carried;
      view.eye_world = tracker.eye_world();
      view.target_world = glm::vec3(tracker.teleport() * glm::dvec4(glm::dvec3(view.target_world), 1.0));
    }
    for (const CellTransition& tr : tracker.transitions())
      EXPECT_TRUE(tr.reason == TransitionReason::PortalCrossing || tr.reason == TransitionReason::Teleport ||
                  tr.from == kNoCell)
          << "frame " << f << ": " << transition_reason_name(tr.reason);
    EXPECT_LE(cell_volume_distance_m(world, tracker.cell(), glm::dvec3(view.eye_world)), 1e-3) << "frame " << f;
    ASSERT_TRUE(builder.build(world, view, tracker.cell(), {}, v).ok());
    EXPECT_LE(v.stats.pops, pop_bound(world, {}));
    frames_with_linked += !v.linked_cells.empty();
  }
  EXPECT_EQ(teleports, 1u);
  EXPECT_EQ(world.cells[tracker.cell()].name, "room_0");
  EXPECT_GT(frames_with_linked, frames / 4);
}

// `lintel vis` and `lintel walk` report cells drawn with a link transform: vis lists them (text
// and JSON), walk counts them per frame and in its summary along with the teleport it carried.
TEST(LinkScenes, VisAndWalkReportLinkedCells) {
  const std::string dir = test::make_temp_dir(), scene = dir + "/teleport.gltf";
  const test::ProcessResult gen = test::run_process(test::lintel_bin() + " gen teleport --cells 4 -o " + scene);
  ASSERT_EQ(gen.exit_code, 0) << gen.err;
  const std::string look_east = " --eye 3,1.6,0.1 --target 30,1.6,0";
  const test::ProcessResult vis = test::run_process(test::lintel_bin() + " vis " + scene + look_east);
  ASSERT_EQ(vis.exit_code, 0) << vis.err;
  EXPECT_NE(vis.out.find("linked cells:"), std::string::npos) << vis.out;
  EXPECT_NE(vis.out.find("through seam_east"), std::string::npos) << vis.out;
  const test::ProcessResult json = test::run_process(test::lintel_bin() + " vis --json " + scene + look_east);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_TRUE(j.contains("linked_cells"));
  EXPECT_GT(j["linked_cell_count"].get<int>(), 0);
  EXPECT_EQ(j["linked_cells"][0]["link_depth"].get<int>(), 1);

  const test::ProcessResult walk =
      test::run_process(test::lintel_bin() + " walk --json-lines --timeline ring " + scene);
  ASSERT_EQ(walk.exit_code, 0) << walk.err;
  std::istringstream lines(walk.out);
  std::string line, last;
  int frames_listing = 0;
  while (std::getline(lines, line)) {
    last = line;
    const nlohmann::json f = nlohmann::json::parse(line);
    if (f.contains("summary")) break;
    frames_listing += f.contains("linked_cells");
  }
  const nlohmann::json summary = nlohmann::json::parse(last)["summary"];
  EXPECT_EQ(summary["teleports"].get<int>(), 1);
  EXPECT_EQ(summary["flaps"].get<int>(), 0);
  EXPECT_GT(summary["linked_cells"].get<int>(), 0);
  EXPECT_EQ(summary["frames_with_linked_cells"].get<int>(), frames_listing);
}

}  // namespace
}  // namespace lintel
