#include "obstacle.hpp"

#include <algorithm>
#include <cmath>

namespace arbor::sc {

const char* obstacleShapeName(ObstacleShape shape) {
  switch (shape) {
    case ObstacleShape::Box: return "box";
    case ObstacleShape::Sphere: return "sphere";
    case ObstacleShape::Mesh: return "mesh";
  }
  return "?";
}

Ball boundingBall(const Obstacle& o) {
  switch (o.shape) {
    case ObstacleShape::Box: return {o.center, 0.5 * glm::length(o.size)};
    case ObstacleShape::Sphere: return {o.center, o.size.x};
    case ObstacleShape::Mesh:
      if (!o.mesh) return {};
      return {0.5 * (o.mesh->low + o.mesh->high), 0.5 * glm::length(o.mesh->high - o.mesh->low)};
  }
  return {};
}

bool insideObstacle(const Obstacle& o, const Vec3& p) {
  switch (o.shape) {
    case ObstacleShape::Box: {
      const Vec3 d = glm::abs(p - o.center), h = 0.5 * o.size;
      return d.x <= h.x && d.y <= h.y && d.z <= h.z;
    }
    case ObstacleShape::Sphere: {
      const Vec3 d = p - o.center;
      return glm::dot(d, d) <= o.size.x * o.size.x;
    }
    case ObstacleShape::Mesh: return o.mesh && insideMesh(*o.mesh, p);
  }
  return false;
}

bool segmentHitsObstacle(const Obstacle& o, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  switch (o.shape) {
    case ObstacleShape::Box: {
      // Slabs: the part of the segment's [0, 1] inside all three pairs of planes.
      const Vec3 low = o.center - 0.5 * o.size, high = o.center + 0.5 * o.size;
      double t0 = 0, t1 = 1;
      for (int k = 0; k < 3; ++k) {
        if (std::abs(d[k]) < 1e-300) {
          if (a[k] < low[k] || a[k] > high[k]) return false;
          continue;
        }
        double u = (low[k] - a[k]) / d[k], v = (high[k] - a[k]) / d[k];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u), t1 = std::min(t1, v);
        if (t0 > t1) return false;
      }
      return true;
    }
    case ObstacleShape::Sphere: {
      const double len2 = glm::dot(d, d);
      const double t = len2 > 0 ? std::clamp(glm::dot(o.center - a, d) / len2, 0.0, 1.0) : 0.0;
      const Vec3 q = a + t * d - o.center;
      return glm::dot(q, q) <= o.size.x * o.size.x;
    }
    case ObstacleShape::Mesh: return o.mesh && segmentHitsMesh(*o.mesh, a, b);
  }
  return false;
}

}  // namespace arbor::sc
