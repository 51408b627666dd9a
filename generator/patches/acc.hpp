#pragma once
// Loop & Schaefer's approximate Catmull-Clark (ACC, 2008) on the CPU: one bicubic Bezier patch per quad
// plus the exact limit normals at its corners. This is the reference the tessellation control shader
// mirrors operation for operation, so keep the order of the arithmetic when changing anything here.
//
// For corner i of a patch (vertex v, valence n, ring e_0 f_0 e_1 f_1 ... from cornerRing, face k around the
// corner being (v, e_k, f_k, e_(k+1))):
//   I_k = (n v + 2 e_k + 2 e_(k+1) + f_k) / (n + 5)     interior point of face k
//   C = (1/n) sum_k I_k                                 the limit position
//   E_next = (I_0 + I_(n-1)) / 2                        edge point towards corner i + 1 (along e_0)
//   E_prev = (I_0 + I_1) / 2                            edge point towards corner i + 3 (along e_1)
// and I_0 is the patch's interior point at that corner. With all valences 4 this is exactly the
// B-spline -> Bezier conversion, so regular patches are the exact limit surface.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/quad_mesh.hpp"
#include "patch_set.hpp"

namespace arbor {

struct AccPatch {
  std::array<glm::dvec3, 16> geometry;      // Bezier points [row * 4 + column]: column along corner 0 -> 1 (u),
                                            // row along corner 0 -> 3 (v)
  std::array<glm::dvec3, 4> cornerNormal;   // exact Catmull-Clark limit normals (unit, outwards)
};

struct BezierDerivatives {
  glm::dvec3 position{0.0}, du{0.0}, dv{0.0};
};

// The 16 Bezier points of `patch` (Regular or Extraordinary) built from any per-vertex attribute: positions
// for the geometry, and the GPU treats texture coordinates and radius the same way. Throws
// std::invalid_argument for a Fallback patch.
std::array<glm::dvec3, 16> accControlPoints(const PatchSet& patches, std::size_t patch,
                                            const std::function<glm::dvec3(std::uint32_t)>& attribute);

// Unit limit normal of corner `corner` from Catmull-Clark's limit tangent masks (outwards for the
// counter-clockwise rings of cornerRing).
glm::dvec3 accCornerNormal(const PatchSet& patches, std::size_t patch, int corner,
                           const std::function<glm::dvec3(std::uint32_t)>& position);

// Every vertex at its Catmull-Clark limit position with its limit normal: what ACC draws at tessellation factor 1
// (two triangles per quad through the corners), for drawing far trees without the tessellator. Vertices only in
// fallback patches keep their control position and normal.
struct LimitVertices {
  std::vector<glm::vec3> positions, normals;
};
LimitVertices limitVertices(const QuadMesh& mesh, const PatchSet& patches);

// Geometry and corner normals from the mesh positions. Throws std::invalid_argument for a Fallback patch.
AccPatch buildAccPatch(const QuadMesh& mesh, const PatchSet& patches, std::size_t patch);

// Bicubic Bezier patch at (u, v), and with its first derivatives.
glm::dvec3 evaluateBezier(const std::array<glm::dvec3, 16>& points, double u, double v);
BezierDerivatives evaluateBezierDerivatives(const std::array<glm::dvec3, 16>& points, double u, double v);

// Shading normal: the geometry patch's normal with each corner's correction (exact corner normal minus the
// geometry patch's normal at that corner) blended in by w_i = that corner's bicubic Bernstein product:
// B0(u) B0(v) = (1-u)^3 (1-v)^3 for corner 0, u^3 (1-v)^3 for corner 1, u^3 v^3 for corner 2, (1-u)^3 v^3 for
// corner 3. w_i is 1 at corner i and 0 at the other three corners and on the two edges away from it, so the
// result is the exact normal at every corner, the geometry normal along the far edges, and exactly the
// geometry normal everywhere on a regular patch (no correction). Normalised.
glm::dvec3 accNormal(const AccPatch& patch, double u, double v);

}  // namespace arbor
