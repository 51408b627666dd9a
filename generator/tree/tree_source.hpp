#pragma once
// What a tree is built from: a growth model with its parameters (grown anew for each seed), or a skeleton
// given whole: an arbor-skeleton/1 file, or an arbor-graph/1 branch graph converted to one (the same tree for
// any seed). Commands, the viewer and the forest take either without knowing which.
#include <memory>
#include <optional>
#include <string>

#include "growth/growth_model.hpp"
#include "growth/skeleton.hpp"

namespace arbor {

class TreeSource {
 public:
  explicit TreeSource(TreeModel model);
  TreeSource(std::string name, Skeleton skeleton);

  std::string name() const;
  int levels() const;
  // The parameters to edit and regrow; nullptr for a skeleton given whole.
  const TreeModel* model() const { return model_ ? &*model_ : nullptr; }
  TreeModel* model() { return model_ ? &*model_ : nullptr; }
  // A model grows for options.seed; a given skeleton is itself whatever the options (its levels are its own).
  Skeleton grow(const GrowthOptions& options) const;
  // A model's estimate from its parameters; a given skeleton's own counts.
  TreeEstimate estimate(int levels = 0) const;

 private:
  std::optional<TreeModel> model_;
  std::shared_ptr<const Skeleton> skeleton_;
  std::string name_;
};

// Skeleton and graph files can be large (a Weber-Penn tupelo's skeleton is 20 MB); the node limit still holds.
constexpr std::size_t kMaxTreeFileBytes = 256u * 1024 * 1024;

// A file by what it holds: a .json whose "format" is "arbor-skeleton/1" or "arbor-graph/1" (a branch graph:
// converted with the default GraphOptions), otherwise a model file (.json of any growth model, .xml Arbaro).
// Throws InputError naming the file and field.
TreeSource loadTreeSource(const std::string& path, const ModelReadOptions& options = {});

}  // namespace arbor
