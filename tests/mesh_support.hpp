#pragma once
// Shared by the mesh, patch and render tests: a preset grown and meshed in one call.
#include <cstdint>
#include <string>

#include "mesh/tree_mesh.hpp"
#include "tree/build_tree.hpp"

namespace arbor::test {

// The preset's tree mesh; levels 0 keeps the species' own Levels.
TreeMesh meshOf(const std::string& preset, std::uint64_t seed = 1, int levels = 0);

// The preset at seed 1 grown to `levels` and built with its wind records, meshing the stem levels below
// `meshLevels` (0: all) and the rest as fake branches; the skeleton beside it for the leaves.
struct WindyTree {
  Skeleton skeleton;
  TreeGeometry geometry;
};
WindyTree windyTree(const std::string& preset, int levels, int meshLevels = 0);

}  // namespace arbor::test
