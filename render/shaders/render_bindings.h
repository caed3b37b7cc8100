// Descriptor binding numbers of the renderer's set layouts (draw, compute, hiz), named once for the C++ and the
// GLSL side (included by both, like render_shared.h). The C++ set layouts are built from these
// names (render/src/binding_tables.cpp) and every pipeline is checked against its shader's
// declarations when it is created (render/src/spirv_bindings.h), so a renumbered binding fails
// at setup with the binding's name instead of rendering garbage.
#ifndef LINTEL_RENDER_BINDINGS_H
#define LINTEL_RENDER_BINDINGS_H

#include "lintel/render/render_shared.h"

#ifdef __cplusplus
namespace lintel::render {
#endif

// Draw set (set 0 of the g-buffer and shadow pipelines; one set per camera slot, one for shadows).
LINTEL_RENDER_CONST(kDrawBindIds, 0u);        // storage: drawable ids (the cull's, or static lists)
LINTEL_RENDER_CONST(kDrawBindInstances, 1u);  // texel: GpuDrawInstance per drawable (kDrawInstanceTexels)
LINTEL_RENDER_CONST(kDrawBindCounts, 2u);     // storage: fragment counts (tests)
LINTEL_RENDER_CONST(kDrawBindTextures, 3u);   // combined sampler: base-colour texture array
LINTEL_RENDER_CONST(kDrawBindLinkClip, 4u);   // texel: GpuLinkClip per view, then pyramid planes
LINTEL_RENDER_CONST(kDrawBindingCount, 5u);

// Compute set (set 0 of every compute pass; one set per frame slot). Data the passes only read
// per pixel is bound as uniform texel buffers (rgba32ui texels, read with texelFetch), not storage
// buffers: lavapipe loads a storage buffer with a per-pixel index one lane at a time, a texel
// buffer with one vector gather (docs/rendering.md, "Performance").
LINTEL_RENDER_CONST(kBindLights, 0u);                 // texel: GpuLight (5 texels each)
LINTEL_RENDER_CONST(kBindActiveLights, 1u);           // texel (uvec2), host-written per frame slot
LINTEL_RENDER_CONST(kBindShadowViews, 2u);            // texel: shadow view matrices (4 texels each)
LINTEL_RENDER_CONST(kBindLightMasks, 3u);             // storage: per-light cell bitmasks
LINTEL_RENDER_CONST(kBindShadowAtlas, 4u);            // combined sampler: D32 array
LINTEL_RENDER_CONST(kBindCellProbes, 5u);             // texel: GpuCellProbes (8 texels each)
LINTEL_RENDER_CONST(kBindProbes, 6u);                 // storage: GpuProbe (written by the GI gather)
LINTEL_RENDER_CONST(kBindSurfels, 7u);                // texel: GpuSurfel (kSurfelTexels each)
LINTEL_RENDER_CONST(kBindSurfelRadiance, 8u);         // storage
LINTEL_RENDER_CONST(kBindActiveCells, 9u);            // storage, host-written per frame slot
LINTEL_RENDER_CONST(kBindAlbedo, 10u);                // storage image rgba8
LINTEL_RENDER_CONST(kBindNormal, 11u);                // storage image rgba16f
LINTEL_RENDER_CONST(kBindCell, 12u);                  // storage image r32ui
LINTEL_RENDER_CONST(kBindDepth, 13u);                 // combined sampler: D32
LINTEL_RENDER_CONST(kBindAo, 14u);                    // storage image r32f
LINTEL_RENDER_CONST(kBindHdr, 15u);                   // storage image rgba32f
LINTEL_RENDER_CONST(kBindLdr, 16u);                   // storage image rgba8
LINTEL_RENDER_CONST(kBindExposure, 17u);              // storage: this frame's exposure
LINTEL_RENDER_CONST(kBindAoHalf, 18u);                // storage image r32f: GTAO at half resolution
LINTEL_RENDER_CONST(kBindLinkViews, 19u);             // texel, host-written per frame slot: GpuLinkView
LINTEL_RENDER_CONST(kBindProbeTexels, 20u);           // texel: the probes buffer again, for reading
LINTEL_RENDER_CONST(kBindSurfelRadianceTexels, 21u);  // texel: surfel radiance again, for reading
LINTEL_RENDER_CONST(kBindProbeVisibility, 22u);       // texel: per probe, a bit per surfel of its cell
LINTEL_RENDER_CONST(kBindEmission, 23u);              // storage image rgba16f: g-buffer emission
LINTEL_RENDER_CONST(kComputeBindingCount, 24u);

// Hiz set (set 0 of the four hiz_*.comp pipelines, render/src/passes/hiz_pass.h; one set).
LINTEL_RENDER_CONST(kHizBindCullCommands, 0u);  // storage: the portal cull's commands (read)
LINTEL_RENDER_CONST(kHizBindCullIds, 1u);       // storage: the portal cull's ids (read)
LINTEL_RENDER_CONST(kHizBindCommands, 2u);      // storage: 2 x groups commands, phase 1 then 2
LINTEL_RENDER_CONST(kHizBindIds, 3u);           // storage: 2 x id capacity, phase 1 then 2
LINTEL_RENDER_CONST(kHizBindCounters, 4u);      // storage: 2 x groups counts, then tested, passed
LINTEL_RENDER_CONST(kHizBindVisibility, 5u);    // storage: per drawable, visible last frame
LINTEL_RENDER_CONST(kHizBindPyramid, 6u);       // storage: every pyramid level, packed
LINTEL_RENDER_CONST(kHizBindInstances, 7u);     // storage: gpu::GpuInstance per drawable
LINTEL_RENDER_CONST(kHizBindSlotGroups, 8u);    // storage: per id slot, its draw group
LINTEL_RENDER_CONST(kHizBindDepth, 9u);         // combined sampler: the g-buffer's D32
LINTEL_RENDER_CONST(kHizBindingCount, 10u);

#ifdef __cplusplus
}  // namespace lintel::render
#endif

#endif  // LINTEL_RENDER_BINDINGS_H
