#include "point_index.hpp"

#include <cmath>

#include <nanoflann.hpp>

namespace arbor::sc {

namespace {

// nanoflann's view of the points.
struct Points {
  std::vector<Vec3> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t k) const { return points[i][static_cast<int>(k)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points>, Points, 3, std::uint32_t>;

double distance2(const Vec3& a, const Vec3& b) {
  const Vec3 d = a - b;
  return glm::dot(d, d);
}

}  // namespace

struct PointIndex::Tree {
  explicit Tree(std::vector<Vec3> p) : data{std::move(p)}, tree(3, data, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
    if (!data.points.empty()) tree.buildIndex();
  }
  Points data;
  KdTree tree;
};

PointIndex::PointIndex(std::vector<Vec3> points) : tree_(std::make_shared<const Tree>(std::move(points))) {}

std::size_t PointIndex::size() const { return tree_ ? tree_->data.points.size() : 0; }

void PointIndex::within(const Vec3& q, double radius, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (size() == 0) return;
  thread_local std::vector<std::pair<std::uint32_t, double>> found;
  found.clear();
  // Searched a little wider, then decided with our own distance, so that the answer is brute force's exactly.
  const double r2 = radius * radius;
  const double query[3] = {q.x, q.y, q.z};
  nanoflann::RadiusResultSet<double, std::uint32_t> result(r2 * (1 + 1e-9) + 1e-300, found);
  tree_->tree.findNeighbors(result, query, nanoflann::SearchParams(32, 0, false));
  for (const auto& [i, d2] : found)
    if (distance2(tree_->data.points[i], q) < r2) out.push_back(i);
}

std::int64_t PointIndex::nearest(const Vec3& q) const {
  if (size() == 0) return -1;
  const double query[3] = {q.x, q.y, q.z};
  std::uint32_t index = 0;
  double d2 = 0;
  tree_->tree.knnSearch(query, 1, &index, &d2);
  // Among the points as near as the one found (ties), the lowest index.
  const double best = distance2(tree_->data.points[index], q);
  std::vector<std::uint32_t> ties;
  within(q, std::sqrt(best) * (1 + 1e-9) + 1e-150, ties);
  std::int64_t out = index;
  double outD2 = best;
  for (const std::uint32_t i : ties) {
    const double d = distance2(tree_->data.points[i], q);
    if (d < outD2 || (d == outD2 && i < out)) out = i, outD2 = d;
  }
  return out;
}

}  // namespace arbor::sc
