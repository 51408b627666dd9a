#pragma once
// Procedural bark: a colour map and a height map that tile in u and v, for the trunk and branch shaders.
#include <cstdint>

#include "png_io.hpp"

namespace arbor {

struct BarkTextures {
  Image color;   // brown-grey bark, dark in the fissures; opaque
  Image height;  // grey (R = G = B), mean about 128; dark = fissure, light = plate top; opaque
  Image normal;  // tangent-space normal map of the height (normalMapFromHeight, kBarkRelief), for exports
};

// The bark's relief in the normal map: black to white in the height map is this many texels (gentle, as the
// colour map already darkens the fissures).
constexpr double kBarkRelief = 6.0;

// Square maps `size` pixels wide (1..16384; the renderer wants powers of two). The image's vertical axis is
// v, along the stem: ridges and fissures run mostly vertically. Tiles seamlessly both ways. Deterministic:
// the same size and seed give the same bytes. Throws std::invalid_argument for a size out of range.
BarkTextures makeBarkTextures(int size, std::uint32_t seed);

}  // namespace arbor

namespace arbor {

// A tangent-space normal map from a height map that tiles (central differences, wrapping at the edges), in
// glTF's convention: red along +x (the image's right, +u), green up the image (against v), blue out. `relief`
// is the height difference, in texels, of black to white. Opaque RGBA, the height map's size.
Image normalMapFromHeight(const Image& height, double relief);

}  // namespace arbor
