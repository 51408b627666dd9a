#pragma once
// Invariants of a skeleton that tests and `arbor generate --check` assert.
#include <string>
#include <vector>

#include "skeleton.hpp"

namespace arbor {

struct SkeletonStats {
  std::size_t nodes = 0, stems = 0, leaves = 0, branchPoints = 0;
  std::size_t stubs = 0;        // stems too short, stubby or thin for a tube (SkeletonStem::stub)
  std::vector<std::size_t> stemsPerLevel;
  double height = 0;            // highest node above the ground
  double lowest = 0;            // lowest node (negative: below the ground)
  double crownRadius = 0;       // largest horizontal distance of a node from the trunk axis
};

SkeletonStats skeletonStats(const Skeleton& skeleton);

// Largest relative violation of r^E = sum of outgoing start radii^E over all branch points
// (and of continuity r = start radius along unbranched edges).
double worstConservationError(const Skeleton& skeleton);

// Human-readable problems: parents after children, non-finite values, negative radii. Empty when sound.
std::vector<std::string> structuralProblems(const Skeleton& skeleton);

}  // namespace arbor
