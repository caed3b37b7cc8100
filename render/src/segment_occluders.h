// Whether a straight segment between two points inside a cell crosses any of the cell's
// triangles: the GI's visibility between a probe and a surfel (gi_layout.cpp). A small bounding
// volume hierarchy over the triangles, built once per cell; both sides of a triangle block (a
// single-sided wall is still solid for light), and the first surface hit says whether the start
// point looks at a front or a back face (a probe buried in a wall or outside its room sees the
// backs of the room's faces).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::render {

class SegmentOccluders {
 public:
  struct Triangle {
    glm::vec3 a, b, c;
    glm::vec3 normal;  // the front face's unit normal
  };
  explicit SegmentOccluders(std::vector<Triangle> triangles);

  enum class Hit { None, Front, Back };
  // The first triangle the segment from `from` to `to` crosses strictly between its ends (ends
  // excluded by a relative margin), and which of its faces looks at `from`.
  Hit first_hit(const glm::vec3& from, const glm::vec3& to) const;
  // Whether any triangle crosses the segment strictly between its ends (stops at the first found).
  bool blocked(const glm::vec3& from, const glm::vec3& to) const;

 private:
  struct Node {
    glm::vec3 min, max;
    uint32_t first = 0, count = 0;  // a leaf's triangles; count 0: children at first, first + 1
  };
  void build(uint32_t node, uint32_t begin, uint32_t end);
  // Nearest crossing in (margin, 1 - margin) of from + t (to - from), or null; with `any`, the first found.
  const Triangle* cross(const glm::vec3& from, const glm::vec3& to, bool any) const;

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
};

}  // namespace lintel::render
