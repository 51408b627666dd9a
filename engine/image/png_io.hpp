#pragma once
// 8-bit RGBA images and PNG files: textures the renderer loads, screenshots the tests compare.
#include <cstdint>
#include <string>
#include <vector>

namespace arbor {

// Row 0 is the top row; four bytes per pixel (R, G, B, A), rows packed without padding.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// Any PNG (grey, RGB, palette, 16-bit, with or without alpha) becomes 8-bit RGBA.
// Throws std::runtime_error naming the path and the reason.
Image readPng(const std::string& path);

// Like readPng, for PNG bytes already in memory; `name` is the label errors give.
Image decodePng(const std::string& bytes, const std::string& name);

// Stores grey or RGB when that loses nothing (smaller files); reading gives back the same RGBA bytes.
// Throws std::invalid_argument when the image is empty or its pixel buffer has the wrong size.
std::string encodePng(const Image& image);

// Encodes, then writes beside the target and renames (arbor::writeFileAtomically).
void writePng(const std::string& path, const Image& image);

}  // namespace arbor
