#include "leaf_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "periodic_noise.hpp"

namespace arbor {

namespace {

constexpr double kPi = 3.14159265358979323846;

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
std::uint8_t toByte(double x) { return static_cast<std::uint8_t>(std::lround(clamp01(x) * 255.0)); }

// A sample of one leaf kind at (s, t): s across the blade (-1 left edge of the cell, 1 right), t from the base
// (0) to the tip (1). `inside` is a signed distance in cell units, positive inside; `vein` 0..1 lightens.
struct Blade {
  double inside = -1.0;
  double vein = 0.0;
};

// The stalk at the base, shared by every kind.
double stalk(double s, double t) { return t < 0.12 ? 0.018 - std::abs(s) : -1.0; }

// Ovate blade with a midrib and side veins (aspen, tupelo, oak read as this at leaf size).
Blade broad(double s, double t) {
  const double x = (t - 0.1) / 0.88;
  const double half = x > 0.0 && x < 1.0 ? 0.82 * std::pow(std::sin(kPi * std::pow(x, 0.8)), 0.75) : 0.0;
  Blade b{std::max(half - std::abs(s), stalk(s, t)), 0.0};
  const double side = std::abs(std::fmod(t * 9.0 - std::abs(s) * 4.0 + 10.0, 1.0) - 0.5);
  b.vein = std::max(std::abs(s) < 0.025 ? 1.0 : 0.0, side < 0.04 && std::abs(s) < half * 0.85 ? 0.5 : 0.0);
  return b;
}

// Lanceolate blade (willow, poplar).
Blade narrow(double s, double t) {
  const double x = (t - 0.08) / 0.9;
  const double half = x > 0.0 && x < 1.0 ? 0.3 * std::pow(std::sin(kPi * x), 0.9) : 0.0;
  Blade b{std::max(half - std::abs(s), stalk(s, t)), std::abs(s) < 0.02 ? 1.0 : 0.0};
  return b;
}

// Palm frond: a rachis with slanted leaflets along it.
Blade frond(double s, double t) {
  const double x = (t - 0.05) / 0.95;
  const double reach = x > 0.0 && x < 1.0 ? 0.95 * std::pow(std::sin(kPi * std::pow(x, 0.7)), 0.8) : 0.0;
  const double phase = std::fmod(t * 16.0 - std::abs(s) * 2.2 + 20.0, 1.0);
  const double leaflet = 0.32 - std::abs(phase - 0.5);  // > 0 on a leaflet
  const double onLeaflet = std::min(reach - std::abs(s), leaflet * 0.2);
  const double rachis = x > 0.0 && x < 1.0 ? 0.03 - std::abs(s) : -1.0;
  Blade b{std::max({onLeaflet, rachis, stalk(s, t)}), std::abs(s) < 0.03 ? 0.8 : 0.0};
  return b;
}

// A fan of needles from the base.
Blade needles(double s, double t) {
  const double r = std::sqrt(s * s + t * t);
  const double angle = std::atan2(s, std::max(t, 1e-9));  // 0 straight up
  const double spoke = std::abs(std::fmod((angle / kPi + 1.0) * 11.0, 1.0) - 0.5) * r * kPi / 11.0;
  const double inFan = std::abs(angle) < 0.75 && r > 0.05 && r < 0.97 ? 0.012 - spoke : -1.0;
  return Blade{std::max(inFan, stalk(s, t)), 0.0};
}

Blade bladeOf(int kind, double s, double t) {
  switch (kind) {
    case 0: return broad(s, t);
    case 1: return narrow(s, t);
    case 2: return frond(s, t);
    default: return needles(s, t);
  }
}

}  // namespace

Image makeLeafAtlas(int size, std::uint32_t seed) {
  if (size < 64 || size > 4096 || (size & (size - 1)) != 0) {
    throw std::invalid_argument("makeLeafAtlas: size " + std::to_string(size) + " is not a power of two from 64 to 4096");
  }
  Image atlas{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4, 0)};
  const int cell = size / 2;
  const double pixel = 2.0 / cell;  // one pixel in s units, for antialiased edges
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int kind = (x / cell) + 2 * (y / cell);
      const double s = ((x % cell) + 0.5) / cell * 2.0 - 1.0;
      const double t = 1.0 - ((y % cell) + 0.5) / cell;
      const Blade b = bladeOf(kind, s, t);
      const double coverage = clamp01(0.5 + b.inside / pixel);
      // Greens that differ by kind, mottled, darker at the edges, lighter on the veins.
      const double mottle = 0.12 * periodicFbm(static_cast<double>(x) / size, static_cast<double>(y) / size, 16, 16, 3,
                                               seed * 0x9e3779b9u + 17u);
      const double edge = clamp01(b.inside / 0.08);
      const double shade = (0.75 + 0.25 * edge) * (1.0 + mottle) + 0.35 * b.vein;
      static constexpr double kGreen[4][3] = {{0.26, 0.42, 0.11}, {0.30, 0.44, 0.16}, {0.24, 0.40, 0.12}, {0.16, 0.30, 0.12}};
      std::uint8_t* p = &atlas.rgba[(static_cast<std::size_t>(y) * size + x) * 4];
      p[0] = toByte(kGreen[kind][0] * shade);
      p[1] = toByte(kGreen[kind][1] * shade);
      p[2] = toByte(kGreen[kind][2] * shade);
      p[3] = toByte(coverage);
    }
  }
  return atlas;
}

}  // namespace arbor
