#include "face_grid.hpp"

#include <algorithm>
#include <cmath>

namespace arbor {

namespace {
constexpr long kMaxCellsPerAxis = 64;      // a huge query box scans its faces' cells at most this far
constexpr std::size_t kGridFrom = 256;     // fewer faces than this: a linear scan beats building cells
// A face spanning more cells than this is looked at by every query instead of filed in each cell (a hub under
// 1,000 trunks filed its wide faces in 65^3 cells each: 5.8 GB).
constexpr long kMaxCellsPerFace = 512;
}

std::uint64_t FaceGrid::key(long x, long y, long z) const {
  const auto u = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & 0x1fffffu; };
  return (u(x) << 42) | (u(y) << 21) | u(z);
}

// Clamped, and NaN to 0, so that a degenerate box (a band of collapsed corners being tested) is never undefined.
long FaceGrid::cell(double v) const {
  const double c = std::floor(v / cellSize_);
  if (std::isnan(c)) return 0;
  return static_cast<long>(std::clamp(c, -0x1p19, 0x1p19));
}

void FaceGrid::build(std::vector<Box> boxes) {
  boxes_ = std::move(boxes);
  cells_.clear();
  large_.clear();
  stamp_.assign(boxes_.size(), 0);
  query_ = 0;
  if (boxes_.size() < kGridFrom) return;
  double sum = 0.0;
  for (const Box& b : boxes_) sum += glm::length(b.hi - b.lo);
  cellSize_ = boxes_.empty() ? 1.0 : std::max(1e-6, 2.0 * sum / static_cast<double>(boxes_.size()));
  for (std::uint32_t i = 0; i < boxes_.size(); ++i) {
    const Box& b = boxes_[i];
    const long x0 = cell(b.lo.x), y0 = cell(b.lo.y), z0 = cell(b.lo.z);
    const long x1 = cell(b.hi.x), y1 = cell(b.hi.y), z1 = cell(b.hi.z);
    if (x1 - x0 >= kMaxCellsPerFace || y1 - y0 >= kMaxCellsPerFace || z1 - z0 >= kMaxCellsPerFace ||
        (x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1) > kMaxCellsPerFace) {
      large_.push_back(i);
      continue;
    }
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y)
        for (long z = z0; z <= z1; ++z) cells_[key(x, y, z)].push_back(i);
  }
}

const std::vector<std::uint32_t>& FaceGrid::candidates(const Box& q) {
  found_.clear();
  ++query_;
  const long x0 = cell(q.lo.x), y0 = cell(q.lo.y), z0 = cell(q.lo.z);
  const long x1 = cell(q.hi.x), y1 = cell(q.hi.y), z1 = cell(q.hi.z);
  if (cells_.empty() || (x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1) > kMaxCellsPerAxis * kMaxCellsPerAxis) {
    // A query far larger than the faces: cheaper to look at every face.
    for (std::uint32_t i = 0; i < boxes_.size(); ++i)
      if (q.overlaps(boxes_[i])) found_.push_back(i);
    return found_;
  }
  for (std::uint32_t i : large_) {
    stamp_[i] = query_;
    if (q.overlaps(boxes_[i])) found_.push_back(i);
  }
  for (long x = x0; x <= x1; ++x) {
    for (long y = y0; y <= y1; ++y) {
      for (long z = z0; z <= z1; ++z) {
        const auto it = cells_.find(key(x, y, z));
        if (it == cells_.end()) continue;
        for (std::uint32_t i : it->second) {
          if (stamp_[i] == query_) continue;
          stamp_[i] = query_;
          if (q.overlaps(boxes_[i])) found_.push_back(i);
        }
      }
    }
  }
  std::sort(found_.begin(), found_.end());  // the same order as a linear scan: results stay deterministic
  return found_;
}

}  // namespace arbor
