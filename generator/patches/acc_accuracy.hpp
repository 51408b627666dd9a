#pragma once
// How far ACC's geometry patches lie from the exact Catmull-Clark limit (OpenSubdiv), relative to the local
// branch radius: the figure that says whether the GPU's approximation is visible on a tree.
#include <cstddef>

#include "mesh/quad_mesh.hpp"
#include "patch_set.hpp"

namespace arbor {

struct AccAccuracy {
  std::size_t regularPatches = 0, extraordinaryPatches = 0;
  std::size_t samples = 0;  // (u, v) points evaluated, over both classes
  double regularMax = 0, regularRms = 0;              // |ACC - limit| / radius at the patch's corner 0
  double extraordinaryMax = 0, extraordinaryRms = 0;
};

// Samples every measured patch on a samplesPerSide x samplesPerSide grid of (u, v) including the corners.
// maxPatches = 0 measures every patch; otherwise every k-th patch (k = ceil(size / maxPatches)), so the choice
// is deterministic. Fallback patches are skipped (ACC does not draw them).
// The reference is LimitSurface (Bfr, default approximation level 2): exact at multiples of 1/4 in u and v,
// which 2, 3 or 5 samples per side hit; between them, near an extraordinary corner, the reference carries
// its own approximation error (measured: up to 2 branch radii), so other counts measure both.
AccAccuracy measureAccAccuracy(const QuadMesh& mesh, const PatchSet& patches, std::size_t maxPatches = 0,
                               int samplesPerSide = 5);

}  // namespace arbor
