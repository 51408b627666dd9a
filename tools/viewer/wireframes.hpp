#pragma once
// The modeller's wireframes as line lists: attraction clouds, obstacles, the live attraction points and the
// branches an obstacle disabled, in the space-colonization model's own coordinates.
#include <vector>

#include "growth/space_colonization/colonizer.hpp"
#include "render/pipelines.hpp"

namespace arbor::viewer {

using Lines = std::vector<render::LineVertex>;

// A colour per cloud index, the same every run; obstacles, disabled branches and the selection have their own.
glm::vec3 cloudColor(std::size_t index);
inline constexpr glm::vec3 kObstacleColor{0.95f, 0.25f, 0.2f};
inline constexpr glm::vec3 kDisabledColor{0.45f, 0.45f, 0.45f};
inline constexpr glm::vec3 kSelectedColor{1.0f, 1.0f, 0.3f};

void addLine(Lines& lines, const Vec3& a, const Vec3& b, const glm::vec3& color);
// Sphere and ellipsoid: three principal ellipses; cone: base circle, a circle halfway up and four lines to the
// apex; box: its twelve edges. `segments` per full circle.
void addCloud(Lines& lines, const sc::AttractionCloud& cloud, const glm::vec3& color, int segments = 48);
// Box: twelve edges; sphere: three great circles; mesh: each edge of its triangles once.
void addObstacle(Lines& lines, const sc::Obstacle& obstacle, const glm::vec3& color, int segments = 48);
// Each live point as a small cross `size` across, in its cloud's colour, darkened.
void addLivePoints(Lines& lines, const sc::Colonizer& colonizer, double size);
// Each disabled node's segment from its parent, grey.
void addDisabledBranches(Lines& lines, const sc::Colonizer& colonizer);

}  // namespace arbor::viewer
