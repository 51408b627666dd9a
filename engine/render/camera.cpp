#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace arbor::render {

Bounds meshBounds(const QuadMesh& mesh) {
  if (mesh.positions.empty()) return {};
  Bounds b{mesh.positions.front(), mesh.positions.front()};
  for (const glm::vec3& p : mesh.positions) {
    b.lo = glm::min(b.lo, p);
    b.hi = glm::max(b.hi, p);
  }
  return b;
}

glm::vec3 upVector(const Camera& c) {
  // Looking straight up or down, z cannot be the up vector (lookAt would divide by zero): +y is.
  const glm::vec3 d = c.target - c.eye;
  const float length = glm::length(d);
  if (length > 0.0f && std::abs(d.z) > 0.9999f * length) return {0.0f, 1.0f, 0.0f};
  return {0.0f, 0.0f, 1.0f};
}

glm::mat4 viewMatrix(const Camera& c) { return glm::lookAt(c.eye, c.target, upVector(c)); }

glm::mat4 projectionMatrix(const Camera& c, float aspect) {
  glm::mat4 p = glm::perspectiveRH_ZO(c.fovY, aspect, c.nearPlane, c.farPlane);
  p[1][1] *= -1.0f;  // Vulkan's y points down
  return p;
}

Camera frameBounds(const Bounds& b, float azimuthDegrees, float elevationDegrees, float aspect, float margin) {
  const glm::vec3 center = 0.5f * (b.lo + b.hi);
  const float radius = std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f);
  const float az = glm::radians(azimuthDegrees), el = glm::radians(elevationDegrees);
  const glm::vec3 back(std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el));
  const glm::vec3 right = std::abs(back.z) > 0.9999f ? glm::vec3(1.0f, 0.0f, 0.0f)  // from straight above or below
                                                      : glm::normalize(glm::cross(-back, glm::vec3(0.0f, 0.0f, 1.0f)));
  const glm::vec3 up = glm::cross(right, -back);
  Camera c;
  c.target = center;
  // The nearest distance at which every corner of the box is inside the view: fits a tall, thin tree far
  // tighter than its bounding sphere would.
  const float tanY = std::tan(0.5f * c.fovY) / margin, tanX = tanY * aspect;
  float distance = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
    const glm::vec3 d = corner - center;
    const float towards = glm::dot(d, back);  // positive: the corner is nearer the camera than the centre
    distance = std::max({distance, std::abs(glm::dot(d, right)) / tanX + towards, std::abs(glm::dot(d, up)) / tanY + towards});
  }
  distance = std::max(distance, 1e-3f);
  c.eye = center + distance * back;
  c.nearPlane = std::max(0.01f, 0.5f * (distance - radius));
  c.farPlane = distance + 4.0f * radius + 500.0f;
  return c;
}

Camera parseCamera(const std::string& text) {
  std::vector<float> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      values.push_back(std::stof(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw std::invalid_argument("'" + item + "' is not a number");
    }
    // NaN would cull every tree and an infinity break the projection; a million metres is past any scene.
    if (!std::isfinite(values.back()) || std::abs(values.back()) > 1e6f) {
      throw std::invalid_argument("'" + item + "' is not allowed; coordinates are finite numbers within 1e6 m");
    }
    if (values.size() > 7) throw std::invalid_argument("expected ex,ey,ez,tx,ty,tz[,fov degrees], got more than 7 numbers");
  }
  if (values.size() != 6 && values.size() != 7) {
    throw std::invalid_argument("expected ex,ey,ez,tx,ty,tz[,fov degrees], got " + std::to_string(values.size()) + " numbers");
  }
  Camera c;
  c.eye = {values[0], values[1], values[2]};
  c.target = {values[3], values[4], values[5]};
  if (values.size() == 7) {
    if (!(values[6] > 1.0f && values[6] < 170.0f)) throw std::invalid_argument("fov must be in (1, 170) degrees");
    c.fovY = glm::radians(values[6]);
  }
  if (glm::length(c.eye - c.target) < 1e-6f) throw std::invalid_argument("the eye and the target coincide");
  c.farPlane = glm::length(c.eye - c.target) * 4.0f + 500.0f;
  return c;
}

glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees) {
  const float a = glm::radians(azimuthDegrees), e = glm::radians(elevationDegrees);
  return {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
}

}  // namespace arbor::render
