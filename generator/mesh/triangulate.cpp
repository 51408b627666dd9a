#include <glm/geometric.hpp>

#include "quad_mesh.hpp"

namespace arbor {

std::vector<std::array<std::uint32_t, 3>> triangulate(const QuadMesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(mesh.quads.size() * 2);
  for (const auto& q : mesh.quads) {
    const auto& p = mesh.positions;
    const float d02 = glm::distance(p[q[0]], p[q[2]]);
    const float d13 = glm::distance(p[q[1]], p[q[3]]);
    if (d02 <= d13) {
      triangles.push_back({q[0], q[1], q[2]});
      triangles.push_back({q[0], q[2], q[3]});
    } else {
      triangles.push_back({q[0], q[1], q[3]});
      triangles.push_back({q[1], q[2], q[3]});
    }
  }
  return triangles;
}

}  // namespace arbor
