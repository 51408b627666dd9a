#pragma once
// The two ways input is refused (callers exit with code 2): bad input naming file, field and what is
// allowed, and input that is valid but would grow past a limit (memory or time) before it is built.
#include <stdexcept>
#include <string>

namespace arbor {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string field, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

// A tree, mesh or picture that would pass one of the project's size limits; says which parameters drive it.
class LimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace arbor
