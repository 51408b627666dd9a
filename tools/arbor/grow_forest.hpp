#pragma once
// A forest for `view` and `bench tess`: the sources' distinct trees grown and built (tree/forest_trees), then
// uploaded and placed by the renderer.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tree/tree_source.hpp"
#include "render/forest.hpp"

namespace arbor::cli {

struct ForestRequest {
  std::vector<std::string> labels;  // one per source
  std::vector<TreeSource> sources;
  std::uint32_t trees = 1;          // instances
  std::uint32_t seeds = 3;          // distinct seeds per growth model
  std::uint64_t seed = 1;
};

// Progress goes to stderr, one line per tree, prefixed by `who` ("arbor view").
std::unique_ptr<render::Forest> growForest(const vk::VulkanContext& context, const ForestRequest& request, const std::string& who);

}  // namespace arbor::cli
