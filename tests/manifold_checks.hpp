#pragma once
// The checks every grown tree's mesh must pass, whatever grew it: one closed, consistently oriented, outward
// 2-manifold piece of genus 0 (a tree's skeleton has no loops). Catch CHECKs, so one report names them all.
// Also whether a band between two cross sections runs forwards (one that does not folds).
#include <catch2/catch.hpp>
#include <cstddef>

#include "mesh/mesh_checks.hpp"
#include "mesh/quad_mesh.hpp"
#include "mesh/tree_mesh.hpp"

namespace arbor::test {

inline MeshTopologyReport checkClosedManifold(const QuadMesh& mesh) {
  const MeshTopologyReport r = checkTopology(mesh);
  CHECK(!mesh.quads.empty());
  CHECK(r.boundaryEdges == 0);
  CHECK(r.nonManifoldEdges == 0);
  CHECK(r.misorientedEdges == 0);
  CHECK(r.nonManifoldVertices == 0);
  CHECK(r.components == 1);
  CHECK(r.eulerCharacteristic == 2);
  CHECK(r.signedVolume > 0.0);  // faces point outwards
  return r;
}

// The band from ring a to ring b runs forwards: b's corners ahead of a (its direction from its corners,
// counter-clockwise about it) and a's behind b.
inline bool bandRunsForwards(const TreeMesh& tree, const MeshRing& a, const MeshRing& b) {
  auto corner = [&](const MeshRing& ring, std::size_t k) { return Vec3(tree.mesh.positions[ring.vertices[k]]); };
  auto direction = [&](const MeshRing& ring) {
    return glm::normalize(glm::cross(corner(ring, 0) - corner(ring, 2), corner(ring, 1) - corner(ring, 3)));
  };
  for (std::size_t k = 0; k < 4; ++k) {
    if (!(glm::dot(corner(b, k) - a.center, direction(a)) > 0.0) || !(glm::dot(corner(a, k) - b.center, direction(b)) < 0.0)) return false;
  }
  return true;
}

}  // namespace arbor::test
