#pragma once
// Patches for the GPU (Nystad 5.3.3): every quad with its 1-ring in counter-clockwise order.
//
// Layout of one patch's control points: the quad's corners c0..c3, then the loop of 1-ring vertices
// around the quad (counter-clockwise), in which corner i's own ring is the run of 2 n_i - 3 points
// starting at prefix[i] (cyclically). Corner i's full ring, counter-clockwise about it and starting
// at c(i+1), is then c(i+1), c(i+2), c(i+3) followed by that run. Neighbouring runs share two points,
// so a patch has 2 (n0 + n1 + n2 + n3) - 16 points: 16 when regular, at most 32 by design.
#include <array>
#include <cstdint>
#include <vector>

#include "mesh/quad_mesh.hpp"

namespace arbor {

constexpr int kMaxPatchPoints = 32;  // Vulkan maxTessellationPatchSize on both drivers measured here

enum class PatchKind : std::uint8_t {
  Regular = 0,        // all four corners of valence 4: exactly a bicubic B-spline patch
  Extraordinary = 1,  // some corner of another valence: approximated (ACC)
  Fallback = 2,       // on the open boundary or beyond 32 points: drawn from its corners alone
};

struct PatchSet {
  std::vector<std::uint32_t> points;   // control point vertex indices, patch p in [offset[p], offset[p + 1])
  std::vector<std::uint32_t> offset;   // one more than the number of patches
  std::vector<std::array<std::uint8_t, 4>> valence;
  std::vector<std::array<std::uint8_t, 4>> prefix;  // start of each corner's run within the loop
  std::vector<PatchKind> kind;

  std::size_t size() const { return kind.size(); }
  std::size_t pointCount(std::size_t p) const { return offset[p + 1] - offset[p]; }
  const std::uint32_t* pointsOf(std::size_t p) const { return points.data() + offset[p]; }
};

// One patch per quad, in quad order.
PatchSet buildPatches(const QuadMesh& mesh);

// Corner i's ring (2 n_i vertices, counter-clockwise about it, starting at corner i + 1), read back from
// the layout exactly as a shader does.
std::vector<std::uint32_t> cornerRing(const PatchSet& patches, std::size_t patch, int corner);

// A regular patch's 16 points as the 4 x 4 B-spline grid, index [row * 4 + column]: column along
// corner 0 -> 1 (u), row along corner 0 -> 3 (v); corner 0 sits at grid (1, 1).
std::array<std::uint32_t, 16> regularGrid(const PatchSet& patches, std::size_t patch);

}  // namespace arbor
