#pragma once
// What `arbor` finds in the subdivision module (libarbor_subdivide.so): OpenSubdiv's Catmull-Clark refinement,
// loaded only by an export that asks for it, so no other command maps OpenSubdiv and its OpenMP runtime at start.
#include <cstddef>

#include "mesh/quad_mesh.hpp"

namespace arbor {

struct SubdivideModule {
  int version;  // kSubdivideModuleVersion: a module from another build is refused, not called
  QuadMesh (*subdivide)(const QuadMesh& mesh, int levels, std::size_t maxQuads);
};

inline constexpr int kSubdivideModuleVersion = 1;
inline constexpr const char* kSubdivideModuleFile = "libarbor_subdivide.so";
inline constexpr const char* kSubdivideModuleEntry = "arborSubdivideModule";  // extern "C" const SubdivideModule* ()

}  // namespace arbor
