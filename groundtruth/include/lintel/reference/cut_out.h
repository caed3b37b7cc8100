// Cut-outs (Mesh::AlphaMode::Mask: leaves, fences, grates) as the reference ray casters see them:
// a ray passes a cut-out's triangle where its coverage, the base colour's alpha times the
// texture's alpha at the hit, is below the cutoff. Shared by the ray-cast ground truth (which
// must see through them, or what a grate shows would never count as visible) and the path
// tracer. See-through surfaces (Mesh::AlphaMode::Blend: glass) are passed stochastically, with
// probability 1 - coverage, the renderer's screen-door transparency in expectation; the ground
// truth passes them always (ray_ground_truth.cpp). Tests and benchmarks only.
#pragma once

#include <lintel/reference/linear_texture.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>

namespace lintel::reference {

struct CutOut {
  bool masked = false;                     // false: every point is surface (Opaque)
  bool blend = false;                      // Blend: the cutoff is a hash of the hit, uniform in [0, 1)
  float base_alpha = 1.0f;                 // Mesh::base_color.a
  float cutoff = 0.5f;                     // Mesh::alpha_cutoff
  const uint32_t* indices = nullptr;       // 3 per triangle, as the Embree geometry holds them
  const glm::vec2* uvs = nullptr;          // per vertex, with `texture`
  const LinearTexture* texture = nullptr;  // the base colour texture, or null (alpha 1)
  TextureSampler sampler;
  const glm::vec4* colors = nullptr;  // per vertex COLOR_0 (its alpha multiplies), or null (1)

  // Whether the point at barycentrics (u, v) of triangle `triangle` is no surface: the texture
  // read at level of detail `lod` (linear_texture.h; -infinity: level 0, magnification), the
  // vertex colours' alpha interpolated.
  bool cut_away(uint32_t triangle, float u, float v, float lod) const;
};

// A number in [0, 1) fixed by a hit (its triangle and barycentrics): the see-through test's
// threshold, uniform over the hits of rays spread over a surface.
float hit_hash(uint32_t triangle, float u, float v);

// The cut-out of `mesh` (masked for Mesh::AlphaMode::Mask and Blend) over Embree's index buffer
// `indices`; `texture` is its decoded base colour texture and `uvs` its uvs (one per vertex), or
// both null; `colors` its COLOR_0 (one per vertex) or null. The pointers are kept: what they
// point to must outlive the CutOut.
CutOut cut_out_of(const Mesh& mesh, const uint32_t* indices, const glm::vec2* uvs, const LinearTexture* texture,
                  const glm::vec4* colors);

}  // namespace lintel::reference
