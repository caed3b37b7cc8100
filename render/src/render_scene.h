// What the renderer draws, packed once per World: every instance AND every cell's shell as
// drawables (the shells become instances of the cell they bound, so walls, floors and ceilings
// go through the same GPU cull and the same indirect draws as the furniture), one vertex/index
// buffer for all meshes, and the cull's scene.
#pragma once

#include <lintel/gpu/cull_data.h>
#include "base_color.h"
#include <lintel/render/render_shared.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::render {

struct Vertex {
  glm::vec3 position_mesh;
  glm::vec3 normal_mesh;
  glm::vec2 uv;  // TEXCOORD_0, (0, 0) where the mesh has none
  // COLOR_0 (linear RGBA) as 16-bit unorm, white where the mesh has none: rgb multiplies the
  // albedo, alpha a cut-out's coverage.
  glm::u16vec4 color;
};

struct RenderScene {
  // The World with one extra instance per cell that has a shell (named "<cell>#shell", in a
  // draw group of its own mesh), appended after the World's instances: drawable i < the World's
  // instance count is World::instances[i].
  World drawables;
  uint32_t world_instance_count = 0;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<gpu::MeshRange> mesh_ranges;      // per mesh
  std::vector<GpuDrawInstance> draw_instances;  // per drawable
  gpu::CullScene cull_scene;
  Aabb bounds_world;       // every drawable's bounds
  TextureLayers textures;  // World::textures as one 2D array, layer = index
};

// Errors: a scene over the cull's limits (pack_scene's messages).
Status build_render_scene(const World& world, RenderScene& out);

// Whether every drawable is single-sided and unmirrored (kFace* bits clear): then the g-buffer may
// cull back faces in the rasterizer instead of its fragment shader (FrameContext::one_sided).
bool all_one_sided(const RenderScene& scene);

// Whether some drawable is a cut-out (kFaceAlphaMask) or see-through (kFaceAlphaBlend): then the
// g-buffer and the shadow maps draw with the alpha test (gbuffer.frag's kAlphaTest,
// shadow_cutout.frag); otherwise without it.
bool any_cut_out(const RenderScene& scene);
// Whether some drawable gives off light (Mesh::emissive > 0): then the g-buffer writes emission
// (gbuffer.frag's kEmission); otherwise its emission target stays 0.
bool any_emission(const RenderScene& scene);

// Brings `scene` (built from a World of the same counts) up to date with `world`'s door state
// (Portal::open_*) and with the instances `moved` (indices < world_instance_count; their transform,
// bounds and cell, the cells' instance lists, their draw records and the cull scene, re-packed).
// `doors_changed` says whether any door differs. Errors (bad input): counts that differ, a moved
// index out of range; pack_scene's.
Status update_render_scene(const World& world, std::span<const uint32_t> moved, RenderScene& scene,
                           bool& doors_changed);

}  // namespace lintel::render
