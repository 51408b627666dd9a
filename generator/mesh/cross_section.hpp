#pragma once
// Four-vertex cross sections (Nystad 4.3) and the frames carried along a branch so that nothing twists.
#include <array>

#include "growth/math.hpp"

namespace arbor {

// Orthonormal frame of a cross section: T along the branch, N and B across it (N x B = T).
struct RingFrame {
  Vec3 T{0, 0, 1}, N{1, 0, 0}, B{0, 1, 0};
};

// The frame moved to a new direction by the smallest rotation (parallel transport: no twist).
// v normalised, or `fallback` (unit) where v is too short to have a direction (opposite directions summed).
Vec3 directionOr(const Vec3& v, const Vec3& fallback);

RingFrame transportFrame(const RingFrame& frame, const Vec3& newT);

// A frame for direction T whose N is as close as possible to `hint`.
RingFrame frameFromHint(const Vec3& T, const Vec3& hint);

// Corner offsets of a cross section of radius r: on +N, +B, -N, -B (counter-clockwise about T).
// Corners sit on the axes so that the flip coordinate is 0 at the front and back and +-1 at the sides.
std::array<Vec3, 4> ringOffsets(const RingFrame& frame, double r);

// Texture coordinates of ring corner k: u mirrored 0..1 front to back, w the flip coordinate.
constexpr std::array<double, 4> kRingU{0.0, 0.5, 1.0, 0.5};
constexpr std::array<double, 4> kRingFlip{0.0, 1.0, 0.0, -1.0};

}  // namespace arbor
