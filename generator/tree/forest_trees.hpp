#pragma once
// The distinct trees of a forest (source x seed), each grown once and built at every level of detail, for the
// walkthrough and the benchmarks; the renderer only uploads and places them.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "build_tree.hpp"
#include "tree_source.hpp"

namespace arbor {

struct ForestTreesOptions {
  std::vector<std::string> labels;  // one per source, shown in progress and the overlay
  std::vector<TreeSource> sources;
  std::uint32_t trees = 1;          // instances the forest will hold
  std::uint32_t seeds = 3;          // distinct seeds per growth model (a skeleton given whole is one tree)
  std::uint64_t seed = 1;           // first seed
  std::uint32_t maxDistinct = 64;   // distinct trees the renderer can hold
  int details = 3;                  // levels of detail per tree (buildDetails)
  // All details of all distinct trees together: GPU memory (host memory on lavapipe) stays bounded.
  std::size_t maxQuads = 3 * TreeLimits{}.quads;
};

struct DetailedTree {
  std::string label;               // "Black Tupelo #2"
  std::vector<Leaf> leaves;
  std::vector<TreeGeometry> details;
};

// Grows and builds up to min(trees, maxDistinct) distinct trees: each source at the first seed, then the models
// at the next seeds in turn (progress: one line per tree). Throws LimitError, before growing where the
// estimates show it, when they would pass maxQuads.
std::vector<DetailedTree> growForestTrees(const ForestTreesOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace arbor
