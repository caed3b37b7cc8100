// Overlay drawing for `lintel view` (see overlay.h). Lines use a DDA walk: one pixel per step
// along the major axis, so an outline is continuous and touches every pixel it crosses once.
#include "overlay.h"

#include <algorithm>
#include <cmath>

namespace lintel::view {

void cell_color(uint32_t cell, uint8_t out[3]) {
  // Golden-ratio hue steps: ids 0, 1, 2, ... land far apart on the colour wheel.
  const float hue = std::fmod(float(cell) * 0.61803399f + 0.1f, 1.0f) * 6.0f;
  const float f = hue - std::floor(hue);
  const float v = 1.0f, s = 0.75f;
  const float p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  float r = v, g = t, b = p;
  switch (int(hue) % 6) {
    case 0:
      r = v, g = t, b = p;
      break;
    case 1:
      r = q, g = v, b = p;
      break;
    case 2:
      r = p, g = v, b = t;
      break;
    case 3:
      r = p, g = q, b = v;
      break;
    case 4:
      r = t, g = p, b = v;
      break;
    default:
      r = v, g = p, b = q;
      break;
  }
  out[0] = uint8_t(r * 255.0f + 0.5f);
  out[1] = uint8_t(g * 255.0f + 0.5f);
  out[2] = uint8_t(b * 255.0f + 0.5f);
}

glm::vec2 ndc_to_pixel(const glm::vec2& p_ndc, int width, int height) {
  return {(p_ndc.x + 1.0f) * 0.5f * float(width), (1.0f - p_ndc.y) * 0.5f * float(height)};
}

void draw_line(const Canvas& canvas, glm::vec2 a, glm::vec2 b, const uint8_t color[3], float alpha) {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return;
  // Pixel (x, y) covers [x, x + 1): a point on the right or bottom border (NDC 1) falls on the
  // last pixel, not past it.
  const float max_x = float(canvas.width) - 0.5f, max_y = float(canvas.height) - 0.5f;
  a = glm::clamp(a, glm::vec2(0.0f), glm::vec2(max_x, max_y));
  b = glm::clamp(b, glm::vec2(0.0f), glm::vec2(max_x, max_y));
  const glm::vec2 d = b - a;
  const int steps = std::max(1, int(std::ceil(std::max(std::abs(d.x), std::abs(d.y)))));
  for (int i = 0; i <= steps; ++i) {
    const glm::vec2 p = a + d * (float(i) / float(steps));
    canvas.blend(int(std::floor(p.x)), int(std::floor(p.y)), color, alpha);
  }
}

void tint_cells(const Canvas& canvas, std::span<const uint32_t> cell_ids, uint32_t no_cell, float alpha) {
  if (cell_ids.size() != size_t(canvas.width) * size_t(canvas.height)) return;
  uint32_t cached = no_cell;
  uint8_t color[3] = {0, 0, 0};
  for (int y = 0; y < canvas.height; ++y)
    for (int x = 0; x < canvas.width; ++x) {
      const uint32_t id = cell_ids[size_t(y) * size_t(canvas.width) + size_t(x)];
      if (id == no_cell) continue;
      if (id != cached) {
        cell_color(id, color);
        cached = id;
      }
      canvas.blend(x, y, color, alpha);
    }
}

size_t outline_regions(const Canvas& canvas, const VisibleSet& visible, uint32_t viewer_cell) {
  static constexpr uint8_t kWhite[3] = {255, 255, 255};
  size_t edges = 0;
  for (const VisibleCell& c : visible.cells) {
    uint8_t color[3];
    cell_color(c.cell, color);
    const bool own = c.cell == viewer_cell;
    const ClipRegionView region = visible.region(c);
    for (size_t i = 0; i < region.polygons.size(); ++i) {
      const std::span<const glm::vec2> poly = region.polygon(i);
      for (size_t k = 0; k < poly.size(); ++k) {
        const glm::vec2 a = ndc_to_pixel(poly[k], canvas.width, canvas.height);
        const glm::vec2 b = ndc_to_pixel(poly[(k + 1) % poly.size()], canvas.width, canvas.height);
        draw_line(canvas, a, b, own ? kWhite : color);
        if (own) draw_line(canvas, a + glm::vec2(1.0f, 1.0f), b + glm::vec2(1.0f, 1.0f), kWhite);
        ++edges;
      }
    }
  }
  return edges;
}

int draw_hud(const Canvas& canvas, const std::vector<std::string>& lines, int scale) {
  static constexpr uint8_t kBlack[3] = {0, 0, 0};
  static constexpr uint8_t kText[3] = {255, 255, 160};
  const int pad = 3 * scale, line_height = (kGlyphHeight + 3) * scale;
  int width = 0;
  for (const std::string& l : lines) width = std::max(width, text_width(l, scale));
  const int box_w = width + 2 * pad, box_h = int(lines.size()) * line_height + 2 * pad - 3 * scale;
  for (int y = 0; y < box_h; ++y)
    for (int x = 0; x < box_w; ++x) canvas.blend(x, y, kBlack, 0.6f);
  for (size_t i = 0; i < lines.size(); ++i) draw_text(canvas, pad, pad + int(i) * line_height, lines[i], kText, scale);
  return box_h;
}

}  // namespace lintel::view
