#include "connection.hpp"

#include <algorithm>
#include <numeric>

namespace arbor {

namespace {

// How well side k suits a child: its direction across the slab against the side's normal.
double sideScore(const Vec3& normal, const Vec3& axis, const Vec3& direction) {
  Vec3 across = direction - axis * glm::dot(direction, axis);
  const double len = glm::length(across);
  across = len > 0.2 ? across / len : direction;  // nearly along the axis: the raw direction decides
  return glm::dot(normal, across);
}

// Two sides as good to within this (about 0.004 degrees either side of their corner): a planar plant's children
// heading straight for a corner, all on one side's necks stacked one over the next (ABOP fig. 1.24b: limb 24's
// neck swung 0.25 m out of the plant's plane across limb 12's, 8 mesh-made pairs; taken in turn, none).
constexpr double kCornerTie = 1e-4;

// The side a child heading for the corner between free side `best` and a neighbour as good takes: the one the
// parent's last child at that corner did not.
int turnAtCorner(const std::array<Vec3, 4>& sideNormals, const Vec3& axis, const Vec3& direction, const std::array<bool, 4>& sideAllowed,
                 const PortAssignment& taken, int best, double bestScore, CornerTurns& turns) {
  for (const int k : {(best + 1) % 4, (best + 3) % 4}) {
    const auto side = static_cast<std::size_t>(k);
    if (!sideAllowed[side] || !taken.sides[side].empty()) continue;
    if (bestScore - sideScore(sideNormals[side], axis, direction) > kCornerTie) continue;
    const auto corner = static_cast<std::size_t>(k == (best + 1) % 4 ? k : best);
    const int chosen = turns[corner] == best ? k : best;
    turns[corner] = chosen;
    return chosen;
  }
  return best;
}

}  // namespace

PortAssignment assignPorts(const std::array<Vec3, 4>& sideNormals, const Vec3& axis,
                           const std::vector<PortRequest>& requests, const std::array<bool, 4>& sideAllowed,
                           bool topAvailable, CornerTurns* turns) {
  PortAssignment result;
  std::vector<int> order(requests.size());
  std::iota(order.begin(), order.end(), 0);
  // Larger children choose first; ties keep skeleton order so the result is deterministic.
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return requests[static_cast<std::size_t>(a)].radius > requests[static_cast<std::size_t>(b)].radius; });

  if (topAvailable && !requests.empty()) {
    int best = 0;
    for (std::size_t i = 1; i < requests.size(); ++i) {
      if (glm::dot(requests[i].direction, axis) > glm::dot(requests[static_cast<std::size_t>(best)].direction, axis)) best = static_cast<int>(i);
    }
    result.top = best;
  }

  for (int r : order) {
    if (r == result.top) continue;
    const Vec3& d = requests[static_cast<std::size_t>(r)].direction;
    int bestFree = -1, bestAllowed = -1, bestAny = 0;
    double scoreFree = -2, scoreAllowed = -2, scoreAny = -2;
    for (int k = 0; k < 4; ++k) {
      const double s = sideScore(sideNormals[static_cast<std::size_t>(k)], axis, d);
      if (s > scoreAny) { scoreAny = s; bestAny = k; }
      if (!sideAllowed[static_cast<std::size_t>(k)]) continue;
      if (s > scoreAllowed) { scoreAllowed = s; bestAllowed = k; }
      // Any free side beats a sub-box: the child's tube leaves straight out, then turns round its parent.
      if (result.sides[static_cast<std::size_t>(k)].empty() && s > scoreFree) { scoreFree = s; bestFree = k; }
    }
    int side = bestFree >= 0 ? bestFree : (bestAllowed >= 0 ? bestAllowed : bestAny);
    if (turns && bestFree >= 0) side = turnAtCorner(sideNormals, axis, d, sideAllowed, result, bestFree, scoreFree, *turns);
    result.sides[static_cast<std::size_t>(side)].push_back(r);
  }
  return result;
}

}  // namespace arbor
