#pragma once
// The checks every grown tree's mesh must pass, whatever grew it: one closed, consistently oriented, outward
// 2-manifold piece of genus 0 (a tree's skeleton has no loops). Catch CHECKs, so one report names them all.
#include <catch2/catch.hpp>

#include "mesh/mesh_checks.hpp"
#include "mesh/quad_mesh.hpp"

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

}  // namespace arbor::test
