#include "growth_model.hpp"

#include <cmath>
#include <stdexcept>

#include "common/text_util.hpp"

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
      if (!(std::abs(node.world.position[k]) <= kMaxCoordinate)) {
        throw GenerationError(name() + ": a node lies at " + formatNumber(node.world.position[k]) + " m on axis " + std::to_string(k) +
                              "; allowed: within " + formatNumber(kMaxCoordinate) +
                              " m of the origin on each axis (the mesh's float positions resolve 8 mm there)");
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
