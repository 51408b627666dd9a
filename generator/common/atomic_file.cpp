#include "atomic_file.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace arbor {

namespace {

// Temporary files being written, removed by the signal handler if the process is interrupted: fixed slots of
// fixed size, because a handler may only touch what is already there (unlink and raise are async-signal-safe).
constexpr std::size_t kSlots = 16, kPathBytes = 4096;
std::array<std::array<char, kPathBytes>, kSlots> partialPaths{};
enum : int { kFree = 0, kClaimed = 1, kReady = 2 };
std::array<std::atomic<int>, kSlots> partialState{};
std::once_flag handlersInstalled;

extern "C" void removePartialsAndDie(int signal) {
  for (std::size_t i = 0; i < kSlots; ++i) {
    if (partialState[i].load() == kReady) ::unlink(partialPaths[i].data());
  }
  std::signal(signal, SIG_DFL);  // then die of the same signal, as the caller expects
  std::raise(signal);
}

void installHandlers() {
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    struct sigaction current {};
    sigaction(s, nullptr, &current);
    if (current.sa_handler != SIG_DFL) continue;  // someone else's handler (or an ignored signal) stays
    struct sigaction action {};
    action.sa_handler = removePartialsAndDie;
    sigemptyset(&action.sa_mask);
    sigaction(s, &action, nullptr);
  }
}

// Holds a slot while the temporary file exists.
class PartialFile {
 public:
  explicit PartialFile(const std::string& path) {
    std::call_once(handlersInstalled, installHandlers);
    if (path.size() >= kPathBytes) return;  // too long to register: still written, only not cleaned on a signal
    for (std::size_t i = 0; i < kSlots && slot_ < 0; ++i) {
      int expected = kFree;
      if (!partialState[i].compare_exchange_strong(expected, kClaimed)) continue;
      std::memcpy(partialPaths[i].data(), path.c_str(), path.size() + 1);
      partialState[i].store(kReady);
      slot_ = static_cast<int>(i);
    }
  }
  ~PartialFile() {
    if (slot_ >= 0) partialState[static_cast<std::size_t>(slot_)].store(kFree);
  }
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  writeFileAtomically(path, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".partial-" + std::to_string(::getpid());
  const PartialFile guard(temporary);
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot be written (" + std::strerror(errno) + ")");
    write(out);
    out.flush();
    if (!out) throw std::runtime_error(path + ": writing failed (" + std::strerror(errno) + ")");
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot be written (" + reason + ")");
  }
}

namespace detail {
void registerPartialForTest(const std::string& path) { static PartialFile keep(path); }
}  // namespace detail

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(path + ": cannot be opened for reading");
  // One read of the whole file where its size is known (a pipe's is not: then chunk by chunk).
  const std::streamoff size = in.tellg();
  if (size > 0) {
    std::string content(static_cast<std::size_t>(size), '\0');
    in.seekg(0);
    if (in.read(content.data(), size) && in.peek() == std::char_traits<char>::eof()) return content;
    in.clear();
  }
  in.seekg(0);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace arbor
