// Triangle soup with flat normals in building space (double), welded per (position, normal):
// what the shell and furniture builders emit before scene assembly moves it into a node's space.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace lintel::gen {

class ShellMesh {
 public:
  // A planar convex quad a-b-c-d (in order around it) facing `normal`; the winding is chosen so
  // that the front face (counter-clockwise, glTF) looks along `normal`.
  void add_quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d,
                const glm::dvec3& normal);
  void add_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& normal);
  // Appends `other` moved by the affine `transform` (normals by its inverse transpose).
  void append(const ShellMesh& other, const glm::dmat4& transform);

  const std::vector<glm::dvec3>& positions() const { return positions_; }
  const std::vector<glm::dvec3>& normals() const { return normals_; }
  const std::vector<uint32_t>& indices() const { return indices_; }
  size_t triangle_count() const { return indices_.size() / 3; }

 private:
  uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n);

  using Key = std::tuple<double, double, double, double, double, double>;
  std::map<Key, uint32_t> index_of_;  // exact match: shared edges are computed bit-identically
  std::vector<glm::dvec3> positions_;
  std::vector<glm::dvec3> normals_;
  std::vector<uint32_t> indices_;
};

}  // namespace lintel::gen
