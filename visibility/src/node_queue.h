// Internal: the flood's queue, nearest first. A cell popped before all the polygons it will
// receive have arrived is popped again for the late ones (a re-queue), and every re-pop sends new
// pieces on to its neighbours, which may be popped again in turn. Pieces travel away from the eye
// (a portal is looked through only when it faces the eye), so popping first the cell entered
// through the portal nearest the eye lets most of a cell's polygons arrive before it is popped:
// they are then processed together, and merged (pending_merge.h). The order changes which
// polygons a pop sees at once, never whether a polygon is processed: the flood's answer stays
// conservative and the pop bound (a count of enqueues) holds for any order (docs/visibility.md).
#pragma once

#include "prefetch.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace lintel::detail {

class NodeQueue {
 public:
  // Room for `capacity` entries (a node is queued at most once at a time): push never allocates.
  void prepare(size_t capacity) {
    heap_.clear();
    heap_.reserve(capacity);
  }
  void clear() { heap_.clear(); }
  void prefetch_head() const { prefetch_write(heap_.data()); }
  bool empty() const { return heap_.empty(); }

  // `key`: the squared distance from the eye to the box of the portal the node was queued
  // through. Equal keys pop in node order, so the order, like everything else in a build, is
  // deterministic.
  void push(float key, uint32_t node) {
    assert(heap_.size() < heap_.capacity());
    heap_.emplace_back(key, node);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  }
  uint32_t pop() {
    assert(!heap_.empty());
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const uint32_t node = heap_.back().second;
    heap_.pop_back();
    return node;
  }

 private:
  std::vector<std::pair<float, uint32_t>> heap_;  // a min-heap on (key, node)
};

}  // namespace lintel::detail
