#include "periodic_noise.hpp"

#include <cmath>

namespace arbor {

namespace {

// A bijective 32-bit mixer (xorshift-multiply rounds); neighbouring inputs give unrelated outputs.
std::uint32_t mix(std::uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

std::uint32_t latticeHash(int ix, int iy, std::uint32_t seed) {
  return mix(mix(mix(seed) ^ static_cast<std::uint32_t>(ix)) ^ static_cast<std::uint32_t>(iy));
}

// Sixteen unit directions, 22.5 degrees apart: written out so that no libm rounding enters the result.
constexpr double kC1 = 0.92387953251128674, kC2 = 0.70710678118654757, kC3 = 0.38268343236508978;
constexpr double kGradients[16][2] = {
    {1, 0},     {kC1, kC3},   {kC2, kC2},   {kC3, kC1},   {0, 1},   {-kC3, kC1}, {-kC2, kC2}, {-kC1, kC3},
    {-1, 0},    {-kC1, -kC3}, {-kC2, -kC2}, {-kC3, -kC1}, {0, -1},  {kC3, -kC1}, {kC2, -kC2}, {kC1, -kC3}};

int wrap(int i, int period) {
  const int r = i % period;
  return r < 0 ? r + period : r;
}

// Quintic fade: continuous second derivative, so no creases along lattice lines.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double corner(int ix, int iy, int periodX, int periodY, std::uint32_t seed, double dx, double dy) {
  const double* g = kGradients[latticeHash(wrap(ix, periodX), wrap(iy, periodY), seed) & 15u];
  return g[0] * dx + g[1] * dy;
}

}  // namespace

double periodicNoise(double x, double y, int periodX, int periodY, std::uint32_t seed) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const double dx = x - fx, dy = y - fy;
  const double n00 = corner(ix, iy, periodX, periodY, seed, dx, dy);
  const double n10 = corner(ix + 1, iy, periodX, periodY, seed, dx - 1.0, dy);
  const double n01 = corner(ix, iy + 1, periodX, periodY, seed, dx, dy - 1.0);
  const double n11 = corner(ix + 1, iy + 1, periodX, periodY, seed, dx - 1.0, dy - 1.0);
  const double sx = fade(dx), sy = fade(dy);
  const double bottom = n00 + sx * (n10 - n00), top = n01 + sx * (n11 - n01);
  return bottom + sy * (top - bottom);
}

FeaturePoint cellFeature(int ix, int iy, int periodX, int periodY, std::uint32_t seed) {
  const std::uint32_t h = latticeHash(wrap(ix, periodX), wrap(iy, periodY), seed);
  // Kept 0.1 away from the cell's sides, so the nearest points always lie in the surrounding 5 x 5 cells.
  return {ix + 0.1 + 0.8 * static_cast<double>(h & 0xffffu) / 65535.0,
          iy + 0.1 + 0.8 * static_cast<double>(h >> 16) / 65535.0, mix(h)};
}

double noiseLayer(double u, double v, int cellsU, int cellsV, std::uint32_t seed) {
  return periodicNoise(u * cellsU, v * cellsV, cellsU, cellsV, seed);
}

double periodicFbm(double u, double v, int cellsU, int cellsV, int octaves, std::uint32_t seed) {
  double sum = 0.0, amplitude = 1.0, total = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * noiseLayer(u, v, cellsU << o, cellsV << o, seed + 0x9e3779b9u * static_cast<std::uint32_t>(o + 1));
    total += amplitude;
    amplitude *= 0.5;
  }
  return sum / total;
}

}  // namespace arbor
