#include "png_io.hpp"

#include <climits>
#include <stdexcept>

#include "common/atomic_file.hpp"

// stb is third-party C: its own warnings are not ours to fix, so they are silenced here only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wcast-qual"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#pragma GCC diagnostic ignored "-Wduplicated-branches"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace arbor {

namespace {

constexpr int kRgba = 4;

std::size_t byteCount(int width, int height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * kRgba;
}

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

// The fewest channels that keep every byte: 1 (grey, opaque), 3 (opaque) or 4.
int channelsNeeded(const Image& image) {
  bool opaque = true, grey = true;
  for (std::size_t i = 0; i < image.rgba.size(); i += kRgba) {
    const std::uint8_t* p = &image.rgba[i];
    opaque = opaque && p[3] == 255;
    grey = grey && p[0] == p[1] && p[1] == p[2];
  }
  if (!opaque) return 4;
  return grey ? 1 : 3;
}

}  // namespace

Image decodePng(const std::string& bytes, const std::string& name) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::runtime_error(name + ": PNG too large to decode");
  int width = 0, height = 0, channelsInFile = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                                          &width, &height, &channelsInFile, kRgba);
  if (!pixels) throw std::runtime_error(name + ": cannot be read as PNG (" + stbi_failure_reason() + ")");
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + byteCount(width, height));
  stbi_image_free(pixels);
  return image;
}

Image readPng(const std::string& path) { return decodePng(readFile(path), path); }

std::string encodePng(const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("encodePng: the image is empty");
  if (image.rgba.size() != byteCount(image.width, image.height)) {
    throw std::invalid_argument("encodePng: " + std::to_string(image.rgba.size()) + " bytes for a " +
                                std::to_string(image.width) + " x " + std::to_string(image.height) + " RGBA image");
  }
  const int channels = channelsNeeded(image);
  std::vector<std::uint8_t> packed;
  const std::uint8_t* data = image.rgba.data();
  if (channels != kRgba) {
    packed.reserve(image.rgba.size() / kRgba * static_cast<std::size_t>(channels));
    for (std::size_t i = 0; i < image.rgba.size(); i += kRgba) {
      packed.insert(packed.end(), image.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                    image.rgba.begin() + static_cast<std::ptrdiff_t>(i) + channels);
    }
    data = packed.data();
  }
  std::string png;
  if (!stbi_write_png_to_func(appendBytes, &png, image.width, image.height, channels, data, image.width * channels)) {
    throw std::runtime_error("encodePng: stb_image_write failed");
  }
  return png;
}

void writePng(const std::string& path, const Image& image) { writeFileAtomically(path, encodePng(image)); }

}  // namespace arbor
