// A tiny 5x7 bitmap font for the viewer's HUD: digits, upper-case letters (lower case is drawn as
// upper case) and the punctuation the HUD prints. The glyphs were drawn for Lintel; any other
// character is drawn as a hollow box so that it is visibly "unknown", never silently dropped.
#pragma once

#include <cstdint>
#include <string_view>

namespace lintel::view {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // one column of spacing

// Row `row` (0 = top) of `c`'s glyph as bits; bit 4 is the leftmost column.
uint8_t glyph_row(char c, int row);
// Whether `c` has a glyph of its own (false: the box).
bool has_glyph(char c);

// An RGBA8 image the drawing functions write into (row 0 at the top). Not owning.
struct Canvas {
  uint8_t* rgba = nullptr;
  int width = 0, height = 0;
  void blend(int x, int y, const uint8_t color[3], float alpha) const;
};

// Draws `text` with its top-left corner at (x, y), each font pixel `scale` x `scale` pixels;
// clipped to the canvas. Returns the x after the last glyph.
int draw_text(const Canvas& canvas, int x, int y, std::string_view text, const uint8_t color[3], int scale = 1);
// Width in pixels of `text` as draw_text draws it.
int text_width(std::string_view text, int scale = 1);

}  // namespace lintel::view
