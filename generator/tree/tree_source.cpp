#include "tree_source.hpp"

#include <filesystem>

#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/graph/graph_json.hpp"
#include "growth/growth_models.hpp"
#include "growth/skeleton_json.hpp"

namespace arbor {

TreeSource::TreeSource(TreeModel model) : model_(std::move(model)) {}

TreeSource::TreeSource(std::string name, Skeleton skeleton)
    : skeleton_(std::make_shared<const Skeleton>(std::move(skeleton))), name_(std::move(name)) {}

std::string TreeSource::name() const { return model_ ? model_->name() : name_; }

int TreeSource::levels() const { return model_ ? model_->levels() : skeleton_->levels; }

Skeleton TreeSource::grow(const GrowthOptions& options) const {
  if (model_) return model_->grow(options);
  if (skeleton_->nodes.size() > options.limits.nodes || skeleton_->leaves.size() > options.limits.leaves) {
    throw LimitError(name_ + ": " + std::to_string(skeleton_->nodes.size()) + " nodes and " + std::to_string(skeleton_->leaves.size()) +
                     " leaves, more than the limits of " + std::to_string(options.limits.nodes) + " and " + std::to_string(options.limits.leaves));
  }
  return *skeleton_;
}

TreeEstimate TreeSource::estimate(int levels) const {
  if (model_) return model_->estimate(levels);
  TreeEstimate e;
  e.stems = static_cast<double>(skeleton_->stems.size());
  e.nodes = static_cast<double>(skeleton_->nodes.size());
  e.leaves = static_cast<double>(skeleton_->leaves.size());
  e.quads = 5.0 * e.nodes;  // the mesher's quads per node, on average (3.5 to 5.2 on the presets)
  e.drivers = "the file's " + std::to_string(skeleton_->stems.size()) + " stems";
  e.lowerNodes = e.lowerLeaves = "the skeleton is given whole: make it smaller where it was made";
  return e;
}

TreeSource loadTreeSource(const std::string& path, const ModelReadOptions& options) {
  if (!endsWith(path, ".json")) return TreeSource(loadModelFile(path, options));
  const std::string text = readInputFile(path, kMaxTreeFileBytes);
  const std::string format = topLevelJsonString(text, "format");
  if (format == "arbor-skeleton/1" || format == "arbor-graph/1") {
    if (options.naturalAngles) throw InputError(path, "--angles", "a " + format + " file is grown already; natural angles apply to models");
    GraphOptions graph;
    graph.species = std::filesystem::path(path).stem().string();  // a graph names no species: its file does
    Skeleton skeleton = format == "arbor-skeleton/1" ? readSkeletonJson(text, path) : graphToSkeleton(readBranchGraphJson(text, path), graph);
    std::string name = skeleton.species.empty() ? graph.species : skeleton.species;
    return TreeSource(std::move(name), std::move(skeleton));
  }
  if (text.size() > kMaxModelFileBytes) {
    throw InputError(path, "(file)", "is " + std::to_string(text.size()) + " bytes; files of this kind are at most 1 MiB (skeleton and graph "
                                         "files, which name their \"format\", may be larger)");
  }
  return TreeSource(readModelFile(text, path, options));
}

}  // namespace arbor
