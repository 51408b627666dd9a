#include "attraction_cloud.hpp"

#include <cmath>

#include "growth/random.hpp"

namespace arbor::sc {

namespace {

// Half extents of the box the volume is sampled from, around its centre.
Vec3 halfBox(const AttractionCloud& c) {
  switch (c.shape) {
    case CloudShape::Sphere: return Vec3(c.size.x);
    case CloudShape::Ellipsoid: return c.size;
    case CloudShape::Cone: return Vec3(c.size.x, c.size.x, 0.5 * c.size.z);
    case CloudShape::Box: return 0.5 * c.size;
  }
  return Vec3(0.0);
}

Vec3 boxCenter(const AttractionCloud& c) { return c.shape == CloudShape::Cone ? c.center + Vec3(0, 0, 0.5 * c.size.z) : c.center; }

bool hasVolume(const AttractionCloud& c) {
  const Vec3 h = halfBox(c);
  return h.x > 0 && h.y > 0 && h.z > 0 && std::isfinite(h.x + h.y + h.z);
}

}  // namespace

const char* cloudShapeName(CloudShape shape) {
  switch (shape) {
    case CloudShape::Sphere: return "sphere";
    case CloudShape::Ellipsoid: return "ellipsoid";
    case CloudShape::Cone: return "cone";
    case CloudShape::Box: return "box";
  }
  return "?";
}

bool insideCloud(const AttractionCloud& c, const Vec3& p) {
  const Vec3 d = p - c.center;
  switch (c.shape) {
    case CloudShape::Sphere: return glm::dot(d, d) <= c.size.x * c.size.x;
    case CloudShape::Ellipsoid: {
      const Vec3 q = d / c.size;
      return glm::dot(q, q) <= 1.0;
    }
    case CloudShape::Cone: {
      if (d.z < 0 || d.z > c.size.z) return false;
      const double r = c.size.x * (1.0 - d.z / c.size.z);
      return d.x * d.x + d.y * d.y <= r * r;
    }
    case CloudShape::Box: {
      const Vec3 h = 0.5 * c.size;
      return std::abs(d.x) <= h.x && std::abs(d.y) <= h.y && std::abs(d.z) <= h.z;
    }
  }
  return false;
}

std::uint64_t cloudSeed(std::uint64_t seed, std::size_t index) { return childKey(seed, 0x5c, index); }

std::vector<Vec3> sampleCloud(const AttractionCloud& cloud, std::uint64_t seed) {
  std::vector<Vec3> out;
  if (!hasVolume(cloud)) return out;
  out.reserve(cloud.points);
  Rng rng(seed, kStreamGeometry);
  const Vec3 h = halfBox(cloud), c = boxCenter(cloud);
  while (out.size() < cloud.points) {
    const double x = rng.signedUnit(), y = rng.signedUnit(), z = rng.signedUnit();
    const Vec3 p = c + Vec3(x * h.x, y * h.y, z * h.z);
    if (insideCloud(cloud, p)) out.push_back(p);  // the box is uniform, so is what it keeps of the volume
  }
  return out;
}

}  // namespace arbor::sc
