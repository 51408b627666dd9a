#pragma once
// Reading input files as the standards ask: only regular files (a FIFO would block, a device never end), at
// most a size fit for the kind of file, as text without NUL bytes; every refusal an InputError.
#include <cstddef>
#include <string>

namespace arbor {

constexpr std::size_t kMiB = 1024 * 1024;

// Reads a whole file. `field` names what the file was given as ("(file)", "--camera-path").
std::string readInputFile(const std::string& path, std::size_t maxBytes, const std::string& field = "(file)");

// Whether a path names something that exists (a broken or looping link is reported, not thrown).
bool inputExists(const std::string& path);

// Refuses text with NUL bytes (parsers stop at them) or bytes that are not UTF-8, naming line and column.
void requireText(const std::string& text, const std::string& file, const std::string& field = "(document)");

// True when `text` is well-formed UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF).
bool isValidUtf8(const std::string& text);

// "line L, column C" of byte `offset` in `text` (both from 1).
std::string lineAndColumn(const std::string& text, std::size_t offset);

}  // namespace arbor
