#pragma once
// Faces one mesh has and another does not, told apart by their corners' positions (vertex indices change when
// quads are taken out): the faces that closed twigs' ports, for the crossing-twig tests.
#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "mesh/quad_mesh.hpp"

namespace arbor::test {

using FacePoints = std::array<std::array<float, 3>, 4>;

// A face as its corners' positions, sorted: the same face whatever its vertices' indices or first corner.
inline FacePoints facePoints(const QuadMesh& mesh, const std::array<std::uint32_t, 4>& q) {
  FacePoints f;
  for (std::size_t k = 0; k < 4; ++k) f[k] = {mesh.positions[q[k]].x, mesh.positions[q[k]].y, mesh.positions[q[k]].z};
  std::sort(f.begin(), f.end());
  return f;
}

// The faces of `after` (their indices, ascending) that `before` does not have.
inline std::vector<std::uint32_t> newFaces(const QuadMesh& before, const QuadMesh& after) {
  std::set<FacePoints> had;
  for (const auto& q : before.quads) had.insert(facePoints(before, q));
  std::vector<std::uint32_t> faces;
  for (std::uint32_t f = 0; f < after.quads.size(); ++f) {
    if (!had.contains(facePoints(after, after.quads[f]))) faces.push_back(f);
  }
  return faces;
}

}  // namespace arbor::test
