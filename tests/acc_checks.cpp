#include "acc_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <opensubdiv/far/primvarRefiner.h>

#include "mesh/osd_topology.hpp"
#include "patches/acc.hpp"
#include "test_support.hpp"

namespace arbor::test {

namespace {

// (u, v) of the point a fraction t along patch edge `edge`, which runs from corner edge to corner edge + 1.
glm::dvec2 edgeParameter(int edge, double t) {
  switch (edge) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {1.0 - t, 1.0};
    default: return {0.0, 1.0 - t};
  }
}

constexpr std::array<glm::dvec2, 4> kCornerUv{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
constexpr std::array<std::size_t, 4> kCornerSlot{0, 3, 15, 12};  // corner i's point in the 4 x 4 grid

// A primvar for OpenSubdiv's PrimvarRefiner, which builds results by weighted sums.
struct LimitPoint {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const LimitPoint& source, double weight) { p += weight * source.p; }
};

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The larger of two errors; a NaN one (a zero normal or tangent) is the worst there is.
double worse(double worst, double error) { return std::isnan(error) ? 1e300 : std::max(worst, error); }

}  // namespace

double patchRadius(const QuadMesh& mesh, std::size_t patch) {
  return std::max(1e-6, static_cast<double>(mesh.radius[mesh.quads[patch][0]]));
}

AccCrackCheck accCracks(const QuadMesh& mesh, const PatchSet& set) {
  std::vector<AccPatch> acc;
  acc.reserve(set.size());
  for (std::size_t p = 0; p < set.size(); ++p) acc.push_back(buildAccPatch(mesh, set, p));
  // Directed edge a -> b (patch p's edge i runs from its corner i to corner i + 1) -> (patch, edge).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::size_t, int>> edges;
  for (std::size_t p = 0; p < set.size(); ++p)
    for (int i = 0; i < 4; ++i)
      edges[{mesh.quads[p][static_cast<std::size_t>(i)], mesh.quads[p][static_cast<std::size_t>((i + 1) % 4)]}] = {p, i};
  AccCrackCheck r;
  for (const auto& [edge, side] : edges) {
    const auto other = edges.find({edge.second, edge.first});
    if (other == edges.end()) {
      ++r.unpaired;
      continue;
    }
    if (edge.first > edge.second) continue;  // each shared edge once
    const auto [p, i] = side;
    const auto [q, j] = other->second;
    for (double t : {0.0, 0.2, 0.5, 0.7, 1.0}) {
      // Fraction t from a towards b on p is fraction 1 - t from b towards a on q, the other way round.
      const glm::dvec2 a = edgeParameter(i, t), b = edgeParameter(j, 1.0 - t);
      const double d = glm::distance(evaluateBezier(acc[p].geometry, a.x, a.y), evaluateBezier(acc[q].geometry, b.x, b.y));
      r.worst = worse(r.worst, d / patchRadius(mesh, p));
    }
    ++r.sharedEdges;
  }
  return r;
}

AccCornerCheck accCorners(const QuadMesh& mesh, const PatchSet& set, std::size_t stride) {
  // OpenSubdiv's exact limit position and tangents of every vertex, from its Catmull-Clark limit masks.
  const auto refiner = makeTopologyRefiner(mesh, "test");
  std::vector<LimitPoint> source(mesh.vertexCount()), position(source.size()), tangent1(source.size()), tangent2(source.size());
  for (std::size_t v = 0; v < source.size(); ++v) source[v].p = glm::dvec3(mesh.positions[v]);
  OpenSubdiv::Far::PrimvarRefinerReal<double>(*refiner).Limit(source, position, tangent1, tangent2);

  AccCornerCheck r;
  for (std::size_t p = 0; p < set.size(); p += std::max<std::size_t>(1, stride)) {
    const AccPatch acc = buildAccPatch(mesh, set, p);
    for (const glm::dvec3& point : acc.geometry) r.finite = r.finite && finite(point);
    const double radius = patchRadius(mesh, p);
    for (std::size_t i = 0; i < 4; ++i) {
      const std::uint32_t vertex = mesh.quads[p][i];
      const glm::dvec3& n = acc.cornerNormal[i];
      r.finite = r.finite && finite(n);
      r.worstPosition = worse(r.worstPosition, glm::distance(acc.geometry[kCornerSlot[i]], position[vertex].p) / radius);
      r.worstNormal = worse(r.worstNormal, angleBetween(n, glm::cross(tangent1[vertex].p, tangent2[vertex].p)));
      r.worstUnit = worse(r.worstUnit, std::abs(glm::length(n) - 1.0));
      r.worstBlend = worse(r.worstBlend, angleBetween(accNormal(acc, kCornerUv[i].x, kCornerUv[i].y), n));
      ++r.valences[std::min<std::size_t>(set.valence[p][i], 6)];
      ++r.corners;
    }
  }
  return r;
}

}  // namespace arbor::test
