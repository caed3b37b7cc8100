// The viewer's CPU parts, pixel by pixel: the font's glyphs, the overlay's lines and tint, the
// script parser's errors, the fly camera's motion and the start's most open heading. No window, no
// GPU.
#include "bitmap_font.h"
#include "fly_camera.h"
#include "open_heading.h"
#include "overlay.h"
#include "view_input.h"

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>
#include <lintel/viewer_tracker.h>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace lintel::view {
namespace {

struct Image {
  int w, h;
  std::vector<uint8_t> px;
  Image(int w_, int h_) : w(w_), h(h_), px(size_t(w_) * size_t(h_) * 4, 0) {}
  Canvas canvas() { return {px.data(), w, h}; }
  bool lit(int x, int y) const { return px[(size_t(y) * size_t(w) + size_t(x)) * 4] != 0; }
  int lit_count() const {
    int n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) n += lit(x, y);
    return n;
  }
};

// Every character the HUD prints has a glyph of its own, and no two glyphs look alike (a reader
// could not tell them apart).
TEST(BitmapFont, GlyphsAreDistinctAndCoverTheHud) {
  const std::string chars = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ .,:-+=><()/_%#?";
  std::set<uint64_t> shapes;  // 7 rows x 5 bits packed
  for (char c : chars) {
    EXPECT_TRUE(has_glyph(c)) << c;
    uint64_t bits = 0;
    for (int r = 0; r < kGlyphHeight; ++r) bits = bits << kGlyphWidth | glyph_row(c, r);
    EXPECT_TRUE(shapes.insert(bits).second) << "glyph '" << c << "' looks like another";
  }
  EXPECT_TRUE(has_glyph('k')) << "lower case draws as upper case";
  EXPECT_FALSE(has_glyph('@'));
}

TEST(BitmapFont, TextStaysInsideItsBoxAndIsClipped) {
  Image img(40, 12);
  const uint8_t white[3] = {255, 255, 255};
  const int end = draw_text(img.canvas(), 1, 2, "L1", white, 1);
  EXPECT_EQ(end, 1 + 2 * kGlyphAdvance);
  EXPECT_EQ(text_width("L1"), 2 * kGlyphAdvance - 1);
  // 'L' is its left column (7) plus the bottom row's other 4 pixels.
  int in_l = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 6; ++x) in_l += img.lit(x, y);
  EXPECT_EQ(in_l, 11);
  for (int x = 0; x < 40; ++x) EXPECT_FALSE(img.lit(x, 0)) << "nothing above the text's top row";
  // Drawn half off the canvas: no crash, only the visible part.
  Image small(4, 4);
  draw_text(small.canvas(), -2, -3, "8", white, 1);
  EXPECT_GT(small.lit_count(), 0);
}

// NDC (-1, 1) is the top-left corner and (1, -1) the bottom-right; an outline of the whole
// screen lights exactly the border pixels.
TEST(Overlay, FullScreenRegionOutlinesTheBorder) {
  Image img(20, 10);
  VisibleSet visible;
  visible.cells.push_back({});
  visible.cells[0].cell = 3;
  visible.cells[0].polygon_count = 1;
  visible.polygons.push_back({0, 4});
  visible.vertices_ndc = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_EQ(outline_regions(img.canvas(), visible, /*viewer_cell=*/99), 4u);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      const bool border = x == 0 || y == 0 || x == 19 || y == 9;
      EXPECT_EQ(
          img.lit(x, y) || img.px[(size_t(y) * 20 + size_t(x)) * 4 + 1] || img.px[(size_t(y) * 20 + size_t(x)) * 4 + 2],
          border)
          << x << "," << y;
    }
}

TEST(Overlay, NdcToPixelFollowsTheClipConvention) {
  EXPECT_EQ(ndc_to_pixel({-1, 1}, 100, 50), glm::vec2(0, 0));
  EXPECT_EQ(ndc_to_pixel({1, -1}, 100, 50), glm::vec2(100, 50));
  EXPECT_EQ(ndc_to_pixel({0, 0.5f}, 100, 50), glm::vec2(50, 12.5f));
}

TEST(Overlay, TintChangesOnlyPixelsOfCells) {
  Image img(4, 1);
  const std::vector<uint32_t> ids = {7, kNoCell, 7, 8};
  tint_cells(img.canvas(), ids, kNoCell, 0.5f);
  EXPECT_TRUE(img.px[4] == 0 && img.px[5] == 0 && img.px[6] == 0) << "no cell: untouched";
  EXPECT_EQ(std::vector<uint8_t>(img.px.begin(), img.px.begin() + 3),
            std::vector<uint8_t>(img.px.begin() + 8, img.px.begin() + 11))
      << "one cell, one colour";
  EXPECT_NE(std::vector<uint8_t>(img.px.begin(), img.px.begin() + 3),
            std::vector<uint8_t>(img.px.begin() + 12, img.px.begin() + 15))
      << "neighbouring ids differ";
  // A size mismatch is ignored rather than read past the end.
  tint_cells(img.canvas(), std::vector<uint32_t>{1}, kNoCell);
}

TEST(Script, ParsesEveryAction) {
  std::vector<ScriptEvent> ev;
  const Status s = parse_script(
      "# header\n0 key down W\n2 key press shift  # both\n3 mouse down right\n3 mouse move 5 -2.5\n"
      "4 mouse up right\n5 screenshot a.png\n5 screenshot\n6 quit\n",
      "s.txt", ev);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(ev.size(), 9u);
  EXPECT_EQ(ev[0].event.key, 'W');
  EXPECT_EQ(ev[1].event.type, InputType::KeyDown);
  EXPECT_EQ(ev[2].event.type, InputType::KeyUp);
  EXPECT_EQ(ev[2].event.key, kKeyShift);
  EXPECT_EQ(ev[4].event.dy, -2.5f);
  EXPECT_EQ(ev[6].event.path, "a.png");
  EXPECT_EQ(ev[8].frame, 6u);
}

TEST(Script, ErrorsNameFileAndLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"0 key down W\n\n1 jump\n", "s.txt:3: unknown action 'jump'"},
      {"x key down W\n", "s.txt:1: 'x' is not a frame number"},
      {"5 quit\n4 quit\n", "s.txt:2: frame 4 comes after frame 5"},
      {"0 key down F1\n", "s.txt:1: unknown key 'F1'"},
      {"0 mouse move 1 nan\n", "s.txt:1: mouse move"},
      {"0 key hold W\n", "s.txt:1: key 'hold'"},
      {"0 quit now\n", "s.txt:1: 'quit' expects"},
  };
  for (const auto& [text, want] : cases) {
    std::vector<ScriptEvent> ev;
    const Status s = parse_script(text, "s.txt", ev);
    ASSERT_FALSE(s.ok()) << text;
    EXPECT_EQ(s.kind(), StatusKind::BadInput);
    EXPECT_EQ(s.message().rfind(want, 0), 0u) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  }
}

TEST(Input, MouseLooksOnlyWithTheRightButtonAndPressesAreEdges) {
  InputState in;
  in.apply({InputType::MouseMove, 0, 0, 10, 0, ""});
  EXPECT_EQ(in.look_dx, 0.0f) << "no button: the cursor moves, the camera does not";
  in.apply({InputType::MouseDown, 0, 1, 0, 0, ""});
  in.apply({InputType::MouseMove, 0, 0, 10, 4, ""});
  EXPECT_EQ(in.look_dx, 10.0f);
  in.apply({InputType::KeyDown, 'C', 0, 0, 0, ""});
  in.apply({InputType::KeyDown, 'C', 0, 0, 0, ""});  // a repeat while held is not a second press
  EXPECT_EQ(in.pressed.size(), 1u);
  in.begin_frame();
  EXPECT_TRUE(in.pressed.empty());
  EXPECT_TRUE(in.down['C']) << "held keys stay held across frames";
}

// The camera moves speed x time along its view, keeps its direction while moving, and turns
// about +Y by the configured degrees per pixel.
TEST(FlyCamera, MovesAndTurnsAsConfigured) {
  View start;
  start.eye_world = {1, 2, 3};
  start.target_world = {1, 2, 0};  // looking down -Z
  FlyCamera cam(start, {2.0f, 4.0f, 0.5f, 89.0f});
  InputState in;
  EXPECT_FALSE(cam.update(in, 0.1f)) << "no input, no change";
  EXPECT_EQ(cam.view().eye_world, start.eye_world);
  in.down['W'] = true;
  EXPECT_TRUE(cam.update(in, 0.5f));
  EXPECT_NEAR(cam.view().eye_world.z, 2.0f, 1e-5f);
  in.down[kKeyShift] = true;
  cam.update(in, 0.5f);
  EXPECT_NEAR(cam.view().eye_world.z, -2.0f, 1e-5f) << "shift: four times faster";
  in.down['W'] = in.down[kKeyShift] = false;
  in.right_button = true;
  in.look_dx = 180.0f;  // 90 degrees at 0.5 deg/pixel: the mouse going right turns the view right, to +X
  cam.update(in, 0.0f);
  const glm::vec3 f = glm::normalize(cam.view().target_world - cam.view().eye_world);
  EXPECT_NEAR(f.x, 1.0f, 1e-4f);
  EXPECT_NEAR(f.y, 0.0f, 1e-4f);
}

// Property: a start that faces the end wall of a row of rooms is turned to look along the row (it
// sees more cells, and no heading sees more); a start already looking down the row is kept bit for
// bit.
TEST(OpenHeading, TurnsAStartFacingAWallToTheMostOpenHeadingAndKeepsAnOpenOne) {
  GridOptions row;
  row.width = 5;
  row.height = 1;
  World world;
  ASSERT_TRUE(build_world(generate_grid(row), "row", world).ok());
  uint32_t first = 0;  // the room at the row's -X end
  auto centre = [&](uint32_t c) {
    return glm::vec3(world.cells[c].cell_to_world * glm::vec4(world.cells[c].volume_box_cell.center(), 1.0f));
  };
  for (uint32_t c = 1; c < world.cells.size(); ++c)
    if (centre(c).x < centre(first).x) first = c;
  View start;
  start.eye_world = centre(first);
  start.target_world = start.eye_world + glm::vec3(-1.0f, 0.0f, 0.0f);  // at the end wall
  VisibilityBuilder builder;
  VisibleSet visible;
  auto seen = [&](const View& v) {
    EXPECT_TRUE(builder.build(world, v, first, {}, visible).ok());
    return visible.cells.size();
  };
  const View turned = most_open_heading(world, start);
  const glm::vec3 look = glm::normalize(turned.target_world - turned.eye_world);
  EXPECT_EQ(turned.eye_world, start.eye_world);
  EXPECT_GT(look.x, 0.5f);  // down the row (45 degrees off the axis sees every room too)
  EXPECT_NEAR(look.y, 0.0f, 1e-6f);
  EXPECT_EQ(seen(start), 1u);
  EXPECT_EQ(seen(turned), world.cells.size());

  View open = start;
  open.target_world = start.eye_world + glm::vec3(1.0f, 0.0f, 0.0f);
  const View kept = most_open_heading(world, open);
  EXPECT_EQ(kept.target_world, open.target_world);
}

}  // namespace
}  // namespace lintel::view
