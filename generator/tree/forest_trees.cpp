#include "forest_trees.hpp"

#include <algorithm>

#include "common/input_error.hpp"

namespace arbor {

std::vector<DetailedTree> growForestTrees(const ForestTreesOptions& options, const std::function<void(const std::string&)>& progress) {
  std::vector<DetailedTree> out;
  // (source, seed) of each distinct tree: every source once, then the growth models again with the next seeds.
  std::vector<std::pair<std::size_t, std::uint64_t>> kinds;
  for (std::uint32_t round = 0; round < std::max(1u, options.seeds); ++round) {
    for (std::size_t m = 0; m < options.sources.size(); ++m) {
      if (round == 0 || options.sources[m].model()) kinds.emplace_back(m, options.seed + round);
    }
  }
  const auto distinct = static_cast<std::uint32_t>(std::min<std::size_t>({kinds.size(), std::max(1u, options.trees), options.maxDistinct}));
  kinds.resize(distinct);
  // Each detail meshes fewer levels than the one before; all together hold at most `details` full meshes.
  const auto tooMany = [&](double quads) {
    return LimitError("the forest's " + std::to_string(distinct) + " distinct trees would hold about " + std::to_string(static_cast<long long>(quads)) +
                      " quads at their three details, more than the limit of " + std::to_string(options.maxQuads) +
                      "; give fewer species or --seeds, or lower Levels");
  };
  double estimated = 0.0;
  for (const auto& [m, seed] : kinds) estimated += options.sources[m].estimate().quads;
  if (estimated > static_cast<double>(options.maxQuads)) throw tooMany(estimated);
  std::size_t quads = 0;
  for (std::uint32_t t = 0; t < distinct; ++t) {
    const auto [m, seed] = kinds[t];
    DetailedTree tree;
    tree.label = options.labels[m] + " #" + std::to_string(seed);
    progress("growing " + tree.label + " (" + std::to_string(t + 1) + "/" + std::to_string(distinct) + ")");
    GrowthOptions growth;
    growth.seed = seed;
    const Skeleton skeleton = options.sources[m].grow(growth);
    for (int d = 0; d < options.details; ++d) {
      // The deepest d levels as fake branches over a mesh of the others (one skeleton: the same tree).
      BuildOptions build;
      build.mesh.levels = std::max(1, skeleton.levels - d);
      build.wind = true;
      tree.details.push_back(buildTree(skeleton, build));
      quads += tree.details.back().mesh.mesh.quads.size();
      if (quads > options.maxQuads) throw tooMany(static_cast<double>(quads));
    }
    tree.leaves = skeleton.leaves;
    out.push_back(std::move(tree));
  }
  return out;
}

}  // namespace arbor
