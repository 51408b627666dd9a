#include "forest_trees.hpp"

#include <algorithm>

#include "common/input_error.hpp"

namespace arbor {

std::vector<DetailedTree> growForestTrees(const ForestTreesOptions& options, const std::function<void(const std::string&)>& progress) {
  std::vector<DetailedTree> out;
  if (options.models.empty()) return out;
  const auto models = static_cast<std::uint32_t>(options.models.size());
  const std::uint32_t distinct = std::min({models * std::max(1u, options.seeds), std::max(1u, options.trees), options.maxDistinct});
  // Each detail meshes fewer levels than the one before; all together hold at most `details` full meshes.
  const auto tooMany = [&](double quads) {
    return LimitError("the forest's " + std::to_string(distinct) + " distinct trees would hold about " + std::to_string(static_cast<long long>(quads)) +
                      " quads at their three details, more than the limit of " + std::to_string(options.maxQuads) +
                      "; give fewer species or --seeds, or lower Levels");
  };
  double estimated = 0.0;
  for (std::uint32_t t = 0; t < distinct; ++t) estimated += options.models[t % models].estimate().quads;
  if (estimated > static_cast<double>(options.maxQuads)) throw tooMany(estimated);
  std::size_t quads = 0;
  for (std::uint32_t t = 0; t < distinct; ++t) {
    const std::size_t m = t % models;
    const std::uint64_t seed = options.seed + t / models;
    DetailedTree tree;
    tree.label = options.labels[m] + " #" + std::to_string(seed);
    progress("growing " + tree.label + " (" + std::to_string(t + 1) + "/" + std::to_string(distinct) + ")");
    GrowthOptions growth;
    growth.seed = seed;
    const Skeleton skeleton = options.models[m].grow(growth);
    for (int d = 0; d < options.details; ++d) {
      // The deepest d levels as fake branches over a mesh of the others (one skeleton: the same tree).
      BuildOptions build;
      build.mesh.levels = std::max(1, skeleton.levels - d);
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
