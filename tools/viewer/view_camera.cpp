#include "view_camera.hpp"

#include <algorithm>
#include <cmath>


namespace arbor::viewer {

namespace {

glm::vec3 lookDirection(float yaw, float pitch) {
  return {std::sin(yaw) * std::cos(pitch), std::cos(yaw) * std::cos(pitch), std::sin(pitch)};
}

}  // namespace

ViewCamera ViewCamera::lookingAt(const render::Camera& camera, bool orbit) {
  ViewCamera v;
  v.orbit = orbit;
  const glm::vec3 d = camera.target - camera.eye;
  const float length = std::max(glm::length(d), 1e-3f);
  v.position = camera.eye;
  v.target = camera.target;
  v.distance = length;
  v.yaw = std::atan2(d.x, d.y);
  v.pitch = std::asin(std::clamp(d.z / length, -1.0f, 1.0f));
  v.fovY = camera.fovY;
  return v;
}

void ViewCamera::update(const WalkInput& in, float seconds, float sceneSize) {
  constexpr float kRadiansPerPixel = 0.004f;
  yaw += in.lookX * kRadiansPerPixel;
  pitch = std::clamp(pitch - in.lookY * kRadiansPerPixel, -1.5f, 1.5f);
  const float speed = (in.fast ? 4.0f : 1.0f) * std::max(2.0f, 0.15f * sceneSize);  // metres per second
  if (orbit) {
    distance = std::clamp(distance * std::pow(0.9f, in.zoom) * (1.0f - in.forward * seconds), 0.5f, 20.0f * sceneSize + 10.0f);
    const glm::vec3 flatRight(std::cos(yaw), -std::sin(yaw), 0.0f);
    target += (flatRight * in.right + glm::vec3(0, 0, 1) * in.up) * speed * seconds;
    position = target - lookDirection(yaw, pitch) * distance;
    return;
  }
  const glm::vec3 forward = lookDirection(yaw, pitch), right(std::cos(yaw), -std::sin(yaw), 0.0f);
  position += (forward * in.forward + right * in.right + glm::vec3(0, 0, 1) * in.up) * speed * seconds;
  position.z = std::max(position.z, 0.3f);  // stay above the ground
  target = position + forward * distance;
}

render::Camera ViewCamera::camera() const {
  render::Camera c;
  c.eye = orbit ? target - lookDirection(yaw, pitch) * distance : position;
  c.target = orbit ? target : position + lookDirection(yaw, pitch);
  c.fovY = fovY;
  return c;
}

render::Camera cameraOnPath(const std::vector<render::Camera>& keys, int frame, int frames) {
  if (keys.size() == 1 || frames <= 1) return keys.front();
  const float t = static_cast<float>(frame) / static_cast<float>(frames - 1) * static_cast<float>(keys.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(t), keys.size() - 2);
  const float f = t - static_cast<float>(i);
  render::Camera c = keys[i];
  c.eye = glm::mix(keys[i].eye, keys[i + 1].eye, f);
  c.target = glm::mix(keys[i].target, keys[i + 1].target, f);
  c.fovY = glm::mix(keys[i].fovY, keys[i + 1].fovY, f);
  return c;
}

}  // namespace arbor::viewer
