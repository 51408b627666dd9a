#include "grow_forest.hpp"

#include <cstdio>

#include "render/renderer.hpp"
#include "tree/forest_trees.hpp"

namespace arbor::cli {

std::unique_ptr<render::Forest> growForest(const vk::VulkanContext& context, const ForestRequest& request, const std::string& who) {
  ForestTreesOptions options;
  options.labels = request.labels;
  options.sources = request.sources;
  options.trees = request.trees;
  options.seeds = request.seeds;
  options.seed = request.seed;
  options.details = static_cast<int>(render::kDetailLevels);
  options.maxDistinct = render::TreeRenderer::kMaxTrees / render::kDetailLevels;
  const std::vector<DetailedTree> trees = growForestTrees(options, [&](const std::string& line) {
    std::fprintf(stderr, "%s: %s\n", who.c_str(), line.c_str());
    std::fflush(stderr);
  });
  return std::make_unique<render::Forest>(context, trees, request.trees, request.seed);
}

}  // namespace arbor::cli
