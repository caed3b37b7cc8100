// PNG through Debian's libstb (the implementation lives in libstb.so; only the headers here).
#include <lintel/render/image_io.h>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <lintel/file_commit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lintel::render {

Status write_png(const std::string& path, const Rgba8Image& image) {
  if (image.width == 0 || image.height == 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
    return Status::error(path + ": image to write is empty or its size does not match its pixels");
  // Encoded in memory, then written through commit_file: a device, FIFO, directory or symlink at
  // `path` is refused and an existing "<path>.tmp" is never touched.
  std::vector<uint8_t> png;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 4, image.pixels.data(),
                              int(image.width * 4)))
    return Status::internal(path + ": PNG encoding failed");
  return commit_files({{path, png.data(), png.size()}});
}

Status read_png(const std::string& path, Rgba8Image& out) {
  int w = 0, h = 0, n = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) return Status::error(path + ": cannot read PNG: " + (stbi_failure_reason() ? stbi_failure_reason() : "?"));
  out.width = uint32_t(w);
  out.height = uint32_t(h);
  out.pixels.assign(data, data + size_t(w) * h * 4);
  stbi_image_free(data);
  return {};
}

Rgba8Image contact_sheet(const std::vector<Rgba8Image>& frames, uint32_t columns, uint32_t tile_width) {
  Rgba8Image sheet;
  if (frames.empty() || columns == 0 || tile_width == 0) return sheet;
  const uint32_t gap = 4;
  uint32_t tile_h = 0;
  std::vector<uint32_t> factor(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    factor[i] = std::max<uint32_t>(1, (frames[i].width + tile_width - 1) / tile_width);
    tile_h = std::max(tile_h, frames[i].height / factor[i]);
  }
  const uint32_t rows = uint32_t((frames.size() + columns - 1) / columns);
  const uint32_t cols = std::min<uint32_t>(columns, uint32_t(frames.size()));
  sheet.width = cols * tile_width + (cols + 1) * gap;
  sheet.height = rows * tile_h + (rows + 1) * gap;
  sheet.pixels.assign(size_t(sheet.width) * sheet.height * 4, 24);
  for (size_t i = 0; i < sheet.pixels.size(); i += 4) sheet.pixels[i + 3] = 255;
  for (size_t i = 0; i < frames.size(); ++i) {
    const Rgba8Image& f = frames[i];
    const uint32_t k = factor[i];
    const uint32_t ox = gap + uint32_t(i % columns) * (tile_width + gap),
                   oy = gap + uint32_t(i / columns) * (tile_h + gap);
    for (uint32_t y = 0; y < f.height / k && y < tile_h; ++y)
      for (uint32_t x = 0; x < f.width / k && x < tile_width; ++x)
        for (int c = 0; c < 4; ++c) {
          uint32_t sum = 0;
          for (uint32_t dy = 0; dy < k; ++dy)
            for (uint32_t dx = 0; dx < k; ++dx) sum += f.pixels[(size_t(y * k + dy) * f.width + x * k + dx) * 4 + c];
          sheet.pixels[(size_t(oy + y) * sheet.width + ox + x) * 4 + c] = uint8_t(sum / (k * k));
        }
  }
  return sheet;
}

double rmse_linear(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  if (a.size() != b.size() || a.empty()) return -1.0;
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 d = glm::dvec3(a[i]) - glm::dvec3(b[i]);
    sum += glm::dot(d, d);
  }
  return std::sqrt(sum / (3.0 * double(a.size())));
}

}  // namespace lintel::render
