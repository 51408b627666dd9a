#include "limit_reference.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include "mesh/osd_topology.hpp"

namespace arbor {

namespace Bfr = OpenSubdiv::Bfr;

struct LimitSurface::Impl {
  std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner;
  std::unique_ptr<Bfr::RefinerSurfaceFactory<>> factory;
  std::vector<double> points;  // mesh positions, xyz per vertex
};

LimitSurface::LimitSurface(const QuadMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->refiner = makeTopologyRefiner(mesh, "limit surface");
  impl_->factory = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*impl_->refiner);
  impl_->points.reserve(mesh.vertexCount() * 3);
  for (const auto& p : mesh.positions) impl_->points.insert(impl_->points.end(), {p.x, p.y, p.z});
}

LimitSurface::~LimitSurface() = default;

glm::dvec3 LimitSurface::position(int face, double u, double v, glm::dvec3* normal) const {
  Bfr::Surface<double> surface;
  if (!impl_->factory->InitVertexSurface<double>(face, &surface) || !surface.IsValid()) {
    throw std::runtime_error("limit surface: face " + std::to_string(face) + " has no limit surface (a hole or boundary)");
  }
  std::vector<double> patchPoints(static_cast<std::size_t>(surface.GetNumPatchPoints()) * 3);
  const Bfr::Surface<double>::PointDescriptor xyz(3);
  surface.PreparePatchPoints(impl_->points.data(), xyz, patchPoints.data(), xyz);
  const double uv[2] = {u, v};
  double p[3], du[3], dv[3];
  surface.Evaluate(uv, patchPoints.data(), xyz, p, du, dv);
  if (normal) *normal = glm::normalize(glm::cross(glm::dvec3(du[0], du[1], du[2]), glm::dvec3(dv[0], dv[1], dv[2])));
  return {p[0], p[1], p[2]};
}

namespace {

std::array<double, 4> bsplineBasis(double t) {
  const double s = 1.0 - t;
  return {s * s * s / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
          (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0};
}

}  // namespace

glm::dvec3 evaluateBSpline(const std::array<glm::dvec3, 16>& grid, double u, double v) {
  const auto bu = bsplineBasis(u), bv = bsplineBasis(v);
  glm::dvec3 p(0.0);
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      p += grid[static_cast<std::size_t>(row * 4 + column)] * (bv[static_cast<std::size_t>(row)] * bu[static_cast<std::size_t>(column)]);
  return p;
}

}  // namespace arbor
