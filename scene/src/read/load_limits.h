// The loader's caps. Each bounds memory or time for hostile input while staying far above any
// real indoor scene; docs/scene-format.md lists them. Sizes are checked before allocating.
#pragma once

#include <cstddef>
#include <cstdint>

namespace lintel::scene_read {

inline constexpr size_t kMaxNodes = size_t{1} << 20;  // 1 M nodes: ~200 B each in the loader
inline constexpr size_t kMaxMeshes = size_t{1} << 20;
inline constexpr size_t kMaxBuffers = 4096;
inline constexpr size_t kMaxBufferViews = size_t{1} << 20;
inline constexpr size_t kMaxAccessors = size_t{1} << 22;
inline constexpr size_t kMaxTotalBufferBytes = size_t{1} << 30;  // all buffers together: 1 GiB
// Vertices and indices read over all meshes together. A mesh's primitives may all name one big
// accessor, so these (not the file size) are what bound the merged meshes: 32 M vertices cost
// 768 MiB (position + normal), 128 M indices 512 MiB.
inline constexpr size_t kMaxTotalVertices = size_t{1} << 25;
inline constexpr size_t kMaxTotalIndices = size_t{1} << 27;
// Elements of one vertex accessor without a bufferView (zeros, what a sparse part fills in): such
// data costs the file nothing, so it gets its own small cap (real uses are sparse patches).
inline constexpr size_t kMaxZeroFilledElements = size_t{1} << 16;
// Base colour textures: each image at most 8192 x 8192 texels (checked from its header before it
// is decoded), all decoded images together at most 1 GiB of RGBA8 (four 8192^2 images).
inline constexpr uint32_t kMaxTextureSide = 8192;
inline constexpr size_t kMaxTotalTexelBytes = size_t{1} << 30;
inline constexpr size_t kMaxPortalTriangles = 1024;  // a 64-gon needs 62; the rest is slack
inline constexpr size_t kMaxTimelines = 1024;
// 64 Ki keys (keys are interpolated: that is 18 minutes keyed at every frame at 60 fps). The
// smallest key is 10 JSON values, so the limit stays reachable under kMaxJsonValues.
inline constexpr size_t kMaxTimelineKeys = size_t{1} << 16;
inline constexpr size_t kMaxTimelineFileBytes = size_t{64} << 20;  // standalone .json timelines

}  // namespace lintel::scene_read
