#include "pn_triangle.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace arbor {

PnTriangle pnTriangle(const std::array<glm::dvec3, 3>& position, const std::array<glm::dvec3, 3>& normal) {
  // The point a third along edge i -> j, projected onto the tangent plane at i.
  const auto edgePoint = [&](int i, int j) {
    return (2.0 * position[i] + position[j] - glm::dot(position[j] - position[i], normal[i]) * normal[i]) / 3.0;
  };
  // The average normal reflected in the plane perpendicular to the edge.
  const auto edgeNormal = [&](int i, int j) {
    const glm::dvec3 d = position[j] - position[i];
    const double v = 2.0 * glm::dot(d, normal[i] + normal[j]) / std::max(glm::dot(d, d), 1e-20);
    return glm::normalize(normal[i] + normal[j] - v * d);
  };
  PnTriangle t;
  t.points = {position[0], position[1], position[2], edgePoint(0, 1), edgePoint(1, 0), edgePoint(1, 2),
              edgePoint(2, 1), edgePoint(2, 0), edgePoint(0, 2), glm::dvec3(0.0)};
  glm::dvec3 e(0.0);
  for (int i = 3; i < 9; ++i) e += t.points[i] / 6.0;
  const glm::dvec3 centre = (position[0] + position[1] + position[2]) / 3.0;
  t.points[9] = e + (e - centre) * 0.5;
  t.edgeNormals = {edgeNormal(0, 1), edgeNormal(1, 2), edgeNormal(2, 0)};
  return t;
}

}  // namespace arbor
