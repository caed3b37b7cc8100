// Linked portals: teleports and mirrors continue the flood in a transformed view, bounded by the
// link depth and budgets (docs/visibility.md, "Linked portals"); the tracker follows the eye
// through a teleport and treats mirrors as walls; bad links are refused.
#include "link_test_worlds.h"

#include <lintel/instance_cull.h>
#include <lintel/portal_link.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace lintel {
namespace {

using testing::check_links_conservative;
using testing::make_facing_mirrors;
using testing::make_teleport_ring;
using testing::TestWorld;

// Twice the default lattice cell (2/1024 NDC): the snap is conservative up to one cell per hop of
// overhang, and the ray walk's pixel sits on float geometry.
constexpr double kSlack = 4.0 / 1024.0;

void expect_bounded_and_deterministic(const World& world, const View& view, uint32_t start, VisibleSet& out) {
  VisibilityBuilder builder, fresh;
  ASSERT_TRUE(builder.build(world, view, start, {}, out).ok());
  EXPECT_LE(out.stats.pops, pop_bound(world, {}));
  EXPECT_EQ(out.stats.pop_bound, pop_bound(world, {}));
  EXPECT_LE(out.transforms.size(), kMaxViewTransforms);
  for (const ViewTransform& t : out.transforms) EXPECT_LE(t.depth, kMaxLinkDepth);
  VisibleSet again, other;
  ASSERT_TRUE(builder.build(world, view, start, {}, again).ok());
  EXPECT_EQ(again, out);
  ASSERT_TRUE(fresh.build(world, view, start, {}, other).ok());
  EXPECT_EQ(other, out);
}

// Two mirrors facing each other across a 4 m room: an endless corridor of reflections. The flood
// follows kMaxLinkDepth reflections, reports the rest as unresolved, and stays within its bound.
TEST(LinkedPortals, FacingMirrorsTerminateWithinTheBound) {
  TestWorld t = make_facing_mirrors();
  ASSERT_EQ(t.world.cells.size(), 1u);
  const View view = t.view({1.0f, 1.5f, 0.2f}, {4.0f, 1.5f, 0.0f});
  VisibleSet v;
  expect_bounded_and_deterministic(t.world, view, 0, v);
  ASSERT_EQ(v.cells.size(), 1u);
  EXPECT_EQ(v.linked_cells.size(), kMaxLinkDepth);  // the room, reflected 1..8 times
  EXPECT_GT(v.stats.link_limit_hits, 0u);
  EXPECT_FALSE(v.unresolved.empty());
  bool odd_mirrored = true;
  for (const VisibleCell& c : v.linked_cells)
    odd_mirrored = odd_mirrored && v.transforms[c.transform].mirrored == (v.transforms[c.transform].depth % 2 == 1);
  EXPECT_TRUE(odd_mirrored);
  const testing::LinkCheck check = check_links_conservative(t.world, view, 0, v, 32, kSlack);
  EXPECT_TRUE(check.failure.empty()) << check.failure;
  EXPECT_GT(check.beyond_depth, 0u);  // the test reached the depth limit and checked its fallback
}

// A chain closed into a ring by a teleport seam (and a mirror): looking down the chain shows the
// first room again behind the seam, then again, up to the link depth.
TEST(LinkedPortals, TeleportRingTerminatesAndIsConservative) {
  TestWorld t = make_teleport_ring(3);
  ASSERT_EQ(t.world.cells.size(), 3u);
  EXPECT_EQ(t.world.cells[2].linked_portals.size(), 1u);
  EXPECT_TRUE(t.world.cells[2].links.size() == 1u);  // the seam is not a plain link
  for (const View& view :
       {t.view({1.0f, 1.2f, 0.1f}, {20.0f, 1.2f, 0.0f}), t.view({11.0f, 1.2f, 0.3f}, {-5.0f, 1.0f, 0.0f}),
        t.view({2.0f, 1.5f, 1.0f}, {2.5f, 1.2f, -6.0f}), t.view({10.5f, 1.0f, -1.0f}, {13.0f, 1.2f, 0.2f})}) {
    ViewerTracker tracker;
    ASSERT_TRUE(tracker.reset(t.world, view.eye_world).ok());
    VisibleSet v;
    expect_bounded_and_deterministic(t.world, view, tracker.cell(), v);
    const testing::LinkCheck check = check_links_conservative(t.world, view, tracker.cell(), v, 32, kSlack);
    EXPECT_TRUE(check.failure.empty()) << check.failure;
    EXPECT_GT(check.checked_entries, check.rays);  // rays went beyond the start cell
  }
  // Looking east down the chain: the first room behind the seam, as a linked entry.
  VisibleSet v;
  VisibilityBuilder builder;
  ASSERT_TRUE(builder.build(t.world, t.view({1.0f, 1.2f, 0.1f}, {20.0f, 1.2f, 0.0f}), 0, {}, v).ok());
  bool first_room_behind_the_seam = false;
  for (const VisibleCell& c : v.linked_cells)
    first_room_behind_the_seam =
        first_room_behind_the_seam || (c.cell == 0 && v.transforms[c.transform].depth == 1 &&
                                       v.transforms[c.transform].portal == uint32_t(t.world.find_portal("seam_east")));
  EXPECT_TRUE(first_room_behind_the_seam);
  EXPECT_GT(v.stats.linked_portals_followed, 0u);
}

// Worlds without links report only the identity transform and no linked entries.
TEST(LinkedPortals, WorldsWithoutLinksHaveOnlyTheIdentity) {
  TestWorld t = testing::make_chain(3);
  VisibilityBuilder builder;
  VisibleSet v;
  ASSERT_TRUE(builder.build(t.world, t.view({1.0f, 1.2f, 0.1f}, {20.0f, 1.2f, 0.0f}), 0, {}, v).ok());
  ASSERT_EQ(v.transforms.size(), 1u);
  EXPECT_EQ(v.transforms[0].seen_from_world, glm::dmat4(1.0));
  EXPECT_TRUE(v.linked_cells.empty() && v.linked_instances.empty() && v.unresolved.empty());
  EXPECT_EQ(pop_bound(t.world, {}), pop_bound(3, {}));
}

// An instance behind the camera is not in the plain list but is seen in the mirror in front.
TEST(LinkedPortals, AnInstanceBehindTheEyeIsSeenInTheMirror) {
  TestWorld t = testing::make_chain(1);
  // A 0.4 m box 0.5 m behind the eye (the eye at x = 2.5 looks west, -X, at the mirror on x = 0).
  Mesh box;
  box.bounds_mesh = Aabb{glm::vec3(-0.2f), glm::vec3(0.2f)};
  t.world.meshes.push_back(box);
  t.world.groups.push_back({uint32_t(t.world.meshes.size() - 1), {}});
  Instance inst;
  inst.name = "crate";
  inst.cell = 0;
  inst.mesh = uint32_t(t.world.meshes.size() - 1);
  inst.group = uint32_t(t.world.groups.size() - 1);
  inst.mesh_to_world = t.layout_to_world * glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 1.5f, 0.0f));
  t.world.instances.push_back(inst);
  testing::add_linked_portal(t, 0, 0, {{0, 0.3f, -1.6f}, {0, 0.3f, 1.6f}, {0, 2.7f, 1.6f}, {0, 2.7f, -1.6f}}, {1, 1, 0},
                             PortalLinkKind::Mirror, "mirror");
  ASSERT_TRUE(finalize_world(t.world).ok());
  const uint32_t crate = uint32_t(t.world.instances.size() - 1);
  VisibilityBuilder builder;
  VisibleSet v;
  ASSERT_TRUE(builder.build(t.world, t.view({2.5f, 1.5f, 0.0f}, {-5.0f, 1.5f, 0.0f}), 0, {}, v).ok());
  EXPECT_TRUE(std::find(v.instances.begin(), v.instances.end(), crate) == v.instances.end());
  bool reflected = false;
  for (const LinkedInstance& li : v.linked_instances)
    reflected = reflected || (li.instance == crate && li.transform == 1);
  EXPECT_TRUE(reflected);
  EXPECT_TRUE(v.transforms[1].mirrored);
  // Turned away from the mirror, the crate is in front and the mirror is not seen.
  ASSERT_TRUE(builder.build(t.world, t.view({2.5f, 1.5f, 0.0f}, {9.0f, 1.5f, 0.0f}), 0, {}, v).ok());
  EXPECT_TRUE(std::find(v.instances.begin(), v.instances.end(), crate) != v.instances.end());
  EXPECT_TRUE(v.linked_cells.empty() && v.linked_instances.empty());
}

// The tracker carries the eye through the seam (reason Teleport, the link as the camera's
// transform) and never crosses a mirror.
TEST(LinkedPortals, TheTrackerFollowsATeleportAndNotAMirror) {
  TestWorld t = make_teleport_ring(3);
  ASSERT_EQ(t.world.cells.size(), 3u);
  const uint32_t seam = uint32_t(t.world.find_portal("seam_east"));
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({11.5f, 1.2f, 0.1f})).ok());
  ASSERT_EQ(tracker.cell(), 2u);
  ASSERT_TRUE(tracker.update(t.world, t.to_world({12.5f, 1.2f, 0.1f})).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0], (CellTransition{2, 0, TransitionReason::Teleport, seam}));
  EXPECT_TRUE(tracker.teleported());
  const glm::vec3 expected = t.to_world({0.5f, 1.2f, 0.1f});
  EXPECT_LT(glm::length(tracker.eye_world() - expected), 1e-3f);
  const glm::dvec3 carried(tracker.teleport() * glm::dvec4(glm::dvec3(t.to_world({12.5f, 1.2f, 0.1f})), 1.0));
  EXPECT_LT(glm::length(carried - glm::dvec3(expected)), 1e-3);
  // The caller applies the transform: walking on is a plain move in room 0, no jump.
  ASSERT_TRUE(tracker.update(t.world, t.to_world({1.0f, 1.2f, 0.1f})).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  EXPECT_TRUE(tracker.transitions().empty());
  EXPECT_FALSE(tracker.teleported());
  // Resting a few micrometres either side of the seam's target plane never teleports back.
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(tracker.update(t.world, t.to_world({(k % 2 ? 0.000003f : -0.000003f), 1.2f, 0.1f})).ok());
    EXPECT_TRUE(tracker.transitions().empty());
  }
  // Into the mirror on room 0's south wall: a wall, never crossed.
  ASSERT_TRUE(tracker.update(t.world, t.to_world({2.0f, 1.2f, -1.5f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({2.0f, 1.2f, -2.1f})).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  for (const CellTransition& tr : tracker.transitions()) EXPECT_NE(tr.reason, TransitionReason::Teleport);
}

// Bad links: one line naming the portal and the fault.
TEST(LinkedPortals, BadLinksAreRefused) {
  {
    TestWorld t = make_facing_mirrors();
    t.world.portals[0].two_way = true;
    const Status s = finalize_world(t.world);
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find("mirror_west"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("one-way"), std::string::npos) << s.message();
  }
  {
    TestWorld t = make_teleport_ring(2);
    t.world.portals[2].link_world[0][0] = 1.5;  // a stretch
    const Status s = finalize_world(t.world);
    EXPECT_NE(s.message().find("not rigid"), std::string::npos) << s.message();
  }
  {
    TestWorld t = make_teleport_ring(2);
    t.world.portals[2].link_world = glm::dmat4(1.0) * glm::dmat4(-1.0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    EXPECT_NE(finalize_world(t.world).message().find("mirrors"), std::string::npos);
  }
  {
    TestWorld t = make_facing_mirrors();
    t.world.portals[1].link_world = t.world.portals[0].link_world;  // the other mirror's reflection
    EXPECT_NE(finalize_world(t.world).message().find("not the reflection"), std::string::npos);
  }
  {
    TestWorld t = make_teleport_ring(2);
    Portal small = t.world.portals[3];
    for (glm::vec3& v : small.polygon_world) v = small.centroid_world + 0.5f * (v - small.centroid_world);
    glm::dmat4 m(1.0);
    EXPECT_NE(link_onto_target(t.world.portals[2], small, m).find("not congruent"), std::string::npos);
  }
}

}  // namespace
}  // namespace lintel
