#pragma once
// The leaf atlas: four leaf kinds (broad, narrow, frond, needle cluster) as RGBA cutouts in a 2 x 2 grid, for
// the leaf quads the renderer expands from leaf points.
#include <cstdint>

#include "png_io.hpp"

namespace arbor {

// Which atlas cell holds a kind (LeafKind order: Broad, Narrow, Frond, Needle): cell k spans
// u in [0.5 (k % 2), 0.5 (k % 2) + 0.5] and v (down the image) in [0.5 (k / 2), 0.5 (k / 2) + 0.5].
// In each cell the blade's base is at the bottom centre and its tip at the top.
constexpr int kLeafAtlasCells = 4;

// Square atlas `size` pixels wide (a power of two from 64 to 4096), colour in RGB, coverage in A with
// antialiased edges. Deterministic: the same size and seed give the same bytes. Throws std::invalid_argument
// for a size out of range.
Image makeLeafAtlas(int size, std::uint32_t seed);

}  // namespace arbor
