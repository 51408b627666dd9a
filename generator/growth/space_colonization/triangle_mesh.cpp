#include "triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "common/input_error.hpp"

namespace arbor::sc {

namespace {

// Möller-Trumbore: the ray parameter t of the hit with triangle (a, b, c), or -1.
double rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return -1;
  const double inv = 1.0 / det;
  const Vec3 s = origin - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) * inv;
  if (v < 0 || u + v > 1) return -1;
  return glm::dot(e2, q) * inv;
}

std::uint32_t vertexIndex(const std::string& token, std::size_t count, const std::string& file, const std::string& field,
                          int line) {
  const std::string head = token.substr(0, token.find('/'));
  char* end = nullptr;
  const long long i = std::strtoll(head.c_str(), &end, 10);
  const long long n = static_cast<long long>(count);
  const long long k = i < 0 ? n + i : i - 1;
  if (head.empty() || *end != '\0' || i == 0 || k < 0 || k >= n) {
    throw InputError(file, field, "line " + std::to_string(line) + ": face index '" + token + "' names no vertex (1.." + std::to_string(count) + ")");
  }
  return static_cast<std::uint32_t>(k);
}

}  // namespace

TriangleMesh readObjMesh(const std::string& text, const std::string& file, const std::string& field) {
  TriangleMesh mesh;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      Vec3 p;
      if (!(words >> p.x >> p.y >> p.z) || !std::isfinite(p.x + p.y + p.z))
        throw InputError(file, field, "line " + std::to_string(number) + ": a vertex needs three finite numbers");
      mesh.vertices.push_back(p);
    } else if (kind == "f") {
      std::vector<std::uint32_t> face;
      for (std::string token; words >> token;) face.push_back(vertexIndex(token, mesh.vertices.size(), file, field, number));
      if (face.size() < 3) throw InputError(file, field, "line " + std::to_string(number) + ": a face needs three vertices");
      for (std::size_t k = 1; k + 1 < face.size(); ++k) mesh.triangles.push_back({face[0], face[k], face[k + 1]});
    }
  }
  if (mesh.triangles.empty()) throw InputError(file, field, "the OBJ file has no face");
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [edge, uses] : edges) {
    if (uses != 2)
      throw InputError(file, field, "the mesh is not closed: the edge between vertices " + std::to_string(edge.first + 1) + " and " +
                                        std::to_string(edge.second + 1) + " has " + std::to_string(uses) + " faces (a closed mesh has 2)");
  }
  mesh.low = mesh.high = mesh.vertices[mesh.triangles[0][0]];
  for (const auto& t : mesh.triangles)
    for (const std::uint32_t v : t) mesh.low = glm::min(mesh.low, mesh.vertices[v]), mesh.high = glm::max(mesh.high, mesh.vertices[v]);
  return mesh;
}

bool insideMesh(const TriangleMesh& mesh, const Vec3& p) {
  if (glm::any(glm::lessThan(p, mesh.low)) || glm::any(glm::greaterThan(p, mesh.high))) return false;
  // An odd direction, so that the ray almost never grazes an edge or a vertex of an artist's mesh.
  const Vec3 dir = glm::normalize(Vec3(0.5377, 0.3181, 0.7813));
  int crossings = 0;
  for (const auto& t : mesh.triangles)
    crossings += rayTriangle(p, dir, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) > 0;
  return crossings % 2 == 1;
}

bool segmentHitsMesh(const TriangleMesh& mesh, const Vec3& a, const Vec3& b) {
  if (glm::any(glm::lessThan(glm::max(a, b), mesh.low)) || glm::any(glm::greaterThan(glm::min(a, b), mesh.high))) return false;
  if (insideMesh(mesh, a) || insideMesh(mesh, b)) return true;
  const Vec3 d = b - a;
  for (const auto& t : mesh.triangles) {
    const double s = rayTriangle(a, d, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    if (s >= 0 && s <= 1) return true;
  }
  return false;
}

}  // namespace arbor::sc
