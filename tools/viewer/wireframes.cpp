#include "wireframes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

namespace arbor::viewer {

namespace {

constexpr double kTau = 6.283185307179586;

// An ellipse about `center` spanned by the semi-axes a and b.
void addEllipse(Lines& lines, const Vec3& center, const Vec3& a, const Vec3& b, const glm::vec3& color, int segments) {
  for (int i = 0; i < segments; ++i) {
    const double t0 = kTau * i / segments, t1 = kTau * (i + 1) / segments;
    addLine(lines, center + std::cos(t0) * a + std::sin(t0) * b, center + std::cos(t1) * a + std::sin(t1) * b, color);
  }
}

void addEllipsoid(Lines& lines, const Vec3& center, const Vec3& semiAxes, const glm::vec3& color, int segments) {
  const Vec3 x(semiAxes.x, 0, 0), y(0, semiAxes.y, 0), z(0, 0, semiAxes.z);
  addEllipse(lines, center, x, y, color, segments);
  addEllipse(lines, center, x, z, color, segments);
  addEllipse(lines, center, y, z, color, segments);
}

void addBox(Lines& lines, const Vec3& center, const Vec3& extents, const glm::vec3& color) {
  const Vec3 h = 0.5 * extents;
  const auto corner = [&](int i) { return center + Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z); };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) addLine(lines, corner(i), corner(i | bit), color);  // each edge once, from its lower corner
}

}  // namespace

glm::vec3 cloudColor(std::size_t index) {
  static constexpr std::array<glm::vec3, 6> palette{{{0.3f, 0.8f, 1.0f},
                                                     {0.4f, 1.0f, 0.45f},
                                                     {1.0f, 0.6f, 0.2f},
                                                     {0.85f, 0.45f, 1.0f},
                                                     {1.0f, 0.9f, 0.5f},
                                                     {0.5f, 0.6f, 1.0f}}};
  return palette[index % palette.size()];
}

void addLine(Lines& lines, const Vec3& a, const Vec3& b, const glm::vec3& color) {
  const auto vertex = [&](const Vec3& p) {
    return render::LineVertex{{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 1.0f}, {color.r, color.g, color.b, 1.0f}};
  };
  lines.push_back(vertex(a));
  lines.push_back(vertex(b));
}

void addCloud(Lines& lines, const sc::AttractionCloud& c, const glm::vec3& color, int segments) {
  switch (c.shape) {
    case sc::CloudShape::Sphere: addEllipsoid(lines, c.center, Vec3(c.size.x), color, segments); break;
    case sc::CloudShape::Ellipsoid: addEllipsoid(lines, c.center, c.size, color, segments); break;
    case sc::CloudShape::Box: addBox(lines, c.center, c.size, color); break;
    case sc::CloudShape::Cone: {
      const double r = c.size.x, height = c.size.z;
      const Vec3 apex = c.center + Vec3(0, 0, height);
      addEllipse(lines, c.center, Vec3(r, 0, 0), Vec3(0, r, 0), color, segments);
      addEllipse(lines, c.center + Vec3(0, 0, 0.5 * height), Vec3(0.5 * r, 0, 0), Vec3(0, 0.5 * r, 0), color, segments);
      for (int i = 0; i < 4; ++i) {
        const double t = kTau * i / 4;
        addLine(lines, c.center + Vec3(r * std::cos(t), r * std::sin(t), 0), apex, color);
      }
      break;
    }
  }
}

void addObstacle(Lines& lines, const sc::Obstacle& o, const glm::vec3& color, int segments) {
  switch (o.shape) {
    case sc::ObstacleShape::Box: addBox(lines, o.center, o.size, color); break;
    case sc::ObstacleShape::Sphere: addEllipsoid(lines, o.center, Vec3(o.size.x), color, segments); break;
    case sc::ObstacleShape::Mesh: {
      if (!o.mesh) break;
      std::set<std::pair<std::uint32_t, std::uint32_t>> edges;  // a closed mesh names each edge twice
      for (const auto& t : o.mesh->triangles)
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]));
      for (const auto& [a, b] : edges) addLine(lines, o.mesh->vertices[a], o.mesh->vertices[b], color);
      break;
    }
  }
}

void addLivePoints(Lines& lines, const sc::Colonizer& colonizer, double size) {
  const double h = 0.5 * size;
  for (const sc::AttractionPoint& p : colonizer.points()) {
    if (p.killedAt != sc::kAlive) continue;
    const glm::vec3 color = 0.7f * cloudColor(p.cloud);
    addLine(lines, p.position - Vec3(h, 0, 0), p.position + Vec3(h, 0, 0), color);
    addLine(lines, p.position - Vec3(0, h, 0), p.position + Vec3(0, h, 0), color);
    addLine(lines, p.position - Vec3(0, 0, h), p.position + Vec3(0, 0, h), color);
  }
}

void addDisabledBranches(Lines& lines, const sc::Colonizer& colonizer) {
  const std::vector<sc::Node>& nodes = colonizer.nodes();
  for (const sc::Node& n : nodes)
    if (!n.enabled && n.parent >= 0) addLine(lines, nodes[static_cast<std::size_t>(n.parent)].position, n.position, kDisabledColor);
}

}  // namespace arbor::viewer
