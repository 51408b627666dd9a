#pragma once
// Cameras for the tree: z is up; Vulkan's clip space (y down, depth 0..1).
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "mesh/quad_mesh.hpp"

namespace arbor::render {

struct Bounds {
  glm::vec3 lo{0.0f}, hi{0.0f};
};

struct Camera {
  glm::vec3 eye{0.0f, -10.0f, 2.0f};
  glm::vec3 target{0.0f};
  float fovY = 0.7f;  // radians
  float nearPlane = 0.05f, farPlane = 2000.0f;
};

Bounds meshBounds(const QuadMesh& mesh);
// +z, or +y when the camera looks straight up or down.
glm::vec3 upVector(const Camera& camera);
glm::mat4 viewMatrix(const Camera& camera);
glm::mat4 projectionMatrix(const Camera& camera, float aspect);

// A camera that sees all of `bounds` from the given azimuth and elevation (degrees), with a margin.
Camera frameBounds(const Bounds& bounds, float azimuthDegrees, float elevationDegrees, float aspect, float margin = 1.08f);

// "ex,ey,ez,tx,ty,tz[,fovDegrees]"; throws std::invalid_argument with what is wrong.
Camera parseCamera(const std::string& text);

// Unit vector towards a sun at this azimuth and elevation (degrees), the azimuth measured like frameBounds'
// (0: from -y, where the default camera stands).
glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees);

}  // namespace arbor::render
