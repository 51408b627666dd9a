#pragma once
// The skeleton as JSON (format "arbor-skeleton/1", documented in docs/skeleton-format.md).
#include <ostream>
#include <string>

#include "skeleton.hpp"

namespace arbor {

std::string writeSkeletonJson(const Skeleton& skeleton);
void writeSkeletonJson(const Skeleton& skeleton, std::ostream& out);  // streamed in chunks of about 1 MiB

}  // namespace arbor
