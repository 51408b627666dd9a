#include "stem_polyline.hpp"

#include <algorithm>
#include <cmath>

#include "cross_section.hpp"

namespace arbor {

StemPolyline::StemPolyline(const Skeleton& skeleton, int stem) {
  const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(stem)];
  // Room for every point at once: growing five vectors point by point cost 4 % of the mesher's instructions.
  const auto points = static_cast<std::size_t>(st.nodeCount) + 2;
  p_.reserve(points);
  s_.reserve(points);
  rStart_.reserve(points);
  rEnd_.reserve(points);
  nodes_.reserve(points);
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

double StemPolyline::nearestArc(const Vec3& point) const {
  double best = 0.0, bestDistance = glm::distance(p_[0], point);
  for (std::size_t i = 1; i < p_.size(); ++i) {
    const Vec3 d = p_[i] - p_[i - 1];
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(point - p_[i - 1], d) / len2, 0.0, 1.0) : 0.0;
    const double distance = glm::distance(p_[i - 1] + d * t, point);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = s_[i - 1] + t * (s_[i] - s_[i - 1]);
    }
  }
  return best;
}

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

double StemPolyline::firstClearOf(const Vec3& point, const Vec3& axis, double clearance, double beyond) const {
  // Along an edge the squared distance from the axis is a quadratic in the edge's parameter t, so the first edge
  // to reach `clearance` gives the crossing exactly (marching in steps of a third of it, then bisecting, was a
  // tenth of a large tree's mesh time: children running along their parent never cleared it).
  const double c2 = clearance * clearance;
  for (std::size_t i = 1; i < p_.size(); ++i) {
    const Vec3 a = p_[i - 1] - point, e = p_[i] - p_[i - 1];
    const Vec3 across = a - axis * glm::dot(a, axis), grows = e - axis * glm::dot(e, axis);
    const double aa = glm::dot(across, across) - c2, along = glm::dot(a, axis), rises = glm::dot(e, axis);
    if (aa >= 0.0 || along >= beyond) return s_[i - 1];
    // f(t) = |grows|^2 t^2 + 2 (across . grows) t + aa, negative at 0: its larger root, in the cancellation-free form.
    const double ab = glm::dot(across, grows), disc = ab * ab - glm::dot(grows, grows) * aa;
    const double denominator = ab + std::sqrt(std::max(disc, 0.0));
    double t = denominator > 0.0 ? -aa / denominator : 2.0;
    if (rises > 0.0) t = std::min(t, (beyond - along) / rises);  // past the end along the axis: linear in t
    if (t <= 1.0) return s_[i - 1] + t * (s_[i] - s_[i - 1]);
  }
  return length();
}

}  // namespace arbor
