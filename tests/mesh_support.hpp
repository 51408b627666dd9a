#pragma once
// Shared by the mesh, patch and render tests: a preset grown and meshed in one call.
#include <cstdint>
#include <string>

#include "mesh/tree_mesh.hpp"

namespace arbor::test {

// The preset's tree mesh; levels 0 keeps the species' own Levels.
TreeMesh meshOf(const std::string& preset, std::uint64_t seed = 1, int levels = 0);

}  // namespace arbor::test
