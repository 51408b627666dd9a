#pragma once
// Obstacles (Patrick et al. §3.1): no segment grows into one; one added later disables the branches it holds.
#include <cstdint>
#include <memory>
#include <string>

#include "triangle_mesh.hpp"

namespace arbor::sc {

enum class ObstacleShape : std::uint8_t { Box, Sphere, Mesh };

struct Obstacle {
  ObstacleShape shape = ObstacleShape::Box;
  Vec3 center{0.0};
  Vec3 size{1.0};                             // box: full extents; sphere: x = radius
  std::shared_ptr<const TriangleMesh> mesh;   // Mesh: the closed triangle mesh (shared: it never changes)
  std::string file;                           // Mesh: the OBJ file as the model file names it
};

const char* obstacleShapeName(ObstacleShape shape);

// A ball holding the whole obstacle: what lies outside it cannot touch the obstacle. Radius < 0: nothing to touch.
struct Ball {
  Vec3 center{0.0};
  double radius = -1;
};
Ball boundingBall(const Obstacle& obstacle);

bool insideObstacle(const Obstacle& obstacle, const Vec3& p);

// Whether the segment a-b enters the obstacle (touching its boundary counts).
bool segmentHitsObstacle(const Obstacle& obstacle, const Vec3& a, const Vec3& b);

}  // namespace arbor::sc
