#include "bark_texture.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "periodic_noise.hpp"

namespace arbor {

namespace {

// Every layer gets its own seed, so changing one layer's lattice never changes another's pattern.
enum Layer : std::uint32_t {
  WarpU = 1, WarpV, PlateCells, FissureEdge, FissureWidth, Streaks, Bumps, Grain, Tone, ToneDetail, Mottle, ColourGrain
};

std::uint32_t layerSeed(std::uint32_t seed, Layer layer) { return seed * 0x2c1b3c6du + layer * 0x297a2d39u; }

// Plates per tile: 12 across, 3 along v, so each is about four times as long as it is wide.
constexpr int kPlatesU = 12, kPlatesV = 3;
constexpr double kFissureWidth = 0.4;  // half width of a fissure, in plate widths
constexpr double kSpread = 54.0;       // standard deviation of the height map, in byte levels

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double mixValue(double a, double b, double t) { return a + (b - a) * t; }

struct Plates {
  double fissure = 0.0;     // 0 on a plate, up to 1 at the bottom of a deep fissure
  double edge = 0.0;        // distance to the nearest border, in fissure widths (for the plate's rounded top)
  std::uint32_t plate = 0;  // which plate the sample lies on
};

// Plates are the cells of feature points on a `cellsU` x `cellsV` lattice, found in lattice units so that they
// are stretched like the lattice; the fissures are their borders. Distances to a border are measured with v
// scaled to u's lattice units, so that fissures in every direction are equally wide; `roughness` (in those
// units) moves the borders, so that fissure walls are ragged instead of straight.
Plates plateField(double u, double v, int cellsU, int cellsV, double width, double roughness, std::uint32_t seed) {
  const double x = u * cellsU, y = v * cellsV;
  const double stretch = static_cast<double>(cellsU) / cellsV;
  const int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y));
  constexpr int kReach = 2;  // feature points stay inside their cells, so both nearest lie in this 5 x 5 block
  FeaturePoint points[(2 * kReach + 1) * (2 * kReach + 1)];
  double distances[std::size(points)];
  std::size_t nearest = 0, n = 0;
  for (int j = -kReach; j <= kReach; ++j) {
    for (int i = -kReach; i <= kReach; ++i, ++n) {
      points[n] = cellFeature(ix + i, iy + j, cellsU, cellsV, seed);
      const double dx = points[n].x - x, dy = points[n].y - y;
      distances[n] = dx * dx + dy * dy;
      if (distances[n] < distances[nearest]) nearest = n;
    }
  }
  Plates p;
  p.plate = points[nearest].hash;
  p.edge = 1e30;
  for (std::size_t k = 0; k < std::size(points); ++k) {
    if (k == nearest) continue;
    // The bisector's normal in texture proportions: the lattice normal with its v part shrunk by the stretch.
    const double ax = points[k].x - points[nearest].x, ay = (points[k].y - points[nearest].y) / stretch;
    const double length = std::sqrt(ax * ax + ay * ay);
    // Distance from the sample to the bisector of the two points: 0 on the border between their cells.
    const double border = std::max(0.0, (distances[k] - distances[nearest]) / (2.0 * length) + roughness) / width;
    p.edge = std::min(p.edge, border);
    if (border >= 1.0) continue;
    // Borders between plates side by side run along v and are deep; those between plates above each other
    // are shallow, so the plates read as long interlaced ridges rather than tiles. The maximum over all
    // neighbours keeps the depth continuous where the second nearest point changes.
    const double across = ax / length;
    p.fissure = std::max(p.fissure, (0.3 + 0.7 * across * across) * (1.0 - border) * (1.0 - border));
  }
  return p;
}

// Relief before normalisation: low in the fissures, about 1 on a plate.
double relief(double u, double v, std::uint32_t seed) {
  // A periodic warp bends the straight borders between feature points into meandering fissures.
  const double wu = u + 0.03 * periodicFbm(u, v, 4, 4, 3, layerSeed(seed, WarpU));
  const double wv = v + 0.06 * periodicFbm(u, v, 3, 3, 3, layerSeed(seed, WarpV));
  const double width = kFissureWidth * (1.0 + 0.3 * noiseLayer(u, v, 4, 3, layerSeed(seed, FissureWidth)));
  const double roughness = 0.5 * kFissureWidth * periodicFbm(u, v, 24, 12, 3, layerSeed(seed, FissureEdge));
  const Plates plates = plateField(wu, wv, kPlatesU, kPlatesV, width, roughness, layerSeed(seed, PlateCells));
  const double lift = 1.0 - 0.1 * static_cast<double>(plates.plate & 0xffu) / 255.0;  // plates differ in height
  const double dome = 1.0 - 0.25 * (1.0 - smoothstep(1.0, 3.5, plates.edge));         // rounded plate tops

  // Fibrous streaks along v and bumps on the plates, a fine isotropic grain everywhere.
  const double streaks = periodicFbm(wu, wv, 24, 4, 4, layerSeed(seed, Streaks));
  const double bumps = periodicFbm(wu, wv, 12, 6, 4, layerSeed(seed, Bumps));
  const double grain = periodicFbm(u, v, 64, 64, 2, layerSeed(seed, Grain));
  return (1.0 - plates.fissure) * lift * dome * (1.0 + 0.35 * streaks + 0.4 * bumps) + 0.08 * grain;
}

struct Rgb {
  double r, g, b;
};

Rgb mixRgb(const Rgb& a, const Rgb& b, double t) {
  return {mixValue(a.r, b.r, t), mixValue(a.g, b.g, t), mixValue(a.b, b.b, t)};
}

std::uint8_t toByte(double x) { return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

// Colour from height (0..1): dark brown fissure bottoms, brown walls, weathered brown to grey plate tops,
// with a mottle and a grain that do not follow the relief.
Rgb barkColour(double u, double v, double height, std::uint32_t seed) {
  constexpr Rgb kBottom{0.16, 0.115, 0.09}, kWall{0.38, 0.29, 0.22}, kTopBrown{0.54, 0.47, 0.40},
      kTopGrey{0.62, 0.60, 0.56};
  const double tone = noiseLayer(u, v, 3, 2, layerSeed(seed, Tone)) + 0.5 * noiseLayer(u, v, 8, 4, layerSeed(seed, ToneDetail));
  const Rgb top = mixRgb(kTopBrown, kTopGrey, smoothstep(-0.4, 0.5, tone));
  const Rgb c = height < 0.5 ? mixRgb(kBottom, kWall, smoothstep(0.05, 0.5, height))
                             : mixRgb(kWall, top, smoothstep(0.5, 0.78, height));
  const double shade = 1.0 + 0.3 * periodicFbm(u, v, 10, 6, 3, layerSeed(seed, Mottle)) +
                       0.12 * periodicFbm(u, v, 96, 48, 2, layerSeed(seed, ColourGrain));
  return {c.r * shade, c.g * shade, c.b * shade};
}

Image opaqueImage(int size) {
  const std::size_t n = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  return Image{size, size, std::vector<std::uint8_t>(n * 4, 255)};
}

}  // namespace

BarkTextures makeBarkTextures(int size, std::uint32_t seed) {
  if (size < 1 || size > 16384) {
    throw std::invalid_argument("makeBarkTextures: size " + std::to_string(size) + " is outside 1..16384");
  }
  // Pixel x samples u = x / size: a whole number of lattice periods per image, so the last column meets the first.
  const auto coordinate = [size](int i) { return static_cast<double>(i) / size; };
  const std::size_t count = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  std::vector<double> raw(count);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) raw[static_cast<std::size_t>(y) * size + x] = relief(coordinate(x), coordinate(y), seed);
  }
  // Normalise to mean 128 and a fixed spread, so every seed uses the byte range alike.
  double sum = 0.0, sumSquares = 0.0;
  for (double h : raw) sum += h;
  const double mean = sum / static_cast<double>(count);
  for (double h : raw) sumSquares += (h - mean) * (h - mean);
  const double deviation = std::sqrt(sumSquares / static_cast<double>(count));
  const double scale = deviation > 0.0 ? kSpread / deviation : 0.0;

  BarkTextures maps{opaqueImage(size), opaqueImage(size), {}};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      const double height = std::clamp(128.0 + (raw[i] - mean) * scale, 0.0, 255.0) / 255.0;
      const std::uint8_t h = toByte(height);
      maps.height.rgba[4 * i] = maps.height.rgba[4 * i + 1] = maps.height.rgba[4 * i + 2] = h;
      const Rgb c = barkColour(coordinate(x), coordinate(y), height, seed);
      maps.color.rgba[4 * i] = toByte(c.r);
      maps.color.rgba[4 * i + 1] = toByte(c.g);
      maps.color.rgba[4 * i + 2] = toByte(c.b);
    }
  }
  maps.normal = normalMapFromHeight(maps.height, kBarkRelief);
  return maps;
}

}  // namespace arbor

namespace arbor {

Image normalMapFromHeight(const Image& height, double relief) {
  if (height.width <= 0 || height.height <= 0 || height.rgba.size() != static_cast<std::size_t>(height.width) * static_cast<std::size_t>(height.height) * 4) {
    throw std::invalid_argument("normalMapFromHeight: the height map is empty or its pixel buffer has the wrong size");
  }
  const int w = height.width, h = height.height;
  auto at = [&](int x, int y) {
    x = (x % w + w) % w;
    y = (y % h + h) % h;
    return height.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4] / 255.0 * relief;
  };
  Image normals;
  normals.width = w;
  normals.height = h;
  normals.rgba.resize(height.rgba.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double dx = 0.5 * (at(x + 1, y) - at(x - 1, y));
      const double dUp = 0.5 * (at(x, y - 1) - at(x, y + 1));  // rows grow down the image; green points up
      const double length = std::sqrt(dx * dx + dUp * dUp + 1.0);
      const double n[3] = {-dx / length, -dUp / length, 1.0 / length};
      std::uint8_t* texel = &normals.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4];
      for (int c = 0; c < 3; ++c) texel[c] = static_cast<std::uint8_t>(std::lround(127.5 * (n[c] + 1.0)));
      texel[3] = 255;
    }
  }
  return normals;
}

}  // namespace arbor
