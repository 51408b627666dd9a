#include "growth_model.hpp"

#include <stdexcept>

namespace arbor {

TreeModel::TreeModel(std::unique_ptr<ModelParams> params) : params_(std::move(params)) {
  if (!params_) throw std::logic_error("TreeModel without parameters");
}

void TreeModel::setValue(std::size_t index, double value) {
  if (params_.use_count() > 1) params_ = std::shared_ptr<ModelParams>(params_->clone());  // copies stay as they were
  params_->setValue(index, value);
}

}  // namespace arbor
