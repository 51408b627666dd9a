#pragma once
// The skeleton as JSON (format "arbor-skeleton/1", documented in docs/skeleton-format.md).
#include <string>

#include "skeleton.hpp"

namespace arbor {

std::string writeSkeletonJson(const Skeleton& skeleton);

}  // namespace arbor
