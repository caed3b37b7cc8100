// Welding is by exact coordinates on purpose: the shell builders compute every shared corner the
// same way, so neighbouring faces share vertices and a watertight ray caster sees no cracks.
#include "generate/shell_mesh.h"

#include <cassert>

namespace lintel::gen {

uint32_t ShellMesh::vertex(const glm::dvec3& p, const glm::dvec3& n) {
  const Key key{p.x, p.y, p.z, n.x, n.y, n.z};
  const auto [it, inserted] = index_of_.emplace(key, uint32_t(positions_.size()));
  if (inserted) {
    positions_.push_back(p);
    normals_.push_back(n);
  }
  return it->second;
}

void ShellMesh::add_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& normal) {
  const glm::dvec3 face = glm::cross(b - a, c - a);
  assert(glm::dot(face, face) > 0.0);
  const uint32_t ia = vertex(a, normal), ib = vertex(b, normal), ic = vertex(c, normal);
  if (glm::dot(face, normal) >= 0.0)
    indices_.insert(indices_.end(), {ia, ib, ic});
  else
    indices_.insert(indices_.end(), {ia, ic, ib});
}

void ShellMesh::add_quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d,
                         const glm::dvec3& normal) {
  add_triangle(a, b, c, normal);
  add_triangle(a, c, d, normal);
}

void ShellMesh::append(const ShellMesh& other, const glm::dmat4& transform) {
  assert(glm::determinant(glm::dmat3(transform)) > 0.0);  // a mirror would turn faces inside out
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(transform)));
  std::vector<uint32_t> remap(other.positions_.size());
  for (size_t i = 0; i < other.positions_.size(); ++i)
    remap[i] = vertex(glm::dvec3(transform * glm::dvec4(other.positions_[i], 1.0)),
                      glm::normalize(normal_matrix * other.normals_[i]));
  for (uint32_t i : other.indices_) indices_.push_back(remap[i]);
}

}  // namespace lintel::gen
