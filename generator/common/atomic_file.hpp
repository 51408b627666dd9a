#pragma once
// Output files appear whole or not at all: written beside the target, then renamed over it.
#include <string>

namespace arbor {

// Throws std::runtime_error naming the path when the file cannot be written.
void writeFileAtomically(const std::string& path, const std::string& content);

std::string readFile(const std::string& path);  // throws std::runtime_error naming the path

}  // namespace arbor
