// Linked-portal properties (link_properties.h). The worlds: two facing mirrors in one room (an
// endless corridor of reflections), and chains of 2..5 rooms closed into a ring by a teleport seam
// with a mirror in the first room, each with pseudo-random cell frames.
#include "link_properties.h"

#include "link_test_worlds.h"

#include <lintel/portal_link.h>
#include <lintel/visibility_builder.h>

#include <rapidcheck.h>

namespace lintel::fuzz {
namespace {

struct LinkCase {
  testing::TestWorld world;
  View view;
  uint32_t start = 0;
};

// A world, and an eye inside one of its rooms at least 0.2 m from every wall, looking anywhere.
LinkCase gen_link_case() {
  testing::WorldOptions options;
  options.frame_seed = *rc::gen::inRange<uint64_t>(1, 1000000);
  const bool mirrors = *rc::gen::element(0, 1) == 0;
  const uint32_t rooms = mirrors ? 1 : *rc::gen::inRange<uint32_t>(2, 6);
  LinkCase c{mirrors ? testing::make_facing_mirrors(options) : testing::make_teleport_ring(rooms, options), {}, 0};
  RC_PRE(!c.world.world.cells.empty());
  c.start = *rc::gen::inRange<uint32_t>(0, rooms);
  auto unit = [] { return *rc::gen::inRange(0, 1001) / 1000.0f; };
  const glm::vec3 eye(4.0f * float(c.start) + 0.2f + 3.6f * unit(), 0.2f + 2.6f * unit(), -1.8f + 3.6f * unit());
  const glm::vec3 dir(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-40, 41), *rc::gen::inRange(-100, 101));
  RC_PRE(glm::length(dir) > 10.0f);
  c.view = c.world.view(eye, eye + dir * 0.05f, float(*rc::gen::inRange(30, 121)));
  c.view.aspect = float(*rc::gen::inRange(50, 251)) / 100.0f;
  RC_PRE(validate_view(c.view).ok());
  RC_LOG() << (mirrors ? "facing mirrors" : "teleport ring of " + std::to_string(rooms)) << " seed "
           << options.frame_seed << " start " << c.start << "\n";
  return c;
}

}  // namespace

bool check_linked_portals() {
  bool ok = true;
  // Termination and determinism: facing mirrors and teleport rings, any eye in a room, any
  // lattice, cap and polygon limit: build() returns within pop_bound(world) with every view at
  // most kMaxLinkDepth links deep and at most kMaxViewTransforms views, and gives the same set
  // bit for bit again and from a fresh builder.
  ok &=
      rc::check("linked portals: facing mirrors and teleport rings terminate within the bound, deterministically", [] {
        const LinkCase c = gen_link_case();
        VisibilityOptions options;
        options.snap_lattice_cells = 1u << *rc::gen::inRange(2, 13);
        options.reprocess_cap = *rc::gen::inRange(0, 33);
        options.max_region_polygons = *rc::gen::inRange(1, 17);
        VisibilityBuilder builder, fresh;
        VisibleSet a, b, d;
        RC_ASSERT(builder.build(c.world.world, c.view, c.start, options, a).ok());
        RC_ASSERT(!a.stats.bound_exceeded);
        RC_ASSERT(a.stats.pops <= pop_bound(c.world.world, options));
        RC_ASSERT(a.transforms.size() <= kMaxViewTransforms);
        for (const ViewTransform& t : a.transforms) RC_ASSERT(t.depth <= kMaxLinkDepth);
        RC_ASSERT(builder.build(c.world.world, c.view, c.start, options, b).ok());
        RC_ASSERT(fresh.build(c.world.world, c.view, c.start, options, d).ok());
        RC_ASSERT(a == b);
        RC_ASSERT(a == d);
      });
  // Conservative: every (cell, view transform) that a ray through a pixel of a 16 x 16 grid
  // reaches through open portals, teleports and mirrors (the ray carried by each link), within
  // kMaxLinkDepth links, is an entry of the set whose region contains the pixel within two
  // lattice cells; a ray that needs more links ends in an unresolved rect. Rays passing within
  // 1 mm of a portal edge are not judged (float geometry).
  ok &= rc::check("linked portals: conservative against a ray walk that follows the links", [] {
    const LinkCase c = gen_link_case();
    VisibilityBuilder builder;
    VisibleSet v;
    RC_ASSERT(builder.build(c.world.world, c.view, c.start, {}, v).ok());
    const testing::LinkCheck check = testing::check_links_conservative(c.world.world, c.view, c.start, v, 16,
                                                                       4.0 / double(kDefaultSnapLatticeCells));
    if (!check.failure.empty()) RC_FAIL(check.failure);
  });
  return ok;
}

}  // namespace lintel::fuzz
