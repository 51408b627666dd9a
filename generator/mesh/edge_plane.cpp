#include "edge_plane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace arbor {

double EdgePlane::height(const Vec3& x) const { return glm::dot(normal, x - origin); }

bool EdgePlane::behind(const std::array<Vec3, 4>& p, const std::array<std::uint32_t, 4>& ids) const {
  for (std::size_t i = 0; i < 4; ++i) {
    if (ids[i] == edge[0] || ids[i] == edge[1]) continue;
    if (!(height(p[i]) < -margin)) return false;
  }
  return true;
}

std::optional<EdgePlane> edgePlane(const Vec3& p0, const Vec3& p1, const std::array<std::uint32_t, 2>& ids, const Vec3& up,
                                   const Vec3& inward, std::span<const Vec3> front, std::span<const Vec3> back, double margin) {
  const Vec3 e = p1 - p0;
  // m: across the edge towards `inward`; u: `up` made perpendicular to the edge and to m.
  Vec3 m = glm::cross(up, e);
  const double len = glm::length(m);
  if (!(len > 0.0)) return std::nullopt;
  m /= len;
  if (glm::dot(m, inward) < 0.0) m = -m;
  Vec3 u = glm::normalize(glm::cross(e, m));
  if (glm::dot(u, up) < 0.0) u = -u;
  // Normal u + t m: a point at height h above the edge and depth d across it is in front when h + t d > 0.
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  auto bound = [&](const Vec3& x, double sign) {
    const double h = sign * glm::dot(u, x - p0), d = sign * glm::dot(m, x - p0);
    if (d > 0.0) {
      lo = std::max(lo, -h / d);
    } else if (d < 0.0) {
      hi = std::min(hi, h / -d);
    } else if (!(h > 0.0)) {
      hi = -1.0;  // on the edge's line: no tilt puts it off the plane
    }
  };
  for (const Vec3& x : front) bound(x, 1.0);
  for (const Vec3& x : back) bound(x, -1.0);
  if (!(lo < hi)) return std::nullopt;
  const double t = std::isinf(hi) ? 4.0 * lo + 4.0 : 0.5 * (lo + hi);
  const EdgePlane plane{glm::normalize(u + t * m), p0, ids, margin};
  for (const Vec3& x : front) {
    if (!(plane.height(x) > margin)) return std::nullopt;
  }
  for (const Vec3& x : back) {
    if (!(plane.height(x) < -margin)) return std::nullopt;
  }
  return plane;
}

}  // namespace arbor
