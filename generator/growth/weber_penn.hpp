#pragma once
// Weber-Penn growth (1995) with Nystad's natural rules, breadth-first so that one more level keeps the
// lower levels of the same seed (Nystad 5.2.2).
#include <cstdint>
#include <stdexcept>

#include "common/input_error.hpp"
#include "raw_tree.hpp"
#include "skeleton.hpp"
#include "tree_estimate.hpp"
#include "species/species.hpp"

namespace arbor {

struct GrowthOptions {
  std::uint64_t seed = 1;
  int levels = 0;                       // 0: the species' Levels; otherwise 1..8 (extra impostor levels)
  TreeLimits limits;                    // refuse trees beyond these instead of exhausting memory or time
};

// A tree that cannot be grown as asked (too large); callers exit with code 2.
class GenerationError : public LimitError {
 public:
  using LimitError::LimitError;
};

// Stage 1: stems, segments, curvature, splits, children, pruning, leaves; undeflected.
RawTree growRawTree(const SpeciesParams& params, const GrowthOptions& options);

// Stage 2: nodes with intermediate nodes, natural-rule radii, primary deflection, object space.
Skeleton buildSkeleton(const RawTree& raw, const SpeciesParams& params, const GrowthOptions& options);

// Both stages.
Skeleton generateSkeleton(const SpeciesParams& params, const GrowthOptions& options);

}  // namespace arbor
