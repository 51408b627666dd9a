#pragma once
// Properties every tree mesh must have; the tests assert them on every preset.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "quad_mesh.hpp"

namespace arbor {

struct MeshTopologyReport {
  std::size_t boundaryEdges = 0;       // edges with one face (only the open base ring may have them)
  std::size_t nonManifoldEdges = 0;    // edges with more than two faces
  std::size_t misorientedEdges = 0;    // edges used twice in the same direction
  std::size_t nonManifoldVertices = 0; // vertices whose faces do not form one fan
  std::size_t degenerateFaces = 0;     // repeated vertices or (nearly) zero area
  std::size_t components = 0;          // connected pieces (must be 1)
  int eulerCharacteristic = 0;         // V - E + F (2 for a closed tree, 1 with an open base)
  int minValence = 0, maxValence = 0;
  double signedVolume = 0;             // > 0 when the faces point outwards
};

MeshTopologyReport checkTopology(const QuadMesh& mesh);

// Pairs (one face from each list) that intersect although they share no vertex: a branch passing
// through another shows up here.
std::size_t intersectingFacePairs(const QuadMesh& mesh, const std::vector<std::uint32_t>& a,
                                  const std::vector<std::uint32_t>& b);

// Whether two quads (each split into two triangles) cross each other.
bool quadsIntersect(const std::array<glm::dvec3, 4>& a, const std::array<glm::dvec3, 4>& b);

// Faces with a corner within `radius` of `center`.
std::vector<std::uint32_t> facesNear(const QuadMesh& mesh, const glm::vec3& center, float radius);

}  // namespace arbor
