#pragma once
// Attraction-point clouds (Runions et al. 2007; Patrick, Rege & Bailey's four crown envelopes): a volume, its
// point count, and the influence radius and kill distance of its points.
#include <cstdint>
#include <vector>

#include "growth/math.hpp"

namespace arbor::sc {

enum class CloudShape : std::uint8_t { Sphere, Ellipsoid, Cone, Box };

struct AttractionCloud {
  CloudShape shape = CloudShape::Sphere;
  Vec3 center{0.0};       // sphere, ellipsoid, box: the centre; cone: the centre of its base disc (apex above)
  Vec3 size{1.0};         // sphere: x = radius; ellipsoid: semi-axes; cone: x = base radius, z = height; box: full extents
  std::uint32_t points = 1000;
  double influence = 1.0;  // a point attracts only nodes nearer than this
  double kill = 0.2;       // a point dies once a node is nearer than this (kill < influence)
};

const char* cloudShapeName(CloudShape shape);

// Whether p lies inside the cloud's volume (its boundary included).
bool insideCloud(const AttractionCloud& cloud, const Vec3& p);

// Exactly cloud.points points, uniform inside the volume (rejection from its bounding box), the same for the same
// seed. A cloud with no volume gives none (the reader refuses such clouds first).
std::vector<Vec3> sampleCloud(const AttractionCloud& cloud, std::uint64_t seed);

// The seed of the index-th cloud: each cloud its own stream, so adding one never moves another's points.
std::uint64_t cloudSeed(std::uint64_t seed, std::size_t index);

}  // namespace arbor::sc
