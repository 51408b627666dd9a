#pragma once
// L-systems behind the growth-model interface: a .lsys grammar as a TreeModel (docs/lsystem-format.md).
#include <cstdint>
#include <string>

#include "growth/graph/branch_graph.hpp"
#include "growth/growth_model.hpp"
#include "lsystem.hpp"

namespace arbor {

inline constexpr const char* kLsystemModel = "l-system";

// Reads a grammar (InputError with line and column, exit 2). Refuses options.naturalAngles: an L-system has
// no angle rules.
TreeModel readLsystemModel(const std::string& text, const std::string& file, const ModelReadOptions& options = {});

// The grammar behind a model with its edits; nullptr when another model grew it.
const lsys::Lsystem* lsystemOf(const TreeModel& model);

// The grammar derived (seed: the file's + seed - 1) and interpreted as grow() does, before the skeleton: the
// branch graph scaled by `size:`, for tools and tests. A GenerationError past maxInternodes drawn (F modules);
// moduleCap (> 0, TreeLimits::modules) lowers the grammar's own module limit for the derivation.
BranchGraph lsystemGraph(const lsys::Lsystem& system, std::uint64_t seed, std::size_t maxInternodes = SIZE_MAX, std::size_t moduleCap = 0);

}  // namespace arbor
