#include "plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace arbor {

namespace {

using Rgb = std::array<std::uint8_t, 3>;

struct Canvas {
  Image& image;

  void put(int x, int y, Rgb c) const {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x));
    image.rgba[i] = c[0];
    image.rgba[i + 1] = c[1];
    image.rgba[i + 2] = c[2];
    image.rgba[i + 3] = 255;
  }
  void fill(int x0, int y0, int x1, int y1, Rgb c) const {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) put(x, y, c);
  }
  // A line two pixels wide (DDA).
  void line(double x0, double y0, double x1, double y1, Rgb c) const {
    const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int i = 0; i <= steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      const int x = static_cast<int>(std::lround(x0 + (x1 - x0) * t)), y = static_cast<int>(std::lround(y0 + (y1 - y0) * t));
      fill(x, y, x + 2, y + 2, c);
    }
  }
  // Text with its top-left corner at (x, y), `scale` pixels per font unit.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1) const {
    static char buffer[64000];
    std::string copy = s;
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, buffer, sizeof buffer);
    for (int q = 0; q < quads; ++q) {
      float v[16];
      std::memcpy(v, buffer + 64 * q, sizeof v);  // 4 vertices of x, y, z, colour (16 bytes each)
      const int qx0 = static_cast<int>(v[0]), qy0 = static_cast<int>(v[1]), qx1 = static_cast<int>(v[8]), qy1 = static_cast<int>(v[9]);
      fill(x + qx0 * scale, y + qy0 * scale, x + qx1 * scale, y + qy1 * scale, c);
    }
  }
  static int textWidth(const std::string& s) {
    std::string copy = s;
    return stb_easy_font_width(copy.data());
  }
};

std::string number(double v) {
  char text[32];
  if (v >= 1e6) std::snprintf(text, sizeof text, "%gM", v / 1e6);
  else if (v >= 1e3) std::snprintf(text, sizeof text, "%gk", v / 1e3);
  else std::snprintf(text, sizeof text, "%g", v);
  return text;
}

void drawPanel(const Canvas& canvas, const PlotPanel& panel, int left, int width, int height) {
  const Rgb ink{40, 40, 40}, grid{225, 225, 225};
  const int x0 = left + 70, x1 = left + width - 20, y0 = 40, y1 = height - 60;  // plot area
  double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
  for (const PlotSeries& s : panel.series) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (s.x[i] <= 0.0 || s.y[i] <= 0.0 || !std::isfinite(s.y[i])) continue;
      xlo = std::min(xlo, s.x[i]), xhi = std::max(xhi, s.x[i]), ylo = std::min(ylo, s.y[i]), yhi = std::max(yhi, s.y[i]);
    }
  }
  canvas.text(left + (width - Canvas::textWidth(panel.title) * 2) / 2, 10, panel.title, ink, 2);
  canvas.text(x0 + (x1 - x0 - Canvas::textWidth(panel.xLabel)) / 2, height - 25, panel.xLabel, ink);
  canvas.text(left + 5, y0 - 15, panel.yLabel, ink);
  if (!(xlo <= xhi)) {
    canvas.text(x0 + 10, (y0 + y1) / 2, "no data", ink);
    return;
  }
  // Whole powers of two on x, decades on y, around the data.
  const double lx0 = std::floor(std::log2(xlo)), lx1 = std::max(std::ceil(std::log2(xhi)), lx0 + 1.0);
  const double ly0 = std::floor(std::log10(ylo)), ly1 = std::max(std::ceil(std::log10(yhi)), ly0 + 1.0);
  const auto px = [&](double x) { return x0 + (std::log2(x) - lx0) / (lx1 - lx0) * (x1 - x0); };
  const auto py = [&](double y) { return y1 - (std::log10(y) - ly0) / (ly1 - ly0) * (y1 - y0); };
  for (double e = lx0; e <= lx1 + 1e-9; e += 1.0) {
    const int x = static_cast<int>(std::lround(px(std::exp2(e))));
    canvas.fill(x, y0, x + 1, y1, grid);
    const std::string label = number(std::exp2(e));
    canvas.text(x - Canvas::textWidth(label) / 2, y1 + 8, label, ink);
  }
  for (double e = ly0; e <= ly1 + 1e-9; e += 1.0) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (std::log10(v) > ly1 + 1e-9) break;
      const int y = static_cast<int>(std::lround(py(v)));
      canvas.fill(x0, y, x1, y + 1, m == 1.0 ? Rgb{205, 205, 205} : grid);
      const std::string label = number(v);
      canvas.text(x0 - 6 - Canvas::textWidth(label), y - 3, label, ink);
    }
  }
  canvas.fill(x0, y0, x0 + 1, y1, ink);
  canvas.fill(x0, y1, x1, y1 + 1, ink);
  int legendY = y0 + 6;
  for (const PlotSeries& s : panel.series) {
    bool havePrevious = false;
    double prevX = 0.0, prevY = 0.0;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (s.x[i] <= 0.0 || s.y[i] <= 0.0 || !std::isfinite(s.y[i])) {
        havePrevious = false;
        continue;
      }
      const double x = px(s.x[i]), y = py(s.y[i]);
      if (havePrevious) canvas.line(prevX, prevY, x, y, s.color);
      canvas.fill(static_cast<int>(x) - 3, static_cast<int>(y) - 3, static_cast<int>(x) + 4, static_cast<int>(y) + 4, s.color);
      prevX = x, prevY = y, havePrevious = true;
    }
    canvas.fill(x1 - 150, legendY + 2, x1 - 136, legendY + 6, s.color);
    canvas.text(x1 - 130, legendY, s.name, ink);
    legendY += 12;
  }
}

}  // namespace

std::array<std::uint8_t, 3> plotColor(std::size_t i) {
  static const Rgb colors[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189},
                               {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  return colors[i % (sizeof colors / sizeof colors[0])];
}

Image plotPanels(const std::vector<PlotPanel>& panels, int panelWidth, int panelHeight) {
  Image image;
  image.width = panelWidth * static_cast<int>(std::max<std::size_t>(1, panels.size()));
  image.height = panelHeight;
  image.rgba.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4, 255);
  const Canvas canvas{image};
  for (std::size_t i = 0; i < panels.size(); ++i) drawPanel(canvas, panels[i], static_cast<int>(i) * panelWidth, panelWidth, panelHeight);
  return image;
}

}  // namespace arbor
