#pragma once
// Unit vectors every exporter needs from data that may be degenerate (a zero normal, a branch seen end-on).
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace arbor::exporting {

// v made unit length, or `fallback` when v has no usable length.
inline glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return (length > 1e-12f && std::isfinite(length)) ? v / length : fallback;
}

// Any unit vector at right angles to the unit vector n, where no direction is preferred.
inline glm::vec3 perpendicularTo(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, axis));
}

}  // namespace arbor::exporting
