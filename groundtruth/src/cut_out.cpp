// Coverage of a cut-out at a ray's hit (cut_out.h).
#include <lintel/reference/cut_out.h>

#include <cstring>

namespace lintel::reference {

bool CutOut::cut_away(uint32_t triangle, float u, float v, float lod) const {
  if (!masked) return false;
  float coverage = base_alpha;
  const uint32_t* tri = indices + 3 * size_t{triangle};
  if (texture) {
    const glm::vec2 uv = (1.0f - u - v) * uvs[tri[0]] + u * uvs[tri[1]] + v * uvs[tri[2]];
    coverage *= sample_alpha(*texture, sampler, uv, lod);
  }
  if (colors) coverage *= (1.0f - u - v) * colors[tri[0]].a + u * colors[tri[1]].a + v * colors[tri[2]].a;
  return coverage < (blend ? hit_hash(triangle, u, v) : cutoff);
}

float hit_hash(uint32_t triangle, float u, float v) {
  uint32_t bu, bv;
  std::memcpy(&bu, &u, 4);
  std::memcpy(&bv, &v, 4);
  // SplitMix64's finalizer over the three words.
  uint64_t z = (uint64_t(bu) << 32 | bv) ^ (uint64_t(triangle) * 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return float(z >> 40) * (1.0f / 16777216.0f);
}

CutOut cut_out_of(const Mesh& mesh, const uint32_t* indices, const glm::vec2* uvs, const LinearTexture* texture,
                  const glm::vec4* colors) {
  CutOut c;
  c.masked = mesh.alpha_mode != Mesh::AlphaMode::Opaque;
  c.blend = mesh.alpha_mode == Mesh::AlphaMode::Blend;
  c.base_alpha = mesh.base_color.a;
  c.cutoff = mesh.alpha_cutoff;
  c.indices = indices;
  c.colors = colors;
  if (texture && uvs) {
    c.uvs = uvs;
    c.texture = texture;
    c.sampler = mesh.base_color_sampler;
  }
  return c;
}

}  // namespace lintel::reference
