#include "stem_polyline.hpp"

#include <algorithm>
#include <cmath>

#include "cross_section.hpp"

namespace arbor {

StemPolyline::StemPolyline(const Skeleton& skeleton, int stem) {
  const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(stem)];
  auto add = [&](int n, double rStart) {
    const SkeletonNode& node = skeleton.nodes[static_cast<std::size_t>(n)];
    const Vec3 p = node.world.position;
    s_.push_back(p_.empty() ? 0.0 : s_.back() + glm::distance(p_.back(), p));
    p_.push_back(p);
    rStart_.push_back(rStart);
    rEnd_.push_back(node.radius);
    nodes_.push_back(n);
  };
  if (st.attachNode >= 0) {
    const SkeletonNode& first = skeleton.nodes[static_cast<std::size_t>(st.firstNode)];
    add(st.attachNode, first.startRadius);
    rEnd_.back() = first.startRadius;  // this stem leaves its attach node with its own start radius
  }
  for (int i = 0; i < st.nodeCount; ++i) {
    const SkeletonNode& n = skeleton.nodes[static_cast<std::size_t>(st.firstNode + i)];
    add(st.firstNode + i, n.startRadius);
  }
  if (p_.size() == 1) {  // a lone point: give it a stub so directions exist
    add(nodes_.back(), rEnd_.back());
    p_.back() += skeleton.nodes[static_cast<std::size_t>(nodes_.back())].world.direction() * 1e-6;
    s_.back() = 1e-6;
  }
}

std::size_t StemPolyline::edgeAt(double s) const {
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  std::size_t i = static_cast<std::size_t>(it - s_.begin());
  return std::clamp<std::size_t>(i, 1, s_.size() - 1);
}

Vec3 StemPolyline::position(double s) const {
  const std::size_t i = edgeAt(s);
  const double span = s_[i] - s_[i - 1];
  const double t = span > 0.0 ? (s - s_[i - 1]) / span : 0.0;
  return p_[i - 1] + (p_[i] - p_[i - 1]) * t;  // t outside [0, 1] extrapolates the end edges
}

Vec3 StemPolyline::direction(double s) const {
  const std::size_t i = edgeAt(s);
  const Vec3 d = glm::normalize(p_[i] - p_[i - 1]);
  const double eps = 1e-9 * std::max(1.0, length());
  // At a joint, the bisector of the two edges; a stem turning straight back has none: any direction across it.
  auto bisector = [&](const Vec3& other) {
    const Vec3 sum = d + glm::normalize(other);
    return glm::length(sum) > 1e-9 ? glm::normalize(sum) : transportFrame(RingFrame{}, d).N;
  };
  if (std::fabs(s - s_[i]) < eps && i + 1 < p_.size()) return bisector(p_[i + 1] - p_[i]);
  if (std::fabs(s - s_[i - 1]) < eps && i >= 2) return bisector(p_[i - 1] - p_[i - 2]);
  return d;
}

double StemPolyline::radius(double s) const {
  const std::size_t i = edgeAt(s);
  const double span = s_[i] - s_[i - 1];
  const double t = std::clamp(span > 0.0 ? (s - s_[i - 1]) / span : 0.0, 0.0, 1.0);
  return rStart_[i] + (rEnd_[i] - rStart_[i]) * t;
}

Vec3 StemPolyline::endDirection() const { return glm::normalize(p_.back() - p_[p_.size() - 2]); }
Vec3 StemPolyline::startDirection() const { return glm::normalize(p_[1] - p_[0]); }

double StemPolyline::firstBeyond(const Vec3& from, double distance) const {
  if (glm::distance(p_[0], from) >= distance) return 0.0;
  for (std::size_t i = 1; i < p_.size(); ++i) {
    if (glm::distance(p_[i], from) < distance) continue;
    // Solve |p0 + t d - from| = distance on this edge for the crossing t in [0, 1].
    const Vec3 d = p_[i] - p_[i - 1], m = p_[i - 1] - from;
    const double a = glm::dot(d, d), b = 2.0 * glm::dot(m, d), c = glm::dot(m, m) - distance * distance;
    const double disc = std::max(0.0, b * b - 4.0 * a * c);
    const double t = a > 0.0 ? std::clamp((-b + std::sqrt(disc)) / (2.0 * a), 0.0, 1.0) : 1.0;
    return s_[i - 1] + t * (s_[i] - s_[i - 1]);
  }
  return length();
}

double StemPolyline::firstClearOf(const Vec3& point, const Vec3& axis, double clearance) const {
  auto away = [&](double s) {
    const Vec3 d = position(s) - point;
    return glm::length(d - axis * glm::dot(d, axis));
  };
  // March in steps of a third of the clearance, then bisect the crossing.
  const double step = std::max(clearance / 3.0, length() * 1e-4);
  double prev = 0.0;
  for (double s = 0.0; s <= length(); s += step) {
    if (away(s) >= clearance) {
      double lo = prev, hi = s;
      for (int i = 0; i < 20; ++i) {
        const double mid = 0.5 * (lo + hi);
        (away(mid) >= clearance ? hi : lo) = mid;
      }
      return hi;
    }
    prev = s;
  }
  return length();
}

}  // namespace arbor
