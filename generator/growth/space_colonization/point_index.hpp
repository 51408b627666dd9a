#pragma once
// A k-d tree over fixed 3D points (nanoflann): the attraction points near a new node, in one query instead of
// a pass over every point. Immutable once built; copies share it.
#include <cstdint>
#include <memory>
#include <vector>

#include "growth/math.hpp"

namespace arbor::sc {

class PointIndex {
 public:
  PointIndex() = default;
  explicit PointIndex(std::vector<Vec3> points);

  // Every point with |p - q|^2 < radius^2 (computed as glm::dot of the difference, as brute force would), in
  // no particular order, into `out` (cleared first).
  void within(const Vec3& q, double radius, std::vector<std::uint32_t>& out) const;

  // The point nearest q (the lowest index among equally near ones); -1 when there is none.
  std::int64_t nearest(const Vec3& q) const;

  std::size_t size() const;

 private:
  struct Tree;
  std::shared_ptr<const Tree> tree_;
};

}  // namespace arbor::sc
