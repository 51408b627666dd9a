#pragma once
// ACC checks shared by the patch tests (presets) and the random-graph test: patches meet their neighbours
// without cracks, and their corners are Catmull-Clark's exact limit positions and normals (OpenSubdiv's).
#include <array>
#include <cstddef>

#include "mesh/quad_mesh.hpp"
#include "patches/patch_set.hpp"

namespace arbor::test {

// Twigs end in points: the floor keeps ratios finite there (as measureAccAccuracy does).
double patchRadius(const QuadMesh& mesh, std::size_t patch);

struct AccCrackCheck {
  double worst = 0;             // largest gap between neighbouring patches along their shared edge, in radii
  std::size_t sharedEdges = 0;  // each counted once: 2 per patch on a closed quad mesh
  std::size_t unpaired = 0;     // directed edges without their opposite (a hole or a flipped face)
};

// Both patches' Bezier edges sampled at five points along every shared edge.
AccCrackCheck accCracks(const QuadMesh& mesh, const PatchSet& set);

struct AccCornerCheck {
  double worstPosition = 0;   // corner Bezier point against OpenSubdiv's limit position, in radii
  double worstNormal = 0;     // corner normal against OpenSubdiv's limit tangents' cross product, radians
  double worstUnit = 0;       // |length of the corner normal - 1|
  double worstBlend = 0;      // accNormal at a corner against that corner's exact normal, radians
  bool finite = true;         // every Bezier point and corner normal finite
  std::size_t corners = 0;
  std::array<std::size_t, 7> valences{};  // corners by valence (6: 6 or more)
};

// Every `stride`-th patch's four corners. Throws for a fallback patch (ACC has no form for it).
AccCornerCheck accCorners(const QuadMesh& mesh, const PatchSet& set, std::size_t stride = 1);

}  // namespace arbor::test
