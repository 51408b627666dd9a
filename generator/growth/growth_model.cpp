#include "growth_model.hpp"

#include <stdexcept>

namespace arbor {

TreeModel::TreeModel(std::unique_ptr<ModelParams> params) : params_(std::move(params)) {
  if (!params_) throw std::logic_error("TreeModel without parameters");
}

Skeleton TreeModel::grow(const GrowthOptions& options) const {
  Skeleton skeleton = params_->grow(options);
  // Every model's files are checked where they name positions; growth can still carry a tree out of reach (a space
  // colonization fuzzed with its trunk 5.6e101 m out meshed into NaN vertices).
  for (const SkeletonNode& node : skeleton.nodes) {
    for (int k = 0; k < 3; ++k) {
      if (const std::string why = outOfReach(node.world.position[k]); !why.empty()) {
        throw GenerationError(name() + ": a node on axis " + std::to_string(k) + " at " + why);
      }
    }
  }
  return skeleton;
}

void TreeModel::setValue(std::size_t index, double value) {
  if (params_.use_count() > 1) params_ = std::shared_ptr<ModelParams>(params_->clone());  // copies stay as they were
  params_->setValue(index, value);
}

}  // namespace arbor
