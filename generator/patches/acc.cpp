#include "acc.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

namespace arbor {

namespace {

// Where corner i's C, E_next, E_prev and I_0 go in the grid (row * 4 + column), corners 0..3 at (0,0), (0,3),
// (3,3), (3,0).
constexpr std::array<std::array<std::size_t, 4>, 4> kCornerSlots{{
    {0, 1, 4, 5},
    {3, 7, 2, 6},
    {15, 14, 11, 10},
    {12, 8, 13, 9},
}};

void requireRings(const PatchSet& patches, std::size_t patch, const char* what) {
  if (patch >= patches.size()) throw std::invalid_argument(std::string(what) + ": patch index out of range");
  if (patches.kind[patch] == PatchKind::Fallback) throw std::invalid_argument(std::string(what) + ": a fallback patch has no ACC form");
}

std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

std::array<double, 4> bernsteinDerivative(double t) {
  const double s = 1.0 - t;
  return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

// Loop & Schaefer's interior points around corner i: (n v + 2 e_k + 2 e_k+1 + f_k) / (n + 5); their mean is the
// corner's Catmull-Clark limit position.
std::vector<glm::dvec3> cornerInterior(const PatchSet& patches, std::size_t patch, int i,
                                       const std::function<glm::dvec3(std::uint32_t)>& attribute) {
  const std::vector<std::uint32_t> ring = cornerRing(patches, patch, i);
  const std::size_t n = patches.valence[patch][static_cast<std::size_t>(i)];
  const double dn = static_cast<double>(n);
  const glm::dvec3 v = attribute(patches.pointsOf(patch)[i]);
  std::vector<glm::dvec3> interior(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec3 e0 = attribute(ring[2 * k]), f = attribute(ring[2 * k + 1]), e1 = attribute(ring[(2 * k + 2) % (2 * n)]);
    interior[k] = (dn * v + 2.0 * e0 + 2.0 * e1 + f) / (dn + 5.0);
  }
  return interior;
}

glm::dvec3 mean(const std::vector<glm::dvec3>& points) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

}  // namespace

LimitVertices limitVertices(const QuadMesh& mesh, const PatchSet& patches) {
  LimitVertices out{mesh.positions, mesh.normals};
  std::vector<bool> done(mesh.vertexCount(), false);
  const auto position = [&mesh](std::uint32_t v) { return glm::dvec3(mesh.positions[v]); };
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches.kind[p] == PatchKind::Fallback) continue;
    for (int corner = 0; corner < 4; ++corner) {
      const std::uint32_t v = patches.pointsOf(p)[static_cast<std::size_t>(corner)];
      if (done[v]) continue;
      done[v] = true;
      out.positions[v] = glm::vec3(mean(cornerInterior(patches, p, corner, position)));
      out.normals[v] = glm::vec3(accCornerNormal(patches, p, corner, position));
    }
  }
  return out;
}

std::array<glm::dvec3, 16> accControlPoints(const PatchSet& patches, std::size_t patch,
                                            const std::function<glm::dvec3(std::uint32_t)>& attribute) {
  requireRings(patches, patch, "accControlPoints");
  std::array<glm::dvec3, 16> grid{};
  for (int i = 0; i < 4; ++i) {
    const std::vector<glm::dvec3> interior = cornerInterior(patches, patch, i, attribute);
    const std::size_t n = interior.size();
    const auto& slot = kCornerSlots[static_cast<std::size_t>(i)];
    grid[slot[0]] = mean(interior);
    grid[slot[1]] = (interior[0] + interior[n - 1]) / 2.0;
    grid[slot[2]] = (interior[0] + interior[1]) / 2.0;
    grid[slot[3]] = interior[0];
  }
  return grid;
}

glm::dvec3 accCornerNormal(const PatchSet& patches, std::size_t patch, int corner,
                           const std::function<glm::dvec3(std::uint32_t)>& position) {
  requireRings(patches, patch, "accCornerNormal");
  const std::vector<std::uint32_t> ring = cornerRing(patches, patch, corner);
  const std::size_t n = patches.valence[patch][static_cast<std::size_t>(corner)];
  const double dn = static_cast<double>(n);
  // Halstead, Kass & DeRose's tangent masks; the centre vertex drops out because the cosines sum to zero.
  const double pi = std::numbers::pi;
  const double a = 1.0 + std::cos(2.0 * pi / dn) + std::cos(pi / dn) * std::sqrt(2.0 * (9.0 + std::cos(2.0 * pi / dn)));
  auto c = [&](std::size_t k) { return std::cos(2.0 * pi * static_cast<double>(k % n) / dn); };
  glm::dvec3 t1(0.0), t2(0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec3 e = position(ring[2 * k]), f = position(ring[2 * k + 1]);
    t1 += a * c(k) * e + (c(k) + c(k + 1)) * f;
    t2 += a * c(k + n - 1) * e + (c(k + n - 1) + c(k)) * f;
  }
  return glm::normalize(glm::cross(t1, t2));
}

AccPatch buildAccPatch(const QuadMesh& mesh, const PatchSet& patches, std::size_t patch) {
  const auto position = [&mesh](std::uint32_t vertex) { return glm::dvec3(mesh.positions[vertex]); };
  AccPatch acc;
  acc.geometry = accControlPoints(patches, patch, position);
  for (int i = 0; i < 4; ++i) acc.cornerNormal[static_cast<std::size_t>(i)] = accCornerNormal(patches, patch, i, position);
  return acc;
}

glm::dvec3 evaluateBezier(const std::array<glm::dvec3, 16>& points, double u, double v) {
  const auto bu = bernstein(u), bv = bernstein(v);
  glm::dvec3 p(0.0);
  for (std::size_t row = 0; row < 4; ++row)
    for (std::size_t column = 0; column < 4; ++column) p += points[row * 4 + column] * (bv[row] * bu[column]);
  return p;
}

BezierDerivatives evaluateBezierDerivatives(const std::array<glm::dvec3, 16>& points, double u, double v) {
  const auto bu = bernstein(u), bv = bernstein(v), du = bernsteinDerivative(u), dv = bernsteinDerivative(v);
  BezierDerivatives d;
  for (std::size_t row = 0; row < 4; ++row) {
    for (std::size_t column = 0; column < 4; ++column) {
      const glm::dvec3& p = points[row * 4 + column];
      d.position += p * (bv[row] * bu[column]);
      d.du += p * (bv[row] * du[column]);
      d.dv += p * (dv[row] * bu[column]);
    }
  }
  return d;
}

glm::dvec3 accNormal(const AccPatch& patch, double u, double v) {
  const BezierDerivatives d = evaluateBezierDerivatives(patch.geometry, u, v);
  const glm::dvec3 geometric = glm::normalize(glm::cross(d.du, d.dv));
  // The geometry patch's own normal at each corner, from the Bezier points' differences there (the common
  // factor 3 of the derivatives drops out in the normalisation).
  const auto& g = patch.geometry;
  const std::array<glm::dvec3, 4> cornerGeometric{
      glm::normalize(glm::cross(g[1] - g[0], g[4] - g[0])), glm::normalize(glm::cross(g[3] - g[2], g[7] - g[3])),
      glm::normalize(glm::cross(g[15] - g[14], g[15] - g[11])), glm::normalize(glm::cross(g[13] - g[12], g[12] - g[8]))};
  const double su = 1.0 - u, sv = 1.0 - v;
  const std::array<double, 4> w{su * su * su * sv * sv * sv, u * u * u * sv * sv * sv, u * u * u * v * v * v,
                                su * su * su * v * v * v};
  // Blend the corrections, not the normals: the surface turns across a patch, so a corner's normal is only
  // right at that corner, while its correction vanishes wherever the geometry is already exact.
  glm::dvec3 n = geometric;
  for (std::size_t i = 0; i < 4; ++i) n += w[i] * (patch.cornerNormal[i] - cornerGeometric[i]);
  return glm::normalize(n);
}

}  // namespace arbor
