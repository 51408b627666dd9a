#pragma once
// Branch connection (Nystad app. D): a connection slab is the band of four quads between two cross
// sections of the parent; the primary continues through its top, the other children are sorted to its
// four sides by direction, and a side wanted by several children becomes a smaller box of its own.
#include <array>
#include <vector>

#include "growth/math.hpp"

namespace arbor {

struct PortRequest {
  Vec3 direction;   // unit direction in which the child leaves the branch point
  double radius;    // child start radius (larger children choose first)
};

struct PortAssignment {
  int top = -1;                               // request taking the top (splits and sub-boxes only)
  std::array<std::vector<int>, 4> sides;      // requests on each side; two or more make a sub-box
};

// Per corner k of a parent's cross sections (between sides k - 1 and k), the side the parent's last child heading
// straight for that corner took (-1: none yet).
using CornerTurns = std::array<int, 4>;
constexpr CornerTurns kNoCornerTurns{-1, -1, -1, -1};

// sideNormals: outward normals of the four sides; axis: the slab's direction; sideAllowed: sides whose
// corners are not yet shared by two ports (so corner valences stay <= 6 and every patch <= 32 points).
// turns (optional): a child heading for a corner between two free sides takes the one the parent's last child
// there did not, and is recorded there.
PortAssignment assignPorts(const std::array<Vec3, 4>& sideNormals, const Vec3& axis,
                           const std::vector<PortRequest>& requests, const std::array<bool, 4>& sideAllowed,
                           bool topAvailable, CornerTurns* turns = nullptr);

}  // namespace arbor
