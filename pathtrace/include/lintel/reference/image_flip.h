// The perceptual image difference FLIP, LDR version (Andersson, Nilsson, Akenine-Möller, Oskarsson,
// Åström and Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020),
// implemented from the paper; reported beside RMSE by `lintel bench render --quality`.
//
// Inputs: two images of the same size, sRGB-encoded values in [0, 1] per channel (values outside
// are clamped), row-major, width x height. Output: a per-pixel error in [0, 1] (0 = no perceived
// difference) and its mean, the figure FLIP papers and tools report. The observer sits
// `pixels_per_degree` pixels per degree of visual angle from the screen; the paper's default, a
// 0.7 m wide 3840-pixel monitor seen from 0.7 m, is 67.0. Image borders are clamped (the
// filters read the edge pixel beyond the border).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel {

struct FlipOptions {
  float pixels_per_degree = 67.0206f;  // 0.7 m * (3840 px / 0.7 m) * pi / 180
};

// FLIP of `test` against `reference` (each width*height, sRGB in [0, 1]); `error_map` (optional,
// may be null) receives the per-pixel error. Returns the mean error; 0 for identical images.
// Preconditions (asserted): both sizes are width*height, width and height >= 1.
double flip_ldr(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, uint32_t width,
                uint32_t height, const FlipOptions& options = {}, std::vector<float>* error_map = nullptr);

// Linear radiance -> the sRGB display values FLIP compares: exposure, the Narkowicz ACES fit the
// renderer's tonemap uses, sRGB encoding. Comparing two HDR images this way with one exposure
// (e.g. the reference's) measures the difference a viewer of the realtime image would see.
std::vector<glm::vec3> tonemap_for_flip(const std::vector<glm::vec3>& linear, float exposure);

// The exposure of the renderer's automatic rule without its highlight cap (render/shaders/exposure.comp):
// middle grey (0.18) over the log-average luminance of the non-black pixels; 1 if none.
float key_exposure(const std::vector<glm::vec3>& linear);

}  // namespace lintel
