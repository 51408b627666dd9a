#include "atomic_file.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>
#include <vector>

#include "descriptor.hpp"

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
    if (path.empty() || path.size() >= kPathBytes) return;  // none, or too long to register: not cleaned on a signal
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

// A file written through its descriptor, its blocks reserved ahead of the writing (fallocate): replacing a
// 44 MB OBJ by rename took 19 ms with delayed allocation (ext4 allocates and flushes the new file's blocks at a
// rename over an existing one) and 10 ms reserved, and the writes themselves were quicker too.
class FileSink : public std::streambuf {
 public:
  FileSink(const std::string& path, const std::string& shownPath) : shown_(shownPath), buffer_(kBuffer) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) fail("cannot be written");
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  ~FileSink() override {
    if (fd_ >= 0) ::close(fd_);
  }
  FileSink(const FileSink&) = delete;
  FileSink& operator=(const FileSink&) = delete;

  // The whole of the open file `source` appended by the kernel; false (nothing written) where it cannot.
  bool copyFrom(int source) {
#ifdef __linux__
    drain(false);
    for (bool first = true;; first = false) {
      const ssize_t n = ::copy_file_range(source, nullptr, fd_, nullptr, std::size_t{1} << 30, 0);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && first && (errno == EXDEV || errno == ENOSYS || errno == EOPNOTSUPP || errno == EINVAL)) return false;
      if (n < 0) fail("writing failed");
      if (n == 0) return true;
      written_ += static_cast<std::size_t>(n);
    }
#else
    (void)source;
    return false;
#endif
  }

  // The rest of the buffer out, blocks reserved past the end given back, and the file closed.
  void finish() {
    drain(false);
    if (reserved_ > written_ && ::ftruncate(fd_, static_cast<off_t>(written_)) != 0) fail("writing failed");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("writing failed");
  }

 protected:
  int_type overflow(int_type c) override {
    drain();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    const auto size = static_cast<std::size_t>(n);
    if (size <= static_cast<std::size_t>(epptr() - pptr())) {
      std::memcpy(pptr(), s, size);
      pbump(static_cast<int>(n));
      return n;
    }
    drain();  // a large block goes out as it is, not through the buffer
    if (size < buffer_.size()) return xsputn(s, n);
    put(s, size);
    return n;
  }
  int sync() override {
    drain();
    return 0;
  }

 private:
  static constexpr std::size_t kBuffer = std::size_t{64} << 10;
  static constexpr std::size_t kReserveAtLeast = std::size_t{4} << 20;

  // ahead: more is coming (not the last of a file that may fit in the buffer, which needs no reservation)
  void drain(bool ahead = true) {
    put(pbase(), static_cast<std::size_t>(pptr() - pbase()), ahead);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  void put(const char* data, std::size_t size, bool ahead = true) {
    if (ahead || reserved_ > 0) reserve(size);
    while (size > 0) {
      const ssize_t n = ::write(fd_, data, size);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail("writing failed");
      data += n;
      size -= static_cast<std::size_t>(n);
      written_ += static_cast<std::size_t>(n);
    }
  }
  // Half again what is written, at least 4 MiB, so a large file is reserved in a few steps; a file system
  // without fallocate is written as before.
  void reserve(std::size_t size) {
#ifdef __linux__
    if (!reserving_ || written_ + size <= reserved_) return;
    const std::size_t more = std::max({size, kReserveAtLeast, reserved_ / 2});
    if (::fallocate(fd_, FALLOC_FL_KEEP_SIZE, static_cast<off_t>(reserved_), static_cast<off_t>(more)) == 0) {
      reserved_ += more;
    } else {
      reserving_ = false;
    }
#else
    (void)size;
#endif
  }
  [[noreturn]] void fail(const char* what) const { throw std::runtime_error(shown_ + ": " + what + " (" + std::strerror(errno) + ")"); }

  std::string shown_;
  std::vector<char> buffer_;
  int fd_ = -1;
  std::size_t written_ = 0, reserved_ = 0;
  bool reserving_ = true;
};

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  writeFileAtomically(path, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

struct StagedFile::State {
  std::string path, temporary;
  PartialFile guard;
  bool placed = false;

  State(std::string target, std::string partial) : path(std::move(target)), temporary(std::move(partial)), guard(temporary) {}
  ~State() {
    if (!placed && !temporary.empty()) std::remove(temporary.c_str());
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;
};

StagedFile::StagedFile(std::unique_ptr<State> state) : state_(std::move(state)) {}
StagedFile::StagedFile(StagedFile&&) noexcept = default;
StagedFile& StagedFile::operator=(StagedFile&&) noexcept = default;
StagedFile::~StagedFile() = default;

void StagedFile::commit() {
  if (!state_ || state_->placed) throw std::logic_error("StagedFile::commit: nothing staged, or committed already");
  if (state_->temporary.empty()) {  // the file holds these bytes already
    state_->placed = true;
    return;
  }
  if (std::rename(state_->temporary.c_str(), state_->path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    throw std::runtime_error(state_->path + ": cannot be written (" + reason + ")");  // the temporary goes with the state
  }
  state_->placed = true;
}

StagedFile stageFile(const std::string& path, const std::function<void(std::ostream&)>& write) {
  auto state = std::make_unique<StagedFile::State>(path, path + ".partial-" + std::to_string(::getpid()));
  FileSink sink(state->temporary, path);
  std::ostream out(&sink);
  out.exceptions(std::ios::badbit);  // a failed write throws from the sink: let it through, not a flag
  write(out);
  sink.finish();
  return StagedFile(std::move(state));
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) { stageFile(path, write).commit(); }

namespace {

// Whether the regular file `to` holds the bytes of the open file `source` (read back to its start).
bool holdsSameBytes(int source, const std::string& to) {
  const Descriptor closeTarget{::open(to.c_str(), O_RDONLY | O_CLOEXEC)};
  const int target = closeTarget.fd;
  struct stat a {}, b {};
  if (target < 0 || ::fstat(source, &a) != 0 || ::fstat(target, &b) != 0 || !S_ISREG(b.st_mode) || a.st_size != b.st_size) return false;
  std::vector<char> x(std::size_t{1} << 16), y(x.size());
  bool same = true;
  for (;;) {
    const ssize_t n = ::read(source, x.data(), x.size());
    if (n <= 0) {
      same = n == 0 && ::read(target, y.data(), 1) == 0;
      break;
    }
    if (::read(target, y.data(), static_cast<std::size_t>(n)) != n || std::memcmp(x.data(), y.data(), static_cast<std::size_t>(n)) != 0) {
      same = false;
      break;
    }
  }
  return ::lseek(source, 0, SEEK_SET) == 0 && same;
}

}  // namespace

StagedFile stageCopy(const std::string& from, const std::string& to) {
  const int source = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (source < 0) throw std::runtime_error(from + ": cannot be opened for reading");
  const Descriptor closeSource{source};
  // Already there (an export again into the same folder): left alone, its time kept, so tools watching it do not
  // reload it, and nothing is copied or renamed.
  if (holdsSameBytes(source, to)) return StagedFile(std::make_unique<StagedFile::State>(to, std::string()));
  return stageFile(to, [&](std::ostream& out) {
    auto* sink = dynamic_cast<FileSink*>(out.rdbuf());
    if (sink && sink->copyFrom(source)) return;
    // Another kind of stream, or a file system the kernel cannot copy within: through the process.
    out << readFile(from);
  });
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
