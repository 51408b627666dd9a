#include "mesh_attributes.hpp"

#include <numbers>

#include <glm/geometric.hpp>

namespace arbor {

void computeNormals(QuadMesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& q : mesh.quads) {
    // Half the cross product of the diagonals: the quad's area-weighted normal, even when not planar.
    const glm::dvec3 a(mesh.positions[q[2]] - mesh.positions[q[0]]);
    const glm::dvec3 b(mesh.positions[q[3]] - mesh.positions[q[1]]);
    const glm::dvec3 n = 0.5 * glm::cross(a, b);
    for (std::uint32_t v : q) sum[v] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double len = glm::length(sum[i]);
    mesh.normals[i] = len > 0.0 ? glm::vec3(sum[i] / len) : glm::vec3(0, 0, 1);
  }
}

double barkTextureAdvance(double distance, double radius) {
  return distance / (std::numbers::pi * (0.2 + 0.8 * radius));
}

}  // namespace arbor
