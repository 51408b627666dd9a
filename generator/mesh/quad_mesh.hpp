#pragma once
// One connected quad mesh per tree (Nystad 4.3, 5.3): the value the mesh stage hands to patches and exports.
// Object space in metres, z up. Every vertex has exactly one set of attributes: the flip coordinate makes
// texture seams unnecessary, so no vertex is ever split.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace arbor {

struct QuadMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // unit, area-weighted from the faces around the vertex
  std::vector<glm::vec3> tangents;   // unit, along the branch (direction of increasing v)
  std::vector<glm::vec3> uvw;        // u mirrored 0..1 front to back, v along the branch, w = flip coordinate
  std::vector<float> radius;         // branch radius the vertex was placed for
  std::vector<std::uint8_t> level;   // stem level (0 = trunk)
  std::vector<std::array<std::uint32_t, 4>> quads;  // counter-clockwise seen from outside

  std::vector<std::uint32_t> openBoundary;  // the open ring at the trunk base, if asked for (else empty)

  std::size_t vertexCount() const { return positions.size(); }
};

// Each quad split along its shorter diagonal, keeping the outward orientation.
std::vector<std::array<std::uint32_t, 3>> triangulate(const QuadMesh& mesh);

}  // namespace arbor
