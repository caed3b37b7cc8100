// Pictures on the host: PNG files (stb_image_write), contact sheets of many frames, and the
// image error the renderer's accuracy chart uses. Writes go through a temporary file and a
// rename, so a failed write never leaves half a PNG behind.
#pragma once

#include <lintel/status.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::render {

struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> pixels;  // width x height x 4, row 0 at the top
};

Status write_png(const std::string& path, const Rgba8Image& image);
Status read_png(const std::string& path, Rgba8Image& out);

// Frames side by side, `columns` per row, each scaled down by an integer box filter to at most
// `tile_width` pixels wide; a dark gap between tiles. Frames may differ in size.
Rgba8Image contact_sheet(const std::vector<Rgba8Image>& frames, uint32_t columns, uint32_t tile_width);

// Root-mean-square difference of two linear images of equal size (rgb channels; a and b are
// width x height). Returns a negative value when the sizes differ.
double rmse_linear(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b);

}  // namespace lintel::render
