#include "image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace arbor {

namespace {

constexpr std::size_t kRgba = 4;

void requireSameSize(const Image& a, const Image& b, const char* function) {
  const auto expected = [](const Image& i) {
    return static_cast<std::size_t>(std::max(i.width, 0)) * static_cast<std::size_t>(std::max(i.height, 0)) * kRgba;
  };
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(std::string(function) + ": sizes differ (" + std::to_string(a.width) + " x " +
                                std::to_string(a.height) + " against " + std::to_string(b.width) + " x " +
                                std::to_string(b.height) + ")");
  }
  if (a.rgba.size() != expected(a) || b.rgba.size() != expected(b)) {
    throw std::invalid_argument(std::string(function) + ": pixel buffer size does not match width x height x 4");
  }
}

}  // namespace

ImageDifference compareImages(const Image& a, const Image& b, int threshold) {
  requireSameSize(a, b, "compareImages");
  ImageDifference d;
  std::uint64_t sumAbsolute = 0, sumSquares = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += kRgba) {
    int pixelMax = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int diff = std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]});
      pixelMax = std::max(pixelMax, diff);
      sumAbsolute += static_cast<std::uint64_t>(diff);
      sumSquares += static_cast<std::uint64_t>(diff * diff);
    }
    d.maxChannelDifference = std::max(d.maxChannelDifference, pixelMax);
    if (pixelMax > threshold) ++d.pixelsOverThreshold;
  }
  const double samples = static_cast<double>(a.rgba.size() / kRgba * 3);
  if (sumSquares == 0 || samples == 0) {
    d.psnr = std::numeric_limits<double>::infinity();
    return d;
  }
  const double meanSquare = static_cast<double>(sumSquares) / samples;
  d.psnr = 10.0 * std::log10(255.0 * 255.0 / meanSquare);
  d.meanAbsoluteDifference = static_cast<double>(sumAbsolute) / samples;
  return d;
}

Image differenceImage(const Image& a, const Image& b) {
  requireSameSize(a, b, "differenceImage");
  // Any difference starts at a visible grey, then grows eight levels per level of difference.
  constexpr int kFloor = 48, kGain = 8;
  Image out{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size())};
  for (std::size_t i = 0; i < a.rgba.size(); i += kRgba) {
    for (std::size_t c = 0; c < 3; ++c) {
      const int diff = std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]});
      out.rgba[i + c] = static_cast<std::uint8_t>(diff == 0 ? 0 : std::min(255, kFloor + kGain * diff));
    }
    out.rgba[i + 3] = 255;
  }
  return out;
}

std::vector<bool> differingPixels(const Image& a, const Image& b) {
  requireSameSize(a, b, "differingPixels");
  std::vector<bool> differs(a.rgba.size() / 4);
  for (std::size_t p = 0; p < differs.size(); ++p) {
    differs[p] = a.rgba[4 * p] != b.rgba[4 * p] || a.rgba[4 * p + 1] != b.rgba[4 * p + 1] || a.rgba[4 * p + 2] != b.rgba[4 * p + 2];
  }
  return differs;
}

}  // namespace arbor
