// Internal: software prefetches for builds that start with cold caches. A game renders between
// two builds, so the builder's scratch, its output and the World's lines it reads are out of
// every cache when a build begins; touching them one by one pays a memory latency each, in
// series. Asking for lines the build is about to touch, all at once, overlaps those misses
// (docs/perf.md, "Cold builds"). A prefetch never faults and changes no result: a line that is
// already cached costs an instruction.
#pragma once

#include <cstddef>
#include <cstdint>

namespace lintel::detail {

inline constexpr size_t kCacheLine = 64;

// At most this many lines per call: the hardware's own prefetcher follows a longer run once it
// has started, and a long range asked for at once would only push other lines out.
inline constexpr size_t kMaxPrefetchLines = 8;

template <int kWrite>
inline void prefetch_lines(const void* p, size_t bytes) {
  uintptr_t a = reinterpret_cast<uintptr_t>(p) & ~uintptr_t(kCacheLine - 1);
  const uintptr_t last = reinterpret_cast<uintptr_t>(p) + (bytes > 0 ? bytes - 1 : 0);
  for (size_t n = 0; a <= last && n < kMaxPrefetchLines; a += kCacheLine, ++n)
    __builtin_prefetch(reinterpret_cast<const void*>(a), kWrite, 3);
}

// The lines of [p, p + bytes) (its first kMaxPrefetchLines), for reading.
inline void prefetch_read(const void* p, size_t bytes = 1) { prefetch_lines<0>(p, bytes); }

// The same, about to be written.
inline void prefetch_write(const void* p, size_t bytes = 1) { prefetch_lines<1>(p, bytes); }

}  // namespace lintel::detail
