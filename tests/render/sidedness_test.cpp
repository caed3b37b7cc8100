// Property: the albedo pass shows, at every pixel away from edges, the surface an Embree ray
// through the pixel's centre reaches first under glTF's face rule (single-sided materials: back
// faces are not seen; double-sided: both) and its cut-out rule (alphaMode MASK: no surface where
// the coverage is below the cutoff), on a tilted closed-shell house whose neighbouring
// rooms' walls lie back to back in one plane, and on every committed scene. At most 0.5 % of
// those pixels may differ (raster vs ray rounding at a grazing angle).
//
// How it fails: without back-face culling the neighbour room's wall wins the depth test on
// large parts of the shared walls (measured with the g-buffer's discard disabled: 1.6-29 % of
// the interior pixels wrong in 11 of the 12 house views); a culling rule with the wrong
// orientation (a flipped viewport or front face) removes every wall instead.
//
// "Away from edges": a pixel whose 8 neighbours in the reference all show the same colour and the
// same hit/miss. Silhouettes and colour edges are where one pixel may legitimately go either way.
// The reference ray is the path tracer's nearest hit (pathtrace/src/embree_scene.h), which applies
// the same face rule. About 3 s on the 2-core lavapipe machine.
#include "closed_house.h"
#include "ray_hit_geometry.h"
#include "render_test_support.h"

#include <lintel/cell_locate.h>
#include <lintel/portal_link.h>
#include <lintel/scene_io.h>

#include "../../pathtrace/src/embree_scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <utility>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr int kColourTolerance = 8;  // in 1/255 steps, per channel, after sRGB encoding
constexpr double kMaxWrongShare = 0.005;

uint8_t encode(float linear) {
  // As the renderer: an 8-bit linear g-buffer, then the sRGB curve into 8 bits.
  float c = std::round(std::clamp(linear, 0.0f, 1.0f) * 255.0f) / 255.0f;
  c = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

struct Reference {
  std::vector<glm::u8vec3> colour;  // per pixel, row 0 at the top
  std::vector<uint8_t> hit;
  std::vector<uint8_t> through_link;  // the ray meets a mirror or teleport first: not compared
};

Reference reference_albedo(const World& world, const pathtrace_detail::EmbreeScene& embree, const View& view) {
  Reference r;
  r.colour.assign(size_t(kWidth) * kHeight, glm::u8vec3(0));
  r.hit.assign(size_t(kWidth) * kHeight, 0);
  r.through_link.assign(size_t(kWidth) * kHeight, 0);
  const glm::dmat4 clip_to_world = glm::inverse(view_projection_d(view));
  for (uint32_t j = 0; j < kHeight; ++j)
    for (uint32_t i = 0; i < kWidth; ++i) {
      const double x = (i + 0.5) / kWidth * 2.0 - 1.0, y = 1.0 - (j + 0.5) / kHeight * 2.0;
      const glm::dvec4 far = clip_to_world * glm::dvec4(x, y, 1.0, 1.0);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(view.eye_world));
      pathtrace_detail::SurfaceHit h;
      if (!embree.intersect(view.eye_world, glm::vec3(dir), pathtrace_detail::RayCone{}, h)) continue;
      const size_t p = size_t(j) * kWidth + i;
      r.hit[p] = 1;
      r.colour[p] = glm::u8vec3(encode(h.albedo.r), encode(h.albedo.g), encode(h.albedo.b));
      double t = 0.0;
      const glm::dvec3 eye(view.eye_world);
      r.through_link[p] =
          linked_portal_on_ray(world.portals, eye, dir, glm::length(glm::dvec3(h.position_world) - eye), t) >= 0;
    }
  return r;
}

bool same(const glm::u8vec3& a, const glm::u8vec3& b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a[c]) - int(b[c])) > kColourTolerance) return false;
  return true;
}

// Pixels whose colours differ by more than kColourTolerance in some channel (same-sized frames).
size_t pixels_differing(const RenderedFrame& a, const RenderedFrame& b) {
  EXPECT_EQ(a.rgba8.size(), b.rgba8.size());
  size_t n = 0;
  for (size_t p = 0; p + 3 < a.rgba8.size() && p + 3 < b.rgba8.size(); p += 4)
    n += !same({a.rgba8[p], a.rgba8[p + 1], a.rgba8[p + 2]}, {b.rgba8[p], b.rgba8[p + 1], b.rgba8[p + 2]});
  return n;
}

class SidednessTest : public ValidatedGpu {
 protected:
  // Debug view `view_kind` (GI off) of worlds a and b from each view (the viewer cell located in
  // a): per view, the pixels that differ.
  std::vector<size_t> differing(const World& a, const World& b, const std::vector<View>& views, uint32_t view_kind) {
    RenderOptions o = test_options(kWidth, kHeight);
    o.view = view_kind;
    o.gi = false;
    std::unique_ptr<Renderer> ra = make_renderer(ctx(), a, o);
    std::unique_ptr<Renderer> rb = make_renderer(ctx(), b, o);
    std::vector<size_t> out;
    if (!ra || !rb) return out;
    for (const View& view : views) {
      const uint32_t cell = locate_cell(a, glm::dvec3(view.eye_world)).cell;
      RenderedFrame fa, fb;
      EXPECT_TRUE(ra->render(view, cell, fa).ok());
      EXPECT_TRUE(rb->render(view, cell, fb).ok());
      out.push_back(pixels_differing(fa, fb));
    }
    return out;
  }

  // Renders every view's albedo pass and checks it against the reference.
  // `cells`: the viewer cell per view (empty: located from the eye).
  void check(const World& world, const std::vector<View>& views, const std::vector<uint32_t>& cells,
             const std::string& label) {
    pathtrace_detail::EmbreeScene embree;
    ASSERT_TRUE(embree.build(world).ok());
    RenderOptions o = test_options(kWidth, kHeight);
    o.view = kViewAlbedo;
    o.gi = false;
    o.readback_cells = true;
    std::unique_ptr<Renderer> r = make_renderer(ctx(), world, o);
    ASSERT_NE(r, nullptr);
    for (size_t v = 0; v < views.size(); ++v) {
      const View& view = views[v];
      RenderedFrame frame;
      const uint32_t cell = cells.empty() ? locate_cell(world, glm::dvec3(view.eye_world)).cell : cells[v];
      const Status s = r->render(view, cell, frame);
      ASSERT_TRUE(s.ok()) << s.message();
      const Reference ref = reference_albedo(world, embree, view);
      size_t checked = 0, wrong = 0, hits = 0, linked = 0;
      for (uint32_t j = 1; j + 1 < kHeight; ++j)
        for (uint32_t i = 1; i + 1 < kWidth; ++i) {
          const size_t p = size_t(j) * kWidth + i;
          bool interior = true;
          for (int dj = -1; dj <= 1 && interior; ++dj)
            for (int di = -1; di <= 1 && interior; ++di) {
              const size_t q = size_t(int(j) + dj) * kWidth + size_t(int(i) + di);
              interior = ref.hit[q] == ref.hit[p] && same(ref.colour[q], ref.colour[p]);
            }
          if (!interior) continue;
          // Seen through a mirror or teleport (the reference's rays do not follow links; the
          // linked views have their own test, render_linked_view_test).
          if (ref.through_link[p] || (frame.cell_ids[p] != kNoCell && (frame.cell_ids[p] >> kCellLinkShift) != 0)) {
            ++linked;
            continue;
          }
          ++checked;
          hits += ref.hit[p];
          const glm::u8vec3 got(frame.rgba8[p * 4], frame.rgba8[p * 4 + 1], frame.rgba8[p * 4 + 2]);
          if (!same(got, ref.colour[p])) ++wrong;
        }
      const double share = checked ? double(wrong) / double(checked) : 0.0;
      std::printf("  %s view %zu: %zu of %zu interior pixels wrong (%.2f %%), %zu hit geometry, %zu through links\n",
                  label.c_str(), v, wrong, checked, 100.0 * share, hits, linked);
      EXPECT_GT(hits, checked / 2) << label << " view " << v << ": the view should look at geometry";
      EXPECT_LE(share, kMaxWrongShare) << label << " view " << v;
    }
  }
};

// glTF doubleSided reaches Mesh::double_sided through the writer and the loader: false by default
// (and not written), true where MeshDesc asks for it.
TEST(DoubleSidedTest, RoundTripsThroughWriterAndLoader) {
  ClosedHouse house = closed_house(1, 1.0f);
  const std::string crate = house.scene.meshes[2].name;
  house.scene.meshes[2].double_sided = true;
  World world;
  ASSERT_TRUE(build_world(house.scene, "closed house", world).ok());
  size_t double_sided = 0;
  for (const Mesh& m : world.meshes) {
    double_sided += m.double_sided;
    EXPECT_EQ(m.double_sided, m.name == crate) << m.name;
  }
  EXPECT_EQ(double_sided, 1u);
}

TEST_F(SidednessTest, ClosedShellHouseMatchesRayCast) {
  for (uint64_t seed : {1u, 2u}) {
    ClosedHouse house = closed_house(seed, float(kWidth) / float(kHeight));
    World world;
    const Status s = build_world(house.scene, "closed house", world);
    ASSERT_TRUE(s.ok()) << s.message();
    check(world, house.views, {}, "house " + std::to_string(seed));
  }
  // With one double-sided mesh the drawables are no longer all one-sided, so the g-buffer culls
  // back faces in its fragment shader rather than in the rasterizer (GBufferPass): the other
  // path, and it must show the same.
  ClosedHouse house = closed_house(1, float(kWidth) / float(kHeight));
  house.scene.meshes[2].double_sided = true;
  World world;
  ASSERT_TRUE(build_world(house.scene, "closed house", world).ok());
  check(world, house.views, {}, "house 1, one mesh double-sided");
}

// Property: an instance whose node mirrors (scale x -1, valid glTF since the loader took it) draws
// exactly as an unmirrored instance of its mesh mirrored by hand (x negated, normals too, winding
// reversed): glTF's rule that a mirroring transform turns the front faces clockwise, which the
// g-buffer applies per instance (kFaceMirrored). Every instance of the closed house is mirrored
// one way in scene A and the other in scene B: the albedo images must agree pixel for pixel (up to
// kMaxWrongShare). Ignoring the rule draws every mirrored box inside out (its far inner faces), and
// the ray-cast check above cannot see that, since its reference reads the same World.
TEST_F(SidednessTest, MirroredInstanceDrawsAsItsMirroredMesh) {
  const ClosedHouse house = closed_house(1, float(kWidth) / float(kHeight));
  SceneDesc by_node = house.scene, by_mesh = house.scene;
  size_t mirrored = 0;
  for (size_t n = 0; n < by_node.nodes.size(); ++n) {
    NodeDesc& a = by_node.nodes[n];
    if (a.kind != NodeDesc::Kind::Plain || a.mesh < 0) continue;
    a.scale.x = -a.scale.x;
    MeshDesc flipped = house.scene.meshes[size_t(a.mesh)];
    for (glm::vec3& p : flipped.positions) p.x = -p.x;
    for (glm::vec3& q : flipped.normals) q.x = -q.x;
    for (size_t t = 0; t + 2 < flipped.indices.size(); t += 3)
      std::swap(flipped.indices[t + 1], flipped.indices[t + 2]);
    flipped.name += " mirrored";
    by_mesh.nodes[n].mesh = int(by_mesh.meshes.size());
    by_mesh.meshes.push_back(std::move(flipped));
    ++mirrored;
  }
  ASSERT_GT(mirrored, 2u);
  World world_a, world_b;
  ASSERT_TRUE(build_world(by_node, "mirrored nodes", world_a).ok());
  ASSERT_TRUE(build_world(by_mesh, "mirrored meshes", world_b).ok());
  const std::vector<size_t> differ = differing(world_a, world_b, house.views, kViewAlbedo);
  ASSERT_EQ(differ.size(), house.views.size());
  for (size_t v = 0; v < house.views.size(); ++v) {
    const size_t wrong = differ[v];
    std::printf("  mirrored house view %zu: %zu of %u pixels differ\n", v, wrong, kWidth * kHeight);
    EXPECT_LE(double(wrong) / double(kWidth * kHeight), kMaxWrongShare) << "view " << v;
  }
}

// Property: cut-outs (alphaMode MASK) draw only where they are covered, as the ray cast sees them.
// Every instance of the closed house (crates, tables) gets a checker whose 4x4-texel blocks have
// alpha 0 or 255 (uv from its mesh-space position), every other one also a COLOR_0 alpha of 1 or
// 0.2 on alternate vertices: the albedo pass must match the path tracer's
// nearest hits, which pass through the uncovered texels, on every view, and it must differ from
// the same house drawn opaque on many pixels (the test sees what cutting out changes). A g-buffer
// that ignored alpha would show the instances whole (the ray cast shows what is behind them); one
// that read the wrong channel or threshold would cut the wrong blocks.
TEST_F(SidednessTest, CutOutsMatchRayCast) {
  const ClosedHouse house = closed_house(1, float(kWidth) / float(kHeight));
  World opaque;
  ASSERT_TRUE(build_world(house.scene, "closed house", opaque).ok());
  World cut = opaque;
  cut.textures.push_back(block_checker(8, 4, {220, 150, 60, 0}, {220, 150, 60, 255}));
  size_t cut_outs = 0;
  for (const Instance& inst : cut.instances) {
    Mesh& m = cut.meshes[inst.mesh];
    if (m.alpha_mode == Mesh::AlphaMode::Mask) continue;  // a mesh shared by several instances
    m.uvs.clear();
    for (const glm::vec3& p : m.positions) m.uvs.emplace_back(p.x + p.z, p.y);
    m.base_color_texture = int(cut.textures.size() - 1);
    m.alpha_mode = Mesh::AlphaMode::Mask;
    // Every other mesh: COLOR_0 alpha 1 and 0.2 on alternate vertices, so the coverage edge
    // also runs inside the checker's covered blocks.
    if (cut_outs % 2)
      for (size_t v = 0; v < m.positions.size(); ++v) m.colors.emplace_back(1.0f, 1.0f, 1.0f, v % 2 ? 1.0f : 0.2f);
    ++cut_outs;
  }
  ASSERT_GE(cut_outs, 2u);
  check(cut, house.views, {}, "cut-out house");

  size_t changed = 0;
  for (const size_t n : differing(opaque, cut, house.views, kViewAlbedo)) changed += n;
  std::printf("  cut-outs change %zu of %zu pixels over %zu views\n", changed,
              size_t(kWidth) * kHeight * house.views.size(), house.views.size());
  EXPECT_GT(changed, size_t(kWidth) * kHeight / 20) << "the cut-outs should be in view";
}

// Property: a cut-out casts shadows only where it is covered. The closed house's instances made
// cut-outs of coverage 0 everywhere (some by their base colour's alpha, some by COLOR_0's alpha,
// which multiplies it) must light the house exactly as the same
// instances moved 1 km below it: the shadow view (shadowed / unshadowed direct light per pixel)
// and the albedo view agree on all but 0.01 % of the pixels, where the house with its
// instances opaque differs (they stand in the lamps' light). A shadow pass without the alpha test
// draws the invisible instances' shadows.
TEST_F(SidednessTest, UncoveredCutOutsCastNoShadow) {
  const ClosedHouse house = closed_house(1, float(kWidth) / float(kHeight));
  World opaque;
  ASSERT_TRUE(build_world(house.scene, "closed house", opaque).ok());
  ASSERT_FALSE(opaque.lights.empty());
  World gone = opaque, away = opaque;
  size_t by_vertex = 0, by_base = 0;
  for (const Instance& inst : gone.instances) {
    Mesh& m = gone.meshes[inst.mesh];
    if (m.alpha_mode == Mesh::AlphaMode::Mask) continue;  // a mesh shared by several instances
    m.alpha_mode = Mesh::AlphaMode::Mask;
    if ((by_vertex + by_base) % 2) {  // coverage 0 by COLOR_0's alpha
      m.colors.assign(m.positions.size(), glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
      ++by_vertex;
    } else {  // by the base colour's alpha
      m.base_color.a = 0.0f;
      ++by_base;
    }
  }
  ASSERT_GE(by_vertex, 1u);
  ASSERT_GE(by_base, 1u);
  const glm::mat4 down = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1000.0f, 0.0f));
  for (Instance& inst : away.instances) {
    inst.mesh_to_world = down * inst.mesh_to_world;
    const Mesh& m = away.meshes[inst.mesh];
    inst.bounds_world = Aabb{};
    for (const glm::vec3& p : m.positions) inst.bounds_world.extend(glm::vec3(inst.mesh_to_world * glm::vec4(p, 1.0f)));
  }
  for (const uint32_t view_kind : {kViewShadow, kViewAlbedo}) {
    size_t differ_gone = 0, differ_opaque = 0;
    for (const size_t n : differing(gone, away, house.views, view_kind)) differ_gone += n;
    for (const size_t n : differing(opaque, away, house.views, view_kind)) differ_opaque += n;
    const size_t pixels = size_t(kWidth) * kHeight * house.views.size();
    std::printf("  view kind %u: cut away vs moved away %zu of %zu pixels differ; opaque vs moved away %zu\n",
                view_kind, differ_gone, pixels, differ_opaque);
    // The same draws but for fragments that are discarded: equal pixel for pixel (measured 0 of
    // 86,400 in both views), so the bound is far below kMaxWrongShare's raster-vs-ray slack.
    EXPECT_LE(double(differ_gone) / double(pixels), 1e-4) << "view kind " << view_kind;
    EXPECT_GT(differ_opaque, pixels / 200) << "the instances should be seen and cast shadows, view kind " << view_kind;
  }
}

TEST_F(SidednessTest, CommittedScenesMatchRayCast) {
  for (const char* file : {"cottage.gltf", "grid16.gltf", "ring64.gltf"}) {
    World world;
    ASSERT_TRUE(load_committed_scene(file, world));
    ASSERT_FALSE(world.timelines.empty());
    std::vector<View> views;
    std::vector<uint32_t> cells;
    const std::vector<TimelineFrame> frames = timeline_frames(world, world.timelines.front(), 1);
    for (size_t k = 0; k < 6; ++k) {
      const TimelineFrame& f = frames[(k * frames.size()) / 6];
      View v = f.view;
      v.aspect = float(kWidth) / float(kHeight);
      views.push_back(v);
      cells.push_back(f.start_cell);
    }
    check(world, views, cells, file);
  }
}

}  // namespace
}  // namespace lintel::render::test
