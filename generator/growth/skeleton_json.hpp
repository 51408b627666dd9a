#pragma once
// The skeleton as JSON (format "arbor-skeleton/1", documented in docs/skeleton-format.md).
#include <ostream>
#include <string>

#include "skeleton.hpp"

namespace arbor {

std::string writeSkeletonJson(const Skeleton& skeleton);
void writeSkeletonJson(const Skeleton& skeleton, std::ostream& out);  // streamed in chunks of about 1 MiB

// Reads what writeSkeletonJson writes (writing it again gives the same bytes); every refusal is an
// InputError naming `file`, the field and what is allowed. Frames get the roll-free rotation of their
// direction (the file has no roll) and raw joints are not in the file.
Skeleton readSkeletonJson(const std::string& text, const std::string& file);

}  // namespace arbor
