#pragma once
// A stem as the mesh sees it: the deflected skeleton polyline from its attach node through its own
// nodes, parametrised by arc length, with the radius interpolated along each edge.
#include <vector>

#include "growth/skeleton.hpp"

namespace arbor {

class StemPolyline {
 public:
  StemPolyline(const Skeleton& skeleton, int stem);

  double length() const { return s_.back(); }
  Vec3 position(double s) const;        // beyond the ends: continued along the end directions
  Vec3 direction(double s) const;       // of the edge at s; at a node, the bisector of its edges
  double radius(double s) const;        // skeleton radius (edges run from startRadius to radius)
  Vec3 endDirection() const;
  Vec3 startDirection() const;

  int pointCount() const { return static_cast<int>(s_.size()); }
  double arcLength(int i) const { return s_[static_cast<std::size_t>(i)]; }
  int node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }  // skeleton node of point i
  // Arc length of the polyline's point nearest to `point` (the first, if several are as near).
  double nearestArc(const Vec3& point) const;
  // Smallest arc length at which the polyline is `distance` away from `from` (its end if never).
  double firstBeyond(const Vec3& from, double distance) const;
  // Smallest arc length at which the polyline is `clearance` away from the line through `point` along
  // `axis`, or `beyond` along that axis past `point` (its end if never).
  double firstClearOf(const Vec3& point, const Vec3& axis, double clearance, double beyond = 1e300) const;

 private:
  std::size_t edgeAt(double s) const;  // index i of the edge from point i-1 to point i (i >= 1)
  std::vector<Vec3> p_;
  std::vector<double> s_, rStart_, rEnd_;
  std::vector<int> nodes_;
};

}  // namespace arbor
