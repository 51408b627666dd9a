#pragma once
// Curved PN triangles (Vlachos, Peters, Boyd & Mitchell 2001) on the CPU: from a triangle's corners and unit
// vertex normals, the ten points of a cubic Bezier triangle and the three mid-edge normals of the quadratic
// normal field. The reference pn_control.comp is tested against; keep the two in the same order.
#include <array>

#include <glm/vec3.hpp>

namespace arbor {

struct PnTriangle {
  // b300 b030 b003 (the corners), b210 b120 b021 b012 b102 b201, b111; exponents of the weights of corners 0, 1, 2.
  std::array<glm::dvec3, 10> points;
  std::array<glm::dvec3, 3> edgeNormals;  // n110 n011 n101, unit
};

// `normal`: unit vertex normals.
PnTriangle pnTriangle(const std::array<glm::dvec3, 3>& position, const std::array<glm::dvec3, 3>& normal);

}  // namespace arbor
