#pragma once
// Output files appear whole or not at all: written beside the target, then renamed over it. An interrupt
// (SIGINT, SIGTERM, SIGHUP, SIGQUIT) while one is written removes the temporary file before the process ends.
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace arbor {

// Throws std::runtime_error naming the path when the file cannot be written.
void writeFileAtomically(const std::string& path, const std::string& content);
// The same, streaming: `write` puts the content into the temporary file (large outputs never sit in memory whole).
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

std::string readFile(const std::string& path);  // throws std::runtime_error naming the path

// A file written whole under a temporary name beside its path and put in place only by commit(): files made on
// another thread, while the caller still works, appear in the order the caller commits them (an OBJ's textures
// before the OBJ). Never committed (the work failed), the temporary file is removed.
class StagedFile {
 public:
  StagedFile(StagedFile&&) noexcept;
  StagedFile& operator=(StagedFile&&) noexcept;
  ~StagedFile();
  void commit();  // throws std::runtime_error naming the path

  struct State;

 private:
  explicit StagedFile(std::unique_ptr<State> state);
  friend StagedFile stageFile(const std::string& path, const std::function<void(std::ostream&)>& write);
  friend StagedFile stageCopy(const std::string& from, const std::string& to);
  std::unique_ptr<State> state_;
};

// writeFileAtomically, less the final rename.
StagedFile stageFile(const std::string& path, const std::function<void(std::ostream&)>& write);
// `from` copied to `to`'s temporary name, the bytes moved by the kernel (copy_file_range) where it can: an OBJ's
// textures never pass through the process. Where `to` holds `from`'s bytes already, nothing is copied and commit()
// leaves it as it is (its modification time too). Throws std::runtime_error naming the path.
StagedFile stageCopy(const std::string& from, const std::string& to);

namespace detail {
// Registers `path` as a file being written, for the test that interrupts a process (never released).
void registerPartialForTest(const std::string& path);
}  // namespace detail

}  // namespace arbor
