#pragma once
// The exact Catmull-Clark limit surface of a quad mesh, evaluated by OpenSubdiv's Bfr::Surface: the
// reference against which the patches and the GPU's approximation are measured.
#include <array>
#include <memory>

#include <glm/vec3.hpp>

#include "mesh/quad_mesh.hpp"

namespace arbor {

class LimitSurface {
 public:
  explicit LimitSurface(const QuadMesh& mesh);
  ~LimitSurface();
  LimitSurface(const LimitSurface&) = delete;
  LimitSurface& operator=(const LimitSurface&) = delete;

  // Limit position (and, if asked, unit normal) of face `face` at (u, v): corner 0 at (0, 0), corner 1 at
  // (1, 0), corner 3 at (0, 1).
  glm::dvec3 position(int face, double u, double v, glm::dvec3* normal = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Uniform cubic B-spline patch from a 4 x 4 grid (index [row * 4 + column]) at (u, v).
glm::dvec3 evaluateBSpline(const std::array<glm::dvec3, 16>& grid, double u, double v);

}  // namespace arbor
