// The fast CPU instance cull (instance_cull.cpp: plane rejects through the eye, clip only for
// boxes that straddle the slab, no libm) against the implementation it replaced, kept below
// verbatim as the reference, on every frame of every committed timeline and the benchmark's grid.
#include <lintel/instance_cull.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace lintel {
namespace {

// ---- the reference: project_aabb and cull_instances as they were before the fast path -------

ProjectedBox reference_project_aabb(const glm::dmat4& view_proj, const glm::dvec3& eye_world, const glm::dvec3& box_min,
                                    const glm::dvec3& box_max) {
  ProjectedBox out;
  if (box_min.x > box_max.x || box_min.y > box_max.y || box_min.z > box_max.z) return out;
  out.contains_eye =
      glm::all(glm::lessThanEqual(box_min, eye_world)) && glm::all(glm::lessThanEqual(eye_world, box_max));
  glm::dvec4 corner[8];
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? box_max.x : box_min.x, (i & 2) ? box_max.y : box_min.y,
                       (i & 4) ? box_max.z : box_min.z);
    corner[i] = view_proj * glm::dvec4(p, 1.0);
  }
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : kEdges) {
    const glm::dvec4& a = corner[e[0]];
    const glm::dvec4& b = corner[e[1]];
    double t0 = 0.0, t1 = 1.0;
    bool inside = true;
    const double da[2] = {a.z, a.w - a.z};
    const double db[2] = {b.z, b.w - b.z};
    for (int p = 0; p < 2 && inside; ++p) {
      if (da[p] < 0.0 && db[p] < 0.0) {
        inside = false;
      } else if (da[p] < 0.0) {
        t0 = std::max(t0, da[p] / (da[p] - db[p]));
      } else if (db[p] < 0.0) {
        t1 = std::min(t1, da[p] / (da[p] - db[p]));
      }
    }
    if (!inside || t0 > t1) continue;
    for (const double t : {t0, t1}) {
      const glm::dvec4 c = a + (b - a) * t;
      if (!(c.w > 0.0)) continue;
      out.in_slab = true;
      out.rect_ndc.extend(glm::vec2(float(c.x / c.w), float(c.y / c.w)));
    }
  }
  if (out.in_slab) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    NdcRect& r = out.rect_ndc;
    r.min = glm::vec2(std::nextafter(r.min.x, -kInf), std::nextafter(r.min.y, -kInf));
    r.max = glm::vec2(std::nextafter(r.max.x, kInf), std::nextafter(r.max.y, kInf));
  }
  return out;
}

// Every slot of every visible cell through the reference rule; the visible instances, ascending,
// each once (an instance reaching several visible cells has several slots).
std::vector<uint32_t> reference_cull(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye,
                                     const VisibleSet& visible) {
  std::vector<uint32_t> out;
  for (const VisibleCell& vc : visible.cells) {
    const ClipRegionView region = visible.region(vc);
    for (uint32_t s = data.cell_begin[vc.cell]; s < data.cell_begin[vc.cell + 1]; ++s) {
      const ProjectedBox box =
          reference_project_aabb(view_proj, eye, glm::dvec3(data.slots[s].min), glm::dvec3(data.slots[s].max));
      if (box.contains_eye || (box.in_slab && region.overlaps(box.rect_ndc))) out.push_back(data.slots[s].instance);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Walks every timeline of `world` (viewer cell tracked) and requires the builder's instance list
// to equal the reference's on every frame. Returns the frames walked.
size_t expect_same_decisions(const World& world, const std::string& label) {
  CullData data;
  data.prepare(world);
  VisibilityBuilder builder;
  VisibleSet visible;
  size_t frames = 0, listed = 0;
  for (const Timeline& t : world.timelines) {
    ViewerTracker tracker;
    for (size_t f = 0; f < timeline_frame_count(t); ++f) {
      const View view = timeline_view(t, t.keys.front().t + double(f) / t.fps);
      EXPECT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
      EXPECT_TRUE(builder.build(world, view, tracker.cell(), {}, visible).ok());
      const std::vector<uint32_t> expected =
          reference_cull(data, view_projection_d(view), glm::dvec3(view.eye_world), visible);
      EXPECT_EQ(visible.instances, expected) << label << ": timeline " << t.name << " frame " << f;
      listed += expected.size();
      ++frames;
    }
  }
  EXPECT_GT(listed, 0u) << label << ": no instance was ever listed, the comparison proves nothing";
  return frames;
}

// Property: on every frame of every committed timeline (scenes/*.gltf), the fast cull lists
// exactly the instances the previous implementation listed, in the same order.
TEST(InstanceCullFast, SameDecisionsAsTheReferenceOnEveryCommittedTimeline) {
  for (const char* name : {"cottage", "grid16", "ring64"}) {
    World world;
    const std::string path = std::string(LINTEL_SOURCE_DIR) + "/scenes/" + name + ".gltf";
    ASSERT_TRUE(load_world(path, world).ok()) << path;
    ASSERT_FALSE(world.timelines.empty()) << path;
    EXPECT_GT(expect_same_decisions(world, name), 100u);
  }
}

// The same on the benchmark's scene (visibility_bench build/grid32x32: generated, not committed).
TEST(InstanceCullFast, SameDecisionsAsTheReferenceOnTheBenchmarkGrid) {
  World world;
  ASSERT_TRUE(build_world(generate_grid({32, 32, false, 1}), "grid32", world).ok());
  EXPECT_GT(expect_same_decisions(world, "grid32"), 100u);
}

// The single-box projection is unchanged too (exact oracle and rect method use it): random boxes
// and views, rect bit for bit.
TEST(InstanceCullFast, ProjectAabbIsBitIdenticalToTheReference) {
  uint64_t state = 12345;
  auto u = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53) * 2.0 - 1.0;
  };
  int in_slab = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    View v;
    v.eye_world = glm::vec3(u(), u(), u());
    v.target_world = v.eye_world + glm::vec3(u(), 0.3 * u(), u()) + glm::vec3(0.0f, 0.0f, 0.01f);
    v.far_m = 8.0f;
    const glm::dmat4 vp = view_projection_d(v);
    const glm::dvec3 c(2.0 * u(), 2.0 * u(), 2.0 * u());
    const glm::dvec3 half(0.01 + std::abs(u()), 0.01 + std::abs(u()), 0.01 + std::abs(u()));
    const glm::dvec3 lo(glm::vec3(c - half)), hi(glm::vec3(c + half));
    const ProjectedBox a = project_aabb(vp, glm::dvec3(v.eye_world), lo, hi);
    const ProjectedBox b = reference_project_aabb(vp, glm::dvec3(v.eye_world), lo, hi);
    ASSERT_EQ(a.contains_eye, b.contains_eye) << trial;
    ASSERT_EQ(a.in_slab, b.in_slab) << trial;
    in_slab += a.in_slab;
    if (!a.in_slab) continue;
    ASSERT_EQ(a.rect_ndc.min, b.rect_ndc.min) << trial;
    ASSERT_EQ(a.rect_ndc.max, b.rect_ndc.max) << trial;
  }
  EXPECT_GT(in_slab, 5000);
}

}  // namespace
}  // namespace lintel
