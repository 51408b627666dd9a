#pragma once
// Double-precision vector types for generation (GLM), and a rigid transform value type.
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace arbor {

using Vec3 = glm::dvec3;
using Quat = glm::dquat;

constexpr Vec3 kUp{0.0, 0.0, 1.0};

// A frame: rotation maps local axes (z = stem direction) to the parent's, then position offsets it.
struct Transform {
  Vec3 position{0.0};
  Quat rotation{1.0, 0.0, 0.0, 0.0};

  Vec3 direction() const { return rotation * Vec3(0.0, 0.0, 1.0); }
  Vec3 apply(const Vec3& p) const { return position + rotation * p; }
};

// a then b: b expressed in a's frame, composed into a's parent frame.
inline Transform compose(const Transform& a, const Transform& b) {
  return Transform{a.position + a.rotation * b.position, a.rotation * b.rotation};
}

inline Transform inverse(const Transform& t) {
  const Quat inv = glm::conjugate(t.rotation);
  return Transform{inv * -t.position, inv};
}

inline Quat rotationX(double angle) { return glm::angleAxis(angle, Vec3(1.0, 0.0, 0.0)); }
inline Quat rotationZ(double angle) { return glm::angleAxis(angle, Vec3(0.0, 0.0, 1.0)); }

constexpr double radians(double degrees) { return degrees * 0.017453292519943295; }
constexpr double degrees(double radians) { return radians * 57.29577951308232; }

}  // namespace arbor
