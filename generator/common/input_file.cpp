#include "input_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "input_error.hpp"
#include "descriptor.hpp"

namespace arbor {

InputError::InputError(std::string file, std::string field, const std::string& message)
    : std::runtime_error(file + ": field '" + field + "': " + message), file_(std::move(file)), field_(std::move(field)) {}

namespace {

std::string sizeText(std::size_t bytes) {
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

std::string readInputFile(const std::string& path, std::size_t maxBytes, const std::string& field) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (d.fd < 0) throw InputError(path, field, std::string("cannot be opened for reading: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) throw InputError(path, field, std::string("cannot be read: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(path, field, std::string("is ") + kindOf(st.st_mode) + "; give a regular file");
  if (static_cast<std::size_t>(st.st_size) > maxBytes) {
    throw InputError(path, field, "is " + sizeText(static_cast<std::size_t>(st.st_size)) + "; files of this kind are at most " +
                                      sizeText(maxBytes));
  }
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(d.fd, text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path, field, std::string("cannot be read: ") + std::strerror(errno));
    if (n == 0) break;  // shrank while read: keep what is there
    got += static_cast<std::size_t>(n);
  }
  text.resize(got);
  char extra = 0;
  if (::read(d.fd, &extra, 1) > 0) throw InputError(path, field, "grew while it was read; files of this kind are at most " + sizeText(maxBytes));
  return text;
}

bool inputExists(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return true;
  if (errno == ELOOP) throw InputError(path, "(file)", "cannot be read: too many levels of symbolic links");
  return false;
}

std::string lineAndColumn(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

namespace {

// Length of the well-formed UTF-8 sequence at `i`, or 0.
std::size_t utf8Sequence(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // bounds of the second byte (RFC 3629's table)
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c == 0xE0) { n = 3; lo = 0xA0; }
  else if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) n = 3;
  else if (c == 0xED) { n = 3; hi = 0x9F; }
  else if (c == 0xF0) { n = 4; lo = 0x90; }
  else if (c >= 0xF1 && c <= 0xF3) n = 4;
  else if (c == 0xF4) { n = 4; hi = 0x8F; }
  else return 0;
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return n;
}

}  // namespace

bool isValidUtf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8Sequence(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

void requireText(const std::string& text, const std::string& file, const std::string& field) {
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '\0') throw InputError(file, field, "a NUL byte at " + lineAndColumn(text, i) + "; give a text file");
    const std::size_t n = utf8Sequence(text, i);
    if (n == 0) throw InputError(file, field, "bytes that are not UTF-8 at " + lineAndColumn(text, i) + "; give UTF-8 text");
    i += n;
  }
}

}  // namespace arbor
