// The viewer's debug overlays, drawn on the CPU into the renderer's RGBA8 frame before it is
// uploaded: cells tinted by id (per-pixel cell ids from RenderOptions::readback_cells), each
// visible cell's clip region outlined (the VisibleSet's NDC polygons), and a HUD of text lines.
// Plain functions on a Canvas, so that tests can check them pixel by pixel without a GPU.
#pragma once

#include "bitmap_font.h"

#include <lintel/visible_set.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lintel::view {

// A colour per cell id, spread over hues so that neighbouring ids differ.
void cell_color(uint32_t cell, uint8_t out[3]);

// NDC (x right, y up, [-1, 1]) -> pixel coordinates (row 0 at the top; pixel centres at +0.5).
glm::vec2 ndc_to_pixel(const glm::vec2& p_ndc, int width, int height);

// A 1-pixel line from a to b (pixel coordinates), clipped to the canvas.
void draw_line(const Canvas& canvas, glm::vec2 a, glm::vec2 b, const uint8_t color[3], float alpha = 1.0f);

// Blends each pixel whose id is a cell (not `no_cell`) toward that cell's colour by `alpha`.
// `cell_ids` has width x height entries (or is empty: nothing happens).
void tint_cells(const Canvas& canvas, std::span<const uint32_t> cell_ids, uint32_t no_cell, float alpha = 0.3f);

// Outlines every polygon of every visible cell's clip region in the cell's colour; the viewer's
// own cell (`viewer_cell`) in white, two pixels wide. Returns the number of edges drawn.
size_t outline_regions(const Canvas& canvas, const VisibleSet& visible, uint32_t viewer_cell);

// Lines of text in the top-left corner on a darkened box. Returns the box's height in pixels.
int draw_hud(const Canvas& canvas, const std::vector<std::string>& lines, int scale);

}  // namespace lintel::view
