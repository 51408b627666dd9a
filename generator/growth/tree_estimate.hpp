#pragma once
// How large a Weber-Penn tree will be, from its parameters alone and in microseconds: the expected stems,
// nodes, leaves and quads per level. The viewer shows it beside its sliders; growth refuses a tree whose
// estimate is far past the limits before any memory is spent on it, naming the level and parameters to lower.
#include <cstddef>
#include <string>
#include <vector>

#include "species/species.hpp"

namespace arbor {

// The limits every tree is held to (memory and time stay within about 2 GB and 10 s on two cores).
struct TreeLimits {
  std::size_t nodes = 1'500'000;   // skeleton nodes (counted as grown: every joint, stem base and branch point with its two neighbours)
  std::size_t leaves = 2'000'000;
  std::size_t quads = 2'500'000;   // mesh quads (also after subdivision for export)
};

struct TreeEstimate {
  std::vector<double> stemsPerLevel;
  std::vector<double> nodesPerLevel;
  double stems = 0, nodes = 0, leaves = 0;
  double quads = 0;  // of the whole mesh, at the mesher's usual cross-section density

  // The first limit the estimate passes, as a sentence naming the level and parameters that drive it; "" if none.
  std::string excess(const TreeLimits& limits, double margin = 1.0) const;
  std::string drivers;  // "level 2: 4.1e+06 stems (Branches 1000, SegSplits 2 over CurveRes 20)"
};

// `levels` 0: the species' own Levels.
TreeEstimate estimateTree(const SpeciesParams& params, int levels = 0);

// Quads the mesher makes per skeleton node, on average over the presets and Arbaro's species (3.5 to 5.2).
constexpr double kQuadsPerNode = 5.0;

}  // namespace arbor
