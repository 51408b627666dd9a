#pragma once
// Gradient and cellular noise that repeat on an integer lattice period, so textures built from them tile seamlessly.
#include <cstdint>

namespace arbor {

// Perlin-style gradient noise at (x, y) in lattice units, repeating every periodX along x and periodY along y
// (both >= 1). Roughly in [-0.7, 0.7], 0 on every lattice point. Uses only exact IEEE operations, so the
// same inputs give the same bits on every conforming compiler and library.
double periodicNoise(double x, double y, int periodX, int periodY, std::uint32_t seed);

// One layer over the unit square: `cellsU` x `cellsV` lattice cells across it, periodic in u and v with
// period 1. Unequal cell counts stretch the features (fewer cells along v: longer along v).
double noiseLayer(double u, double v, int cellsU, int cellsV, std::uint32_t seed);

// Fractal sum of `octaves` layers, each with twice the cells and half the amplitude of the one before,
// normalised so that its amplitude matches a single layer's.
double periodicFbm(double u, double v, int cellsU, int cellsV, int octaves, std::uint32_t seed);

// The feature point of lattice cell (ix, iy) for cellular noise: jittered inside the cell, in the same
// lattice units as (ix, iy); cells a whole period apart get the same jitter and hash.
struct FeaturePoint {
  double x = 0.0, y = 0.0;
  std::uint32_t hash = 0;
};
FeaturePoint cellFeature(int ix, int iy, int periodX, int periodY, std::uint32_t seed);

}  // namespace arbor
