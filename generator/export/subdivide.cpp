#include "subdivide.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <opensubdiv/far/primvarRefiner.h>

#include "common/input_error.hpp"
#include "export_checks.hpp"
#include "mesh/osd_topology.hpp"

namespace arbor {

namespace {

namespace Far = OpenSubdiv::Far;

// Channel layout of Primvar: everything shares the vertex weights, so one pass per level refines it all.
constexpr int kPosition = 0, kUvw = 3, kRadius = 6, kLevel = 7, kTangent = 8, kChannels = 11;

struct Primvar {
  std::array<float, kChannels> c{};

  // The two members OpenSubdiv's PrimvarRefiner calls on source and destination values.
  void Clear(void* = nullptr) { c.fill(0.0f); }
  void AddWithWeight(const Primvar& source, float weight) {
    for (int i = 0; i < kChannels; ++i) c[i] += weight * source.c[i];
  }

  glm::vec3 vec3(int first) const { return {c[first], c[first + 1], c[first + 2]}; }
  void setVec3(int first, const glm::vec3& v) {
    c[first] = v.x;
    c[first + 1] = v.y;
    c[first + 2] = v.z;
  }
};

// Each boundary edge splits in two, so the refined ring alternates a vertex's child and its edge's child.
std::vector<std::uint32_t> refineBoundary(const Far::TopologyRefiner& refiner, std::vector<std::uint32_t> ring, int levels) {
  if (ring.empty()) return ring;
  const Far::TopologyLevel& base = refiner.GetLevel(0);
  if (ring.size() < 3) throw std::invalid_argument("subdivide: openBoundary needs at least 3 vertices");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::uint32_t a = ring[i], b = ring[(i + 1) % ring.size()];
    if (a >= static_cast<std::uint32_t>(base.GetNumVertices()) || b >= static_cast<std::uint32_t>(base.GetNumVertices())) {
      throw std::invalid_argument("subdivide: openBoundary refers past the last vertex");
    }
    const Far::Index e = base.FindEdge(static_cast<Far::Index>(a), static_cast<Far::Index>(b));
    if (e == Far::INDEX_INVALID || !base.IsEdgeBoundary(e)) {
      throw std::invalid_argument("subdivide: openBoundary vertices " + std::to_string(a) + " and " + std::to_string(b) +
                                  " are not joined by a boundary edge");
    }
  }
  for (int l = 0; l < levels; ++l) {
    const Far::TopologyLevel& level = refiner.GetLevel(l);
    std::vector<std::uint32_t> finer;
    finer.reserve(ring.size() * 2);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto a = static_cast<Far::Index>(ring[i]), b = static_cast<Far::Index>(ring[(i + 1) % ring.size()]);
      finer.push_back(static_cast<std::uint32_t>(level.GetVertexChildVertex(a)));
      finer.push_back(static_cast<std::uint32_t>(level.GetEdgeChildVertex(level.FindEdge(a, b))));
    }
    ring = std::move(finer);
  }
  return ring;
}

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return (length > 1e-12f && std::isfinite(length)) ? v / length : fallback;
}

glm::vec3 perpendicularTo(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, axis));
}

// The part of `t` at right angles to the unit normal; a `t` almost along the normal leaves only noise.
glm::vec3 tangentOr(const glm::vec3& t, const glm::vec3& normal, const glm::vec3& fallback) {
  const glm::vec3 inPlane = t - normal * glm::dot(normal, t);
  if (!(glm::length(inPlane) > 1e-3f * glm::length(t))) return fallback;
  const glm::vec3 once = unitOr(inPlane, fallback);
  return unitOr(once - normal * glm::dot(normal, once), fallback);  // again, for what cancellation left over
}

// Direction of steepest increase of texture v on the surface, from the limit derivatives along s and t.
glm::vec3 gradientOfV(const Primvar& ds, const Primvar& dt) {
  const glm::vec3 a = ds.vec3(kPosition), b = dt.vec3(kPosition);
  const float vs = ds.c[kUvw + 1], vt = dt.c[kUvw + 1];
  const float aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
  return (bb * vs - ab * vt) * a + (aa * vt - ab * vs) * b;  // inverse metric times (vs, vt), scaled by its determinant
}

}  // namespace

QuadMesh subdivide(const QuadMesh& mesh, int levels, std::size_t maxQuads) {
  if (levels < 1 || levels > 6) throw std::invalid_argument("subdivide: levels must be 1..6, got " + std::to_string(levels));
  const double result = static_cast<double>(mesh.quads.size()) * std::pow(4.0, levels);
  if (result > static_cast<double>(maxQuads)) {
    throw LimitError(std::to_string(mesh.quads.size()) + " quads subdivided " + std::to_string(levels) + " times would be " +
                     std::to_string(static_cast<std::uint64_t>(result)) + " quads, more than the limit of " + std::to_string(maxQuads) +
                     "; subdivide fewer times or mesh fewer levels");
  }
  const char* context = "subdivide";
  exporting::requirePerVertex(mesh, mesh.tangents.size(), "tangents", context);
  exporting::requirePerVertex(mesh, mesh.uvw.size(), "uvw", context);
  exporting::requirePerVertex(mesh, mesh.radius.size(), "radii", context);
  exporting::requirePerVertex(mesh, mesh.level.size(), "levels", context);
  const auto refiner = makeTopologyRefiner(mesh, context);
  const detail::OsdDiagnostics diagnostics;

  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;  // limit evaluation needs the last level's edges and vertex faces
  refiner->RefineUniform(uniform);
  diagnostics.throwIfReported(context, "refinement");
  std::vector<std::uint32_t> boundary = refineBoundary(*refiner, mesh.openBoundary, levels);

  std::vector<Primvar> current(mesh.vertexCount());
  for (std::size_t i = 0; i < current.size(); ++i) {
    Primvar& p = current[i];
    p.setVec3(kPosition, mesh.positions[i]);
    p.setVec3(kUvw, mesh.uvw[i]);
    p.c[kRadius] = mesh.radius[i];
    p.c[kLevel] = static_cast<float>(mesh.level[i]);
    p.setVec3(kTangent, mesh.tangents[i]);
  }
  const Far::PrimvarRefiner primvars(*refiner);
  for (int l = 1; l <= levels; ++l) {
    std::vector<Primvar> finer(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()));
    primvars.Interpolate(l, current, finer);
    current = std::move(finer);
  }
  std::vector<Primvar> limit(current.size()), ds(current.size()), dt(current.size());
  primvars.Limit(current, limit, ds, dt);
  diagnostics.throwIfReported(context, "limit evaluation");

  const Far::TopologyLevel& fine = refiner->GetLevel(levels);
  QuadMesh out;
  out.quads.reserve(static_cast<std::size_t>(fine.GetNumFaces()));
  for (Far::Index f = 0; f < fine.GetNumFaces(); ++f) {
    const auto v = fine.GetFaceVertices(f);
    out.quads.push_back({static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[1]), static_cast<std::uint32_t>(v[2]),
                         static_cast<std::uint32_t>(v[3])});
  }

  const std::size_t n = current.size();
  out.positions.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.positions[i] = limit[i].vec3(kPosition);
  // Where the limit tangents degenerate, the refined faces around the vertex still know which way is out.
  std::vector<glm::vec3> faceNormals(n, glm::vec3(0));
  for (const auto& q : out.quads) {
    const auto& p = out.positions;
    const glm::vec3 normal = glm::cross(p[q[2]] - p[q[0]], p[q[3]] - p[q[1]]);
    for (const std::uint32_t v : q) faceNormals[v] += normal;
  }

  out.normals.resize(n);
  out.tangents.resize(n);
  out.uvw.resize(n);
  out.radius.resize(n);
  out.level.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    // OpenSubdiv's first and second limit tangents follow the face winding, so their cross product points out.
    const glm::vec3 normal = unitOr(glm::cross(ds[i].vec3(kPosition), dt[i].vec3(kPosition)),
                                    unitOr(faceNormals[i], glm::vec3(0, 0, 1)));
    const glm::vec3 along = limit[i].vec3(kTangent);
    const glm::vec3 vGradient = gradientOfV(ds[i], dt[i]);
    out.normals[i] = normal;
    out.tangents[i] = tangentOr(along, normal, tangentOr(vGradient, normal, perpendicularTo(normal)));
    out.uvw[i] = current[i].vec3(kUvw);
    out.radius[i] = current[i].c[kRadius];
    out.level[i] = static_cast<std::uint8_t>(std::lround(std::clamp(current[i].c[kLevel], 0.0f, 255.0f)));
  }
  out.openBoundary = std::move(boundary);
  return out;
}

}  // namespace arbor
