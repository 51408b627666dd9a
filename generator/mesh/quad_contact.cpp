#include "quad_contact.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <glm/geometric.hpp>

namespace arbor {

namespace {

// Distances below this share of the quads' longest edge are contact, not crossing.
constexpr double kRelativeTolerance = 1e-6;
// Coordinates came from floats: anything within a few float steps of the largest coordinate is rounding.
constexpr double kFloatSteps = 4.0 * FLT_EPSILON;
// Two triangles on one edge count as folded only when their dihedral angle has closed to this (radians).
constexpr double kFoldAngle = 1e-3;

struct Triangle {
  std::array<Vec3, 3> p;
  std::array<std::uint32_t, 3> id;
};

std::array<Triangle, 2> split(const QuadCorners& q) {
  auto tri = [&](int i, int j, int k) {
    return Triangle{{q.p[static_cast<std::size_t>(i)], q.p[static_cast<std::size_t>(j)], q.p[static_cast<std::size_t>(k)]},
                    {q.index[static_cast<std::size_t>(i)], q.index[static_cast<std::size_t>(j)], q.index[static_cast<std::size_t>(k)]}};
  };
  // The shorter diagonal, as triangulate() chooses it.
  const Vec3 d02 = q.p[2] - q.p[0], d13 = q.p[3] - q.p[1];
  if (glm::dot(d02, d02) <= glm::dot(d13, d13)) return {tri(0, 1, 2), tri(0, 2, 3)};
  return {tri(0, 1, 3), tri(1, 2, 3)};
}

bool has(const Triangle& t, std::uint32_t id) { return t.id[0] == id || t.id[1] == id || t.id[2] == id; }

// Signed distance of x from the line a-b within the plane of unit normal n: > 0 on the triangle's side
// when a, b run counter-clockwise about n.
double inward(const Vec3& a, const Vec3& b, const Vec3& x, const Vec3& n) {
  const Vec3 e = b - a;
  const double len = glm::length(e);
  return len > 0.0 ? glm::dot(glm::cross(e, x - a), n) / len : -1.0;
}

bool strictlyInside(const Triangle& t, const Vec3& n, const Vec3& x, double tol) {
  return inward(t.p[0], t.p[1], x, n) > tol && inward(t.p[1], t.p[2], x, n) > tol && inward(t.p[2], t.p[0], x, n) > tol;
}

Vec3 unitNormal(const Triangle& t) {
  const Vec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  const double len = glm::length(n);
  return len > 0.0 ? n / len : Vec3(0.0);
}

// Segment p-q crossing the plane of t (both ends clearly on opposite sides) strictly inside t.
std::optional<Vec3> pierces(const Vec3& p, const Vec3& q, const Triangle& t, const Vec3& n, double tol) {
  const double dp = glm::dot(n, p - t.p[0]), dq = glm::dot(n, q - t.p[0]);
  if (!((dp > tol && dq < -tol) || (dp < -tol && dq > tol))) return std::nullopt;
  const Vec3 x = p + (q - p) * (dp / (dp - dq));
  if (!strictlyInside(t, n, x, tol)) return std::nullopt;
  return x;
}

// Triangles in one plane (within tol): they overlap when edges cross properly or an unshared corner of one
// lies strictly inside the other; corners they share touch by construction.
std::optional<Vec3> coplanarOverlap(const Triangle& t, const Triangle& s, const Vec3& n, double tol) {
  for (int i = 0; i < 3; ++i) {
    const std::size_t i0 = static_cast<std::size_t>(i), i1 = static_cast<std::size_t>((i + 1) % 3);
    for (int j = 0; j < 3; ++j) {
      const std::size_t j0 = static_cast<std::size_t>(j), j1 = static_cast<std::size_t>((j + 1) % 3);
      // Edges with a common corner meet there and nowhere else unless they overlap, which the corners show.
      if (t.id[i0] == s.id[j0] || t.id[i0] == s.id[j1] || t.id[i1] == s.id[j0] || t.id[i1] == s.id[j1]) continue;
      const double a = inward(t.p[i0], t.p[i1], s.p[j0], n), b = inward(t.p[i0], t.p[i1], s.p[j1], n);
      const double c = inward(s.p[j0], s.p[j1], t.p[i0], n), d = inward(s.p[j0], s.p[j1], t.p[i1], n);
      const bool crossST = (a > tol && b < -tol) || (a < -tol && b > tol);
      const bool crossTS = (c > tol && d < -tol) || (c < -tol && d > tol);
      if (crossST && crossTS) return s.p[j0] + (s.p[j1] - s.p[j0]) * (a / (a - b));
    }
  }
  // Inside-tests need s's orientation about n; a flipped s (a fold) winds clockwise, so test it both ways.
  Triangle sUp = s;
  if (glm::dot(unitNormal(s), n) < 0.0) std::swap(sUp.p[1], sUp.p[2]);
  for (int i = 0; i < 3; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (!has(t, s.id[k]) && strictlyInside(t, n, s.p[k], tol)) return s.p[k];
    if (!has(s, t.id[k]) && strictlyInside(sUp, n, t.p[k], tol)) return t.p[k];
  }
  return std::nullopt;
}

std::optional<Vec3> trianglesMeet(const Triangle& t, const Triangle& s, double tol) {
  int shared = 0;
  for (std::uint32_t id : t.id) shared += has(s, id) ? 1 : 0;
  if (shared == 3) return std::nullopt;  // the same triangle twice: a duplicate face, not a crossing
  const Vec3 nt = unitNormal(t), ns = unitNormal(s);
  if (nt == Vec3(0.0) || ns == Vec3(0.0)) return std::nullopt;  // a degenerate triangle has no inside
  double offPlane = 0.0;  // how far s leaves t's plane, against s's extent away from the shared corners
  for (const Vec3& p : s.p) offPlane = std::max(offPlane, std::fabs(glm::dot(nt, p - t.p[0])));
  if (shared == 2) {
    // Sharing an edge: a fold only when the two close onto each other (dihedral angle near 0).
    std::size_t far = 0;
    while (has(t, s.id[far])) ++far;
    const std::size_t a = (far + 1) % 3, b = (far + 2) % 3;
    const Vec3 edge = glm::normalize(s.p[b] - s.p[a]);
    const Vec3 off = s.p[far] - s.p[a];
    const double height = glm::length(off - edge * glm::dot(off, edge));
    if (offPlane > std::max(tol, std::sin(kFoldAngle) * height)) return std::nullopt;
    return coplanarOverlap(t, s, nt, tol);
  }
  if (offPlane <= tol) return coplanarOverlap(t, s, nt, tol);
  // Edges through a shared corner meet the other triangle's plane only at that corner: skip them, so that
  // two triangles on one corner intersect iff an edge facing away from it pierces the other.
  for (int i = 0; i < 3; ++i) {
    const std::size_t i0 = static_cast<std::size_t>(i), i1 = static_cast<std::size_t>((i + 1) % 3);
    if (!has(s, t.id[i0]) && !has(s, t.id[i1]))
      if (auto x = pierces(t.p[i0], t.p[i1], s, ns, tol)) return x;
    if (!has(t, s.id[i0]) && !has(t, s.id[i1]))
      if (auto x = pierces(s.p[i0], s.p[i1], t, nt, tol)) return x;
  }
  return std::nullopt;
}

}  // namespace

QuadContact quadContact(const std::array<std::uint32_t, 4>& a, const std::array<std::uint32_t, 4>& b) {
  int shared = 0;
  bool adjacent = false;
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      if (a[i] != b[j]) continue;
      ++shared;
      // An edge: the next corner of a is a neighbour of b's corner too.
      const std::uint32_t next = a[(i + 1) % 4];
      adjacent = adjacent || next == b[(j + 1) % 4] || next == b[(j + 3) % 4];
    }
  }
  if (shared == 0) return QuadContact::Apart;
  return adjacent ? QuadContact::Edge : QuadContact::Vertex;
}

std::optional<Vec3> quadsMeet(const QuadCorners& a, const QuadCorners& b) {
  // Tolerance from the two quads' extent and coordinates: cheap, no square roots, the same order as the size.
  Vec3 lo = a.p[0], hi = a.p[0];
  for (const QuadCorners* q : {&a, &b}) {
    for (const Vec3& p : q->p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  const Vec3 extent = hi - lo, reach = glm::max(glm::abs(lo), glm::abs(hi));
  const double size = std::max({extent.x, extent.y, extent.z});
  const double tol = std::max(kRelativeTolerance * size, kFloatSteps * std::max({reach.x, reach.y, reach.z}));
  // On a shared edge a fold closes within kFoldAngle, farther than tol: keep such pairs for the fold test.
  const double foldTol = std::max(tol, std::sin(kFoldAngle) * size);
  const std::array<Triangle, 2> ta = split(a);
  // A triangle with the other quad's corners all clearly on one side of its plane (its own corners on it)
  // meets that quad nowhere: most candidate pairs end here.
  auto clear = [tol, foldTol](const Triangle& t, const QuadCorners& q) {
    const Vec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);  // not normalised: margins scale by its length
    const double length = std::sqrt(glm::dot(n, n));
    if (length == 0.0) return true;
    const int shared = has(t, q.index[0]) + has(t, q.index[1]) + has(t, q.index[2]) + has(t, q.index[3]);
    const double margin = (shared >= 2 ? foldTol : tol) * length;
    int above = 0, below = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      if (has(t, q.index[k])) continue;
      const double d = glm::dot(n, q.p[k] - t.p[0]);
      above += d > margin ? 1 : 0;
      below += d < -margin ? 1 : 0;
    }
    return above == 4 - shared || below == 4 - shared;
  };
  // Both of one quad's triangles clear of the other: done before the other two tests (a third of the mesher's time).
  const std::array<bool, 2> clearA{clear(ta[0], b), clear(ta[1], b)};
  if (clearA[0] && clearA[1]) return std::nullopt;
  const std::array<Triangle, 2> tb = split(b);  // split only now: most pairs end with a's triangles
  const std::array<bool, 2> clearB{clear(tb[0], a), clear(tb[1], a)};
  if (clearB[0] && clearB[1]) return std::nullopt;
  for (std::size_t i = 0; i < 2; ++i) {
    if (clearA[i]) continue;
    for (std::size_t j = 0; j < 2; ++j) {
      if (clearB[j]) continue;
      if (auto x = trianglesMeet(ta[i], tb[j], tol)) return x;
    }
  }
  return std::nullopt;
}

}  // namespace arbor
