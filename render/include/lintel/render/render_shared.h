// The one header shared by the renderer's C++ and GLSL (as cull_shared.h is for the cull): the
// per-instance draw data, lights, shadow views, GI surfels and probes, and every pass's push
// constants. std430 layouts; the C++ side asserts sizes so a reordered field fails to compile.
// docs/rendering.md describes the passes that read them.
#ifndef LINTEL_RENDER_SHARED_H
#define LINTEL_RENDER_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <cstdint>
namespace lintel::render {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
#define LINTEL_RENDER_CONST(name, value) inline constexpr uint32_t name = value
#else
#define LINTEL_RENDER_CONST(name, value) const uint name = value
#endif

// Light types (World Light::Type order).
LINTEL_RENDER_CONST(kLightPoint, 0u);
LINTEL_RENDER_CONST(kLightSpot, 1u);
LINTEL_RENDER_CONST(kLightDirectional, 2u);
// Compute workgroup sizes.
LINTEL_RENDER_CONST(kTileSize, 8u);             // image passes: 8 x 8 pixels
LINTEL_RENDER_CONST(kLinearGroupSize, 64u);     // surfel and probe passes
LINTEL_RENDER_CONST(kExposureGroupSize, 256u);  // exposure pass: threads per workgroup
// The exposure pass's two-level reduction: up to kExposureMaxGroups workgroups each write one slot
// (kExposureBins histogram counts, log2 sum, lit count, 2 unused) after exposure_value[0..3];
// 256 x 132 x 4 B = 132 KiB. A workgroup covers at least kExposureGroupSize x 16 pixels.
LINTEL_RENDER_CONST(kExposureMaxGroups, 256u);
LINTEL_RENDER_CONST(kExposureBins, 128u);
LINTEL_RENDER_CONST(kExposureSlotFloats, 132u);
LINTEL_RENDER_CONST(kExposurePixelsPerThread, 16u);
// Debug views (RenderOptions::pass), the tonemap pass's `view` push constant.
LINTEL_RENDER_CONST(kViewFinal, 0u);
LINTEL_RENDER_CONST(kViewAlbedo, 1u);
LINTEL_RENDER_CONST(kViewNormal, 2u);
LINTEL_RENDER_CONST(kViewDepth, 3u);
LINTEL_RENDER_CONST(kViewShadow, 4u);
LINTEL_RENDER_CONST(kViewGi, 5u);
LINTEL_RENDER_CONST(kViewAo, 6u);
// GpuDrawInstance texture layer of a mesh without a base-colour texture.
LINTEL_RENDER_CONST(kNoTexture, 0xffffffffu);
// GpuDrawInstance face flags (normal_to_world_c1.w bits): glTF doubleSided, and a mirroring
// transform (negative determinant), which turns the mesh's front faces clockwise (glTF 2.0 3.7.4).
LINTEL_RENDER_CONST(kFaceDoubleSided, 1u);
LINTEL_RENDER_CONST(kFaceMirrored, 2u);
// A cut-out (glTF alphaMode MASK): the g-buffer and the shadow maps drop its points whose texture
// alpha is below a threshold, its alphaCutoff over its base colour's alpha, stored as a half
// float in the bits from kFaceAlphaThresholdShift (base_color.glsl).
LINTEL_RENDER_CONST(kFaceAlphaMask, 4u);
// A see-through surface (glTF alphaMode BLEND: glass, water) drawn with screen-door transparency:
// a point has surface on the pixels of a 4 x 4 ordered dither whose threshold is below its
// coverage (base alpha x texture alpha x COLOR_0 alpha), so a fraction `coverage` of its pixels
// shows it and the rest what lies behind. The bits from kFaceAlphaThresholdShift hold 1 / base
// alpha as a half float (base_color.glsl).
LINTEL_RENDER_CONST(kFaceAlphaBlend, 8u);
LINTEL_RENDER_CONST(kFaceAlphaThresholdShift, 16u);
// GpuDrawInstance sampler bits (normal_to_world_c2.w): the glTF sampler of the base-colour
// texture (lintel::TextureSampler), applied in gbuffer.frag. Wrap per axis in 2 bits (0 repeat,
// 1 clamp to edge, 2 mirrored repeat), nearest mag / min texel filters, mip mode in 2 bits
// (0 none, 1 nearest, 2 linear). kSamplerDefault (repeat, trilinear) takes the sampler's own path.
LINTEL_RENDER_CONST(kSamplerWrapSShift, 0u);
LINTEL_RENDER_CONST(kSamplerWrapTShift, 2u);
LINTEL_RENDER_CONST(kSamplerMagNearest, 16u);
LINTEL_RENDER_CONST(kSamplerMinNearest, 32u);
LINTEL_RENDER_CONST(kSamplerMipShift, 6u);
LINTEL_RENDER_CONST(kSamplerDefault, 128u);
// The emissive texture's sampler, in the same 8-bit code, from this bit of normal_to_world_c2.w.
LINTEL_RENDER_CONST(kSamplerEmissiveShift, 8u);
// G-buffer cell id of a background pixel.
LINTEL_RENDER_CONST(kNoCell, 0xffffffffu);
// A g-buffer cell id (and GpuDrawInstance::albedo.w) is the cell in its low 24 bits and, from bit
// kCellLinkShift, the view transform it was drawn with: 0 for the plain view, t >= 1 for a linked
// view (VisibleSet::transforms[t]: the pixel shows that cell through a mirror or teleport). The
// lighting pass lights such a pixel where the surface really is (GpuLinkView::world_from_seen).
LINTEL_RENDER_CONST(kCellIdMask, 0x00ffffffu);
LINTEL_RENDER_CONST(kCellLinkShift, 24u);
// Linked views a frame may draw (VisibleSet transforms, the identity included): the lighting
// pass's per-slot GpuLinkView array. lintel::kMaxViewTransforms (asserted in renderer_linked.cpp).
LINTEL_RENDER_CONST(kMaxLinkViews, 64u);
// Active-light entry of a light that got no shadow-atlas slot this frame (it lights unshadowed).
LINTEL_RENDER_CONST(kNoShadowSlot, 0xffffffffu);

// One drawable (a World instance or a cell's shell): read by the g-buffer and shadow vertex
// shaders at gl_InstanceIndex -> the cull's id buffer -> this.
struct GpuDrawInstance {
  mat4 mesh_to_world;
  vec4 normal_to_world_c0;  // inverse-transpose of mesh_to_world's 3x3, columns; c0.w = texture layer (uint bits)
  vec4 normal_to_world_c1;  // c1.w = face flags (kFace*, uint bits)
  vec4 normal_to_world_c2;  // c2.w = sampler bits (kSampler*, uint bits)
  vec4 albedo;              // linear base colour; w = the cell as a float-exact uint (bits)
  vec4 emission;            // rgb = Mesh::emissive (linear radiance); w = emissive texture layer or kNoTexture (bits)
};
// GpuDrawInstance in rgba32ui texels (the draw set's kDrawBindInstances).
LINTEL_RENDER_CONST(kDrawInstanceTexels, 9u);

// A light as the lighting passes read it. Radiant intensity = color (colour x intensity).
struct GpuLight {
  vec4 position_type;      // xyz world position, w = type (as float)
  vec4 direction_range;    // xyz unit direction the light points, w = range (0 = unlimited)
  vec4 color;              // rgb = colour x intensity; w unused
  vec4 cone;               // x = spot scale, y = spot offset (KHR_lights_punctual), z = shadow texel size per
                           // meter of distance (perspective views), w unused
  uint shadow_view;        // first shadow view: its matrix in shadow_views (atlas layers come per frame)
  uint shadow_view_count;  // 1 (spot), 2 (the sun: fine, then coarse) or 6 (cube faces +X,-X,+Y,-Y,+Z,-Z)
  uint mask_offset;        // first word of this light's cell bitmask
  uint unused;             // std430 pads the struct to 80 bytes anyway
};

// A point on a surface that the GI lights each frame: the irradiance it receives (direct, and
// from its cell's probes) makes its outgoing radiance, which the probes of its cell gather.
struct GpuSurfel {
  vec4 position_cell;  // xyz world position, w = the cell (uint bits)
  vec4 normal_area;    // xyz unit normal, w = area in m^2 it stands for
  vec4 albedo;         // rgb; w = 1 for a surface, 0 for a portal surfel (radiance from the neighbour)
  uvec4 portal;        // portal surfel: x = neighbour cell, y = portal, z = its open flag in active_cells; w unused
  vec4 emission;       // surface surfel: the radiance it gives off by itself (Mesh::emissive x texture); w unused
};
// GpuSurfel in rgba32ui texels (kBindSurfels).
LINTEL_RENDER_CONST(kSurfelTexels, 5u);

// Per cell, its probe grid (probes only ever serve their own cell). The grid's space is built from
// the cell's world-space geometry, never from the cell's frame, so how a file frames its cells
// cannot change the GI (today world axes: world_to_grid is the identity).
struct GpuCellProbes {
  mat4 world_to_grid;
  vec4 origin_grid;  // xyz: probe (0,0,0) in grid space; w unused
  vec4 step_grid;    // xyz: spacing per axis (grid space); w unused
  uvec4 dims;        // xyz probes per axis; w = first probe index
  uvec4 surfels;     // x = first surfel, y = surfel count, z = first portal surfel, w = portal surfel count
};

// SH L1 radiance per probe, 4 coefficients x rgb in three vec4: sh[k].rgb = coefficient k for
// k < 3, (sh[0].w, sh[1].w, sh[2].w) = coefficient 3 (so a lookup reads three texels, not four).
struct GpuProbe {
  vec4 position_world;  // w = the cell (uint bits)
  vec4 sh[3];
  uvec4 visibility;  // x = the first texel of its surfel visibility bits (kBindProbeVisibility); yzw unused
};

struct GBufferPush {
  mat4 view_proj;  // world -> clip
  vec4 eye_world;  // the normals of double-sided surfaces are turned to face it
  // Camera draws (link.y = 1; shadow views push zeros): link.x = the view drawn (0 the plain one, t
  // a linked view: VisibleSet::transforms[t]). Its fragments are kept inside the view's pyramid
  // and, for t >= 1, inside clip_rect_px (framebuffer pixels: min x, min y, max x, max y; the rect
  // of its regions), and dropped where a linked view seen from it takes over (GpuLinkClip).
  vec4 clip_rect_px;
  uvec4 link;
};

// Per frame slot, per view drawn by the camera (index = its transform): what the g-buffer keeps.
// Pyramids are runs in the plane array after the views: a header (x = plane count n) then n
// planes (xyz, w: inside where dot(xyz, p) + w >= 0, p as drawn): the linked portal's plane (the
// far side) and one plane per portal edge through the eye. A linked view keeps only what lies in
// its portal's pyramid (widened by a millimetre: conservative); every view drops what lies in
// the pyramids of the linked views seen from it (narrowed by the same: a seam shows the wall
// rather than a crack the background).
struct GpuLinkClip {
  uvec4 keep;  // x = first plane (its header), y = 1 when the view has a pyramid; zw unused
  uvec4 cut;   // x = first plane of the first cut pyramid, y = cut pyramids (consecutive runs); zw unused
};

// Per frame slot, per linked view (index = its transform, [0] the identity): where a pixel drawn
// through it really is, for the lighting pass.
struct GpuLinkView {
  mat4 world_from_seen;  // inverse of VisibleSet's seen_from_world
};

struct LightingPush {
  mat4 clip_to_world;  // inverse of view_proj
  uvec4 size;          // x, y = image size; z = GI on (1/0); w = AO on (1/0)
  uvec4 mode;          // x = active light count (unused: lists per cell), y = view (kView*)
  vec4 environment;    // rgb = the sky's radiance (World::environment); w unused
};

// The hierarchical-Z stages' push constants (render/shaders/hiz.glsl, passes/hiz_pass.cpp).
struct HizPush {
  mat4 view_proj;
  uvec4 counts;  // id capacity (CullScene::id_capacity), draw groups, phase (stage 1), pyramid levels
  uvec4 image;   // depth image width, height, destination level (stage 2), first shell drawable
};

struct SurfelLightPush {
  uvec4 counts;  // x = surfels, y = lights, z = bounce index (0: direct only), w unused
};

struct ProbeGatherPush {
  uvec4 counts;  // x = probes; yzw unused
};

struct GtaoPush {
  mat4 world_to_view;  // normals and positions into view space (right-handed, looking down -Z)
  vec4 projection;     // x = tan(fov_x / 2), y = tan(fov_y / 2), z = near, w = far
  vec4 params;         // x = radius (m), y = slices, z = steps per side, w = falloff range fraction
  uvec4 size;          // x, y = full image size; z = 2: half resolution (one pixel per 2x2 block, into
                       // ao_half_image), 1: every pixel (into ao_image); w unused
};

struct AoUpsamplePush {
  vec4 params;      // x = relative view-depth tolerance of the upsample's depth weight; yzw unused
  vec4 projection;  // z = near, w = far (view depth from the depth buffer); xy unused
  uvec4 size;       // x, y = full image size; z, w = half image size
};

struct TonemapPush {
  vec4 params;  // x = exposure (used when w of size is 0), y = near, z = far, w = depth view range (m)
  uvec4 size;   // x, y; z = view (kView*); w = 1: the exposure pass's value (exposure_value[0])
};

struct ExposurePush {
  vec4 params;  // x = multiplier (--exposure); yzw unused
  uvec4 size;   // x, y = image size; z = workgroups of the histogram stage; w = stage (0 histogram, 1 resolve)
};

#ifdef __cplusplus
static_assert(sizeof(GpuDrawInstance) == 16 * kDrawInstanceTexels);
static_assert(sizeof(GpuLight) == 80);
static_assert(sizeof(GpuSurfel) == 16 * kSurfelTexels);
static_assert(sizeof(GpuCellProbes) == 128);
static_assert(sizeof(GpuProbe) == 80);
static_assert(sizeof(GpuLinkView) == 64 && sizeof(GpuLinkClip) == 32);
// Every push block fits the 128 bytes every Vulkan device guarantees.
static_assert(sizeof(GBufferPush) <= 128 && sizeof(LightingPush) <= 128 && sizeof(GtaoPush) <= 128);
static_assert(sizeof(TonemapPush) <= 128 && sizeof(SurfelLightPush) <= 128 && sizeof(ProbeGatherPush) <= 128);
static_assert(sizeof(ExposurePush) <= 128 && sizeof(AoUpsamplePush) <= 128 && sizeof(HizPush) <= 128);
}  // namespace lintel::render
#endif

#endif  // LINTEL_RENDER_SHARED_H
