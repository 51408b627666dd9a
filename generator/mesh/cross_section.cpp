#include "cross_section.hpp"

#include <cmath>

namespace arbor {

namespace {

Vec3 anyPerpendicular(const Vec3& t) {
  const Vec3 a = std::fabs(t.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return glm::normalize(a - t * glm::dot(a, t));
}

}  // namespace

Vec3 directionOr(const Vec3& v, const Vec3& fallback) {
  const double length = glm::length(v);
  return length > 1e-9 ? v / length : fallback;
}

RingFrame transportFrame(const RingFrame& frame, const Vec3& newT) {
  const Vec3 t = glm::normalize(newT);
  const double c = glm::dot(frame.T, t);
  Vec3 n;
  if (c > -0.9999) {
    // Rotate N by the rotation taking T to t (Rodrigues with axis T x t, written without angles).
    const Vec3 axis = glm::cross(frame.T, t);
    const double k = 1.0 / (1.0 + c);
    n = frame.N * c + glm::cross(axis, frame.N) + axis * (glm::dot(axis, frame.N) * k);
  } else {
    n = -frame.N;  // a half turn: any axis will do, keep N's plane
  }
  n = n - t * glm::dot(n, t);
  const double len = glm::length(n);
  n = len > 1e-12 ? n / len : anyPerpendicular(t);
  return RingFrame{t, n, glm::cross(t, n)};
}

RingFrame frameFromHint(const Vec3& T, const Vec3& hint) {
  const Vec3 t = glm::normalize(T);
  Vec3 n = hint - t * glm::dot(hint, t);
  const double len = glm::length(n);
  n = len > 1e-9 ? n / len : anyPerpendicular(t);
  return RingFrame{t, n, glm::cross(t, n)};
}

std::array<Vec3, 4> ringOffsets(const RingFrame& f, double r) {
  return {f.N * r, f.B * r, -f.N * r, -f.B * r};
}

}  // namespace arbor
