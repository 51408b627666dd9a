#pragma once
// The walkthrough's cameras: first-person (WASD + mouse look) and orbit around a point, and scripted camera
// paths (view_script.hpp) interpolated over the frames.
#include <string>
#include <vector>

#include "render/camera.hpp"

namespace arbor::viewer {

struct WalkInput {
  float forward = 0, right = 0, up = 0;  // -1..1 each
  float lookX = 0, lookY = 0;            // mouse pixels
  float zoom = 0;                        // scroll steps
  bool fast = false;
};

struct ViewCamera {
  bool orbit = false;
  glm::vec3 position{0.0f, -20.0f, 1.7f};  // first person: the eye
  glm::vec3 target{0.0f, 0.0f, 4.0f};      // orbit: the centre
  float yaw = 0.0f, pitch = 0.0f;          // radians; yaw 0 looks along +y
  float distance = 20.0f;                  // orbit
  float fovY = 0.8f;

  static ViewCamera lookingAt(const render::Camera& camera, bool orbit);
  void update(const WalkInput& input, float seconds, float sceneSize);
  render::Camera camera() const;
};

// The camera at frame `frame` of `frames`, moving evenly from the first key to the last.
render::Camera cameraOnPath(const std::vector<render::Camera>& keys, int frame, int frames);

}  // namespace arbor::viewer
