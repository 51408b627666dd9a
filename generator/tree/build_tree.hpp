#pragma once
// The one "build a tree" stage every command, the forest and the tests use: a skeleton (from any growth model,
// or a file) -> one quad mesh -> 1-ring patches, with the levels past the mesh as fake-branch segments. What
// grew the skeleton is not known here.
#include <vector>

#include "growth/skeleton.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/mesh_options.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/patch_set.hpp"
#include "wind.hpp"

namespace arbor {

struct BuildOptions {
  MeshOptions mesh;     // mesh.levels: stem levels meshed (0: all); the deeper ones become fake-branch segments
  bool patches = true;  // the GPU's 1-ring patches (off for exports and checks that need only the mesh)
  bool wind = false;    // what moves each vertex, leaf and fake branch in the wind (the renderer's)
};

struct TreeGeometry {
  TreeMesh mesh;
  PatchSet patches;
  std::vector<ImpostorSegment> impostors;  // the levels past the mesh and every stub, one segment per skeleton edge
  std::vector<ImpostorSegment> sketch;     // a coarser sketch of them, without the deepest, for trees far away
  TreeWind wind;                           // with BuildOptions::wind
};

TreeGeometry buildTree(const Skeleton& skeleton, const BuildOptions& options = {});

}  // namespace arbor
