#pragma once
// A space-colonization model file (docs/space-colonization-format.md): clouds, obstacles, trunk, segment length
// D, gravitropism, radii, leaves and seed, read with every refusal naming the field (exit 2).
#include <cstdint>
#include <string>
#include <vector>

#include "attraction_cloud.hpp"
#include "obstacle.hpp"

namespace arbor::sc {

struct SpaceColonization {
  std::string name;            // the model file's stem when the file names none
  std::string file;            // where it was read from: OBJ obstacles are found beside it
  std::uint64_t seed = 1;
  double segmentLength = 0.1;  // D
  double gravity = 0.0;
  Vec3 trunkBase{0.0};
  int trunkSegments = 10;
  double trunkWidth = 0.2;     // the trunk's diameter at least (the pipe model may make it thicker)
  std::vector<AttractionCloud> clouds;
  std::vector<Obstacle> obstacles;
  double tipRadius = 0.005;    // the pipe model: every tip this thick ...
  double exponent = 2.49;      // ... and r^E = sum of the children's r^E
  int leafDepth = 3;           // leaves on nodes at most this many segments above a tip
  double leafLength = 0.1, leafWidth = 0.05;
};

// Throws InputError(file, field, ...) for anything the format does not allow, among them clouds with no
// volume, negative radii, kill >= influence, an obstacle OBJ that is not closed and a trunk inside an obstacle.
SpaceColonization readSpaceColonization(const std::string& text, const std::string& file);

std::string writeSpaceColonization(const SpaceColonization& model);

}  // namespace arbor::sc
