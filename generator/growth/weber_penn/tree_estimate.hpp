#pragma once
// How large a Weber-Penn tree will be, from its parameters alone and in microseconds: the expected stems,
// nodes, leaves and quads per level. The viewer shows it beside its sliders; growth refuses a tree whose
// estimate is far past the limits before any memory is spent on it, naming the level and parameters to lower.
#include "growth/tree_limits.hpp"
#include "species.hpp"

namespace arbor {

// `levels` 0: the species' own Levels.
TreeEstimate estimateTree(const SpeciesParams& params, int levels = 0);

// Quads the mesher makes per skeleton node, on average over the presets and Arbaro's species (3.5 to 5.2).
constexpr double kQuadsPerNode = 5.0;

}  // namespace arbor
