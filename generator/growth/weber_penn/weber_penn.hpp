#pragma once
// Weber-Penn growth (1995) with Nystad's natural rules, breadth-first so that one more level keeps the
// lower levels of the same seed (Nystad 5.2.2).
#include "raw_tree.hpp"
#include "growth/growth_model.hpp"
#include "growth/skeleton.hpp"
#include "tree_estimate.hpp"
#include "species.hpp"

namespace arbor {

// Stage 1: stems, segments, curvature, splits, children, pruning, leaves; undeflected.
RawTree growRawTree(const SpeciesParams& params, const GrowthOptions& options);

// Stage 2: nodes with intermediate nodes, natural-rule radii, primary deflection, object space.
Skeleton buildSkeleton(const RawTree& raw, const SpeciesParams& params, const GrowthOptions& options);

// Both stages.
Skeleton generateSkeleton(const SpeciesParams& params, const GrowthOptions& options);

}  // namespace arbor
