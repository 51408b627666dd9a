#pragma once
// A plane through one edge of a joint that separates what leaves the joint from the faces around it: a pair of quads
// on opposite sides meets at most along that edge, which proves "no crossing" for the cheap price of a few dot products
// (the exact quad tests on a port's neighbours were a third of the tupelo file's meshing).
#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "growth/math.hpp"

namespace arbor {

struct EdgePlane {
  Vec3 normal{0.0};  // unit, towards the points kept strictly in front
  Vec3 origin{0.0};  // the edge's first corner
  std::array<std::uint32_t, 2> edge{};  // the edge's vertex indices: corners a tested face may have on the plane
  double margin = 0.0;                  // how far points must be in front or behind

  double height(const Vec3& x) const;
  // Whether every corner of a quad (positions p, vertex indices ids) is more than margin behind, but for the edge's own.
  bool behind(const std::array<Vec3, 4>& p, const std::array<std::uint32_t, 4>& ids) const;
};

// The plane through edge p0-p1 (vertex indices ids) tilted from `up` towards `inward` (both need only point the right
// way) so that every point of `front` lies more than margin in front of it and every point of `back` more than margin
// behind; the tilt is the middle of those allowed, or well towards upright when nothing bounds it. None if no tilt does.
std::optional<EdgePlane> edgePlane(const Vec3& p0, const Vec3& p1, const std::array<std::uint32_t, 2>& ids, const Vec3& up,
                                   const Vec3& inward, std::span<const Vec3> front, std::span<const Vec3> back, double margin);

}  // namespace arbor
