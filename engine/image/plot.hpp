#pragma once
// Line plots as pictures (benchmark figures): panels side by side, each with log axes, ticks, labels and a
// legend, drawn into an RGBA image with a small built-in font (stb_easy_font).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "png_io.hpp"

namespace arbor {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;  // points with x or y <= 0 are left out (log axes)
  std::array<std::uint8_t, 3> color{0, 0, 0};
};

struct PlotPanel {
  std::string title, xLabel, yLabel;
  std::vector<PlotSeries> series;
};

// Both axes logarithmic: x ticks at powers of two, y ticks at 1, 2 and 5 times powers of ten.
Image plotPanels(const std::vector<PlotPanel>& panels, int panelWidth = 560, int panelHeight = 420);

// A distinct colour for series i.
std::array<std::uint8_t, 3> plotColor(std::size_t i);

}  // namespace arbor
