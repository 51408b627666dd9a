#pragma once
// A uniform grid over a set of quads' bounding boxes: "which faces could touch this box" without testing
// every face of a long parent stem for each of its children.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "growth/math.hpp"

namespace arbor {

struct Box {
  Vec3 lo{0.0}, hi{0.0};
  bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
};

template <std::size_t N>
Box boxOf(const std::array<Vec3, N>& corners) {
  Box b{corners[0], corners[0]};
  for (const Vec3& c : corners) {
    b.lo = glm::min(b.lo, c);
    b.hi = glm::max(b.hi, c);
  }
  return b;
}

class FaceGrid {
 public:
  // Boxes of the faces; the cell size follows their typical size.
  void build(std::vector<Box> boxes);
  // Indices (into the boxes given to build) of faces whose box overlaps `query`, each once.
  const std::vector<std::uint32_t>& candidates(const Box& query);
  const Box& box(std::uint32_t i) const { return boxes_[i]; }

 private:
  std::uint64_t key(long x, long y, long z) const;
  long cell(double v) const;
  std::vector<Box> boxes_;
  double cellSize_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> large_;  // faces too large to file in cells: every query looks at them
  std::vector<std::uint32_t> stamp_, found_;
  std::uint32_t query_ = 0;
};

}  // namespace arbor
