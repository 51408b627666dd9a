#pragma once
// How far two images of the same size are apart: renders against references, tolerant of small GPU differences.
#include <cstddef>
#include <vector>

#include "png_io.hpp"

namespace arbor {

// Every figure is over R, G and B; alpha is ignored (renders and references are opaque).
struct ImageDifference {
  int maxChannelDifference = 0;          // largest |a - b| of any channel of any pixel, 0..255
  double psnr = 0.0;                     // dB, peak 255; +infinity when the images are identical
  std::size_t pixelsOverThreshold = 0;   // pixels whose largest channel difference exceeds the threshold
  double meanAbsoluteDifference = 0.0;   // per channel, 0..255
};

// Throws std::invalid_argument when the sizes differ.
ImageDifference compareImages(const Image& a, const Image& b, int threshold);

// Black where the images agree; each channel's difference amplified so that one level is already visible.
// Opaque. Throws std::invalid_argument when the sizes differ.
Image differenceImage(const Image& a, const Image& b);

// Per pixel, row by row: whether R, G or B differs at all (what a drawing added to a picture without it).
// Throws std::invalid_argument when the sizes differ.
std::vector<bool> differingPixels(const Image& a, const Image& b);

}  // namespace arbor
