#include "mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

namespace arbor {

namespace {

struct HalfEdge {
  std::uint64_t key;  // min, max vertex
  std::uint32_t from, face;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

int findRoot(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}

}  // namespace

MeshTopologyReport checkTopology(const QuadMesh& mesh) {
  MeshTopologyReport r;
  const auto& quads = mesh.quads;
  std::vector<HalfEdge> edges;
  edges.reserve(quads.size() * 4);
  for (std::uint32_t f = 0; f < quads.size(); ++f) {
    const auto& q = quads[f];
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t a = q[static_cast<std::size_t>(k)], b = q[static_cast<std::size_t>((k + 1) % 4)];
      edges.push_back(HalfEdge{edgeKey(a, b), a, f});
    }
    // Degenerate: a repeated corner, or an area tiny against the longest edge (a sliver).
    bool repeated = false;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) repeated = repeated || q[static_cast<std::size_t>(i)] == q[static_cast<std::size_t>(j)];
    const glm::dvec3 p0(mesh.positions[q[0]]), p1(mesh.positions[q[1]]), p2(mesh.positions[q[2]]), p3(mesh.positions[q[3]]);
    const double area = 0.5 * glm::length(glm::cross(p2 - p0, p3 - p1));
    const double longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p3 - p2), glm::length(p0 - p3)});
    if (repeated || area <= 1e-4 * longest * longest) ++r.degenerateFaces;
    r.signedVolume += (glm::dot(p0, glm::cross(p1, p2)) + glm::dot(p0, glm::cross(p2, p3))) / 6.0;
  }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& a, const HalfEdge& b) { return a.key < b.key; });
  std::vector<int> valence(mesh.positions.size(), 0);
  std::size_t edgeCount = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    const std::size_t count = j - i;
    ++edgeCount;
    ++valence[static_cast<std::size_t>(edges[i].key >> 32)];
    ++valence[static_cast<std::size_t>(edges[i].key & 0xffffffffu)];
    if (count == 1) ++r.boundaryEdges;
    else if (count > 2) ++r.nonManifoldEdges;
    else if (edges[i].from == edges[i + 1].from) ++r.misorientedEdges;
    i = j;
  }

  // Connected pieces, through shared vertices.
  std::vector<int> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> used(mesh.positions.size(), false);
  for (const auto& q : quads) {
    for (std::uint32_t v : q) used[v] = true;
    for (int k = 1; k < 4; ++k) {
      const int a = findRoot(parent, static_cast<int>(q[0])), b = findRoot(parent, static_cast<int>(q[static_cast<std::size_t>(k)]));
      if (a != b) parent[static_cast<std::size_t>(a)] = b;
    }
  }
  std::size_t vertices = 0;
  r.minValence = 1 << 30;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    ++vertices;
    if (findRoot(parent, static_cast<int>(v)) == static_cast<int>(v)) ++r.components;
    r.minValence = std::min(r.minValence, valence[v]);
    r.maxValence = std::max(r.maxValence, valence[v]);
  }
  if (vertices == 0) r.minValence = 0;

  // Vertex manifoldness: walking from one incident face across shared edges must reach all of them.
  std::vector<std::vector<std::uint32_t>> facesAt(mesh.positions.size());
  for (std::uint32_t f = 0; f < quads.size(); ++f)
    for (std::uint32_t v : quads[f]) facesAt[v].push_back(f);
  for (std::size_t v = 0; v < facesAt.size(); ++v) {
    const auto& fs = facesAt[v];
    if (fs.size() < 2) continue;
    std::vector<bool> seen(fs.size(), false);
    std::vector<std::size_t> stack{0};
    seen[0] = true;
    std::size_t reached = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for (std::size_t j = 0; j < fs.size(); ++j) {
        if (seen[j]) continue;
        // Faces i and j are neighbours around v when they share an edge through v.
        int shared = 0;
        for (std::uint32_t a : quads[fs[i]])
          for (std::uint32_t b : quads[fs[j]]) shared += (a == b && a != v) ? 1 : 0;
        if (shared > 0) {
          seen[j] = true;
          ++reached;
          stack.push_back(j);
        }
      }
    }
    if (reached != fs.size()) ++r.nonManifoldVertices;
  }
  r.eulerCharacteristic = static_cast<int>(vertices) - static_cast<int>(edgeCount) + static_cast<int>(quads.size());
  return r;
}

namespace {

using V = glm::dvec3;

// Whether segment pq crosses triangle abc (Moller-Trumbore, both parameters strictly inside).
bool segmentHitsTriangle(const V& p, const V& q, const V& a, const V& b, const V& c) {
  const V dir = q - p, e1 = b - a, e2 = c - a;
  const V h = glm::cross(dir, e2);
  const double det = glm::dot(e1, h);
  if (std::fabs(det) < 1e-18) return false;
  const double inv = 1.0 / det;
  const V s = p - a;
  const double u = glm::dot(s, h) * inv;
  if (u <= 1e-9 || u >= 1.0 - 1e-9) return false;
  const V qv = glm::cross(s, e1);
  const double v = glm::dot(dir, qv) * inv;
  if (v <= 1e-9 || u + v >= 1.0 - 1e-9) return false;
  const double t = glm::dot(e2, qv) * inv;
  return t > 1e-9 && t < 1.0 - 1e-9;
}

// All of t strictly on one side of the plane of s: they cannot meet (the usual early out).
bool oneSide(const std::array<V, 3>& t, const std::array<V, 3>& s) {
  const V n = glm::cross(s[1] - s[0], s[2] - s[0]);
  const double a = glm::dot(n, t[0] - s[0]), b = glm::dot(n, t[1] - s[0]), c = glm::dot(n, t[2] - s[0]);
  return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
}

// Whether an edge of either triangle passes through the other (the test past the planes' early out).
bool edgesCross(const std::array<V, 3>& t, const std::array<V, 3>& s) {
  for (int i = 0; i < 3; ++i) {
    if (segmentHitsTriangle(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)], s[0], s[1], s[2])) return true;
    if (segmentHitsTriangle(s[static_cast<std::size_t>(i)], s[static_cast<std::size_t>((i + 1) % 3)], t[0], t[1], t[2])) return true;
  }
  return false;
}

bool trianglesIntersect(const std::array<V, 3>& t, const std::array<V, 3>& s) {
  return !oneSide(t, s) && !oneSide(s, t) && edgesCross(t, s);
}

// Signed distances (times the normal's length) of the corners p to the planes of q's two triangles, q0 q1 q2 and
// q0 q2 q3: the same numbers oneSide computes for each pair of triangles.
std::array<std::array<double, 4>, 2> planeHeights(const std::array<V, 4>& q, const std::array<V, 4>& p) {
  const std::array<V, 2> n{glm::cross(q[1] - q[0], q[2] - q[0]), glm::cross(q[2] - q[0], q[3] - q[0])};
  std::array<std::array<double, 4>, 2> h{};
  for (std::size_t t = 0; t < 2; ++t)
    for (std::size_t k = 0; k < 4; ++k) h[t][k] = glm::dot(n[t], p[k] - q[0]);
  return h;
}

}  // namespace

bool quadsIntersect(const std::array<glm::dvec3, 4>& a, const std::array<glm::dvec3, 4>& b) {
  // Each triangle's plane once for all four pairs of triangles (the early out is most of the calls).
  constexpr std::array<std::array<std::size_t, 3>, 2> corners{{{0, 1, 2}, {0, 2, 3}}};
  const auto aOnB = planeHeights(b, a), bOnA = planeHeights(a, b);
  auto oneSideOf = [&](const std::array<double, 4>& h, std::size_t t) {
    const double x = h[corners[t][0]], y = h[corners[t][1]], z = h[corners[t][2]];
    return (x > 0 && y > 0 && z > 0) || (x < 0 && y < 0 && z < 0);
  };
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t j = 0; j < 2; ++j) {
      if (oneSideOf(aOnB[j], i) || oneSideOf(bOnA[i], j)) continue;
      const std::array<V, 3> t{a[corners[i][0]], a[corners[i][1]], a[corners[i][2]]};
      const std::array<V, 3> s{b[corners[j][0]], b[corners[j][1]], b[corners[j][2]]};
      if (edgesCross(t, s)) return true;
    }
  }
  return false;
}

std::vector<std::uint32_t> facesNear(const QuadMesh& mesh, const glm::vec3& center, float radius) {
  std::vector<std::uint32_t> near;
  for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
    for (std::uint32_t v : mesh.quads[f]) {
      if (glm::distance(mesh.positions[v], center) < radius) {
        near.push_back(static_cast<std::uint32_t>(f));
        break;
      }
    }
  }
  return near;
}

std::size_t intersectingFacePairs(const QuadMesh& mesh, const std::vector<std::uint32_t>& a,
                                  const std::vector<std::uint32_t>& b) {
  auto tris = [&](std::uint32_t f) {
    const auto& q = mesh.quads[f];
    auto P = [&](int k) { return V(mesh.positions[q[static_cast<std::size_t>(k)]]); };
    return std::array<std::array<V, 3>, 2>{{{P(0), P(1), P(2)}, {P(0), P(2), P(3)}}};
  };
  std::size_t count = 0;
  for (std::uint32_t fa : a) {
    for (std::uint32_t fb : b) {
      if (fa == fb) continue;
      bool sharesVertex = false;
      for (std::uint32_t x : mesh.quads[fa])
        for (std::uint32_t y : mesh.quads[fb]) sharesVertex = sharesVertex || x == y;
      if (sharesVertex) continue;
      bool hit = false;
      for (const auto& t : tris(fa))
        for (const auto& s : tris(fb)) hit = hit || trianglesIntersect(t, s);
      count += hit ? 1 : 0;
    }
  }
  return count;
}

}  // namespace arbor
