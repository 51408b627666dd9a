#include "turtle.hpp"

#include <algorithm>
#include <cmath>

#include "common/input_error.hpp"

namespace arbor::lsys {

void turn(TurtleState& t, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec3 h = t.heading;
  t.heading = h * c + t.left * s;
  t.left = t.left * c - h * s;
}

void pitch(TurtleState& t, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec3 h = t.heading;
  t.heading = h * c - t.up * s;
  t.up = t.up * c + h * s;
}

void roll(TurtleState& t, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec3 l = t.left;
  t.left = l * c + t.up * s;
  t.up = t.up * c - l * s;
}

void turnAround(TurtleState& t) {
  t.heading = -t.heading;
  t.left = -t.left;
}

void rollHorizontal(TurtleState& t, const Vec3& vertical) {
  const Vec3 l = glm::cross(vertical, t.heading);
  const double n = glm::length(l);
  if (n < 1e-12) return;  // heading vertical: every left is horizontal
  t.left = l / n;
  t.up = glm::cross(t.heading, t.left);
}

void bend(TurtleState& t, const Vec3& tropism, double susceptibility) {
  const Vec3 axis = glm::cross(t.heading, tropism);
  const double n = glm::length(axis);
  if (n < 1e-12 || susceptibility == 0) return;
  const Vec3 k = axis / n;
  const double angle = susceptibility * n, c = std::cos(angle), s = std::sin(angle);
  // Rodrigues' rotation of each axis of the frame about k.
  const auto rotate = [&](const Vec3& v) { return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1 - c)); };
  t.heading = rotate(t.heading);
  t.left = rotate(t.left);
  t.up = rotate(t.up);
}

TurtleSettings turtleSettings(const Lsystem& system) {
  TurtleSettings s;
  s.step = system.step;
  s.angle = system.angle;
  s.widthFactor = system.widthFactor;
  s.tropism = system.tropism;
  s.susceptibility = system.susceptibility;
  s.leafKind = system.leafKind;
  s.start.width = system.width;
  s.file = system.file;
  return s;
}

TurtleSettings planarTurtleSettings(const Lsystem& system) {
  TurtleSettings s = turtleSettings(system);
  s.start.heading = Vec3(0.0, 1.0, 0.0);
  s.start.left = Vec3(-1.0, 0.0, 0.0);
  s.start.up = Vec3(0.0, 0.0, 1.0);
  s.vertical = Vec3(0.0, 1.0, 0.0);
  s.tropism = Vec3(system.tropism.x, system.tropism.z, -system.tropism.y);  // the 3D frame's x-z plane, seen from -y
  return s;
}

bool polygonLeaf(const std::vector<Vec3>& vertices, const Vec3& fallbackNormal, GraphLeaf& leaf) {
  if (vertices.size() < 3) return false;
  const Vec3 base = vertices.front();
  Vec3 far = base;
  for (const Vec3& v : vertices)
    if (glm::length(v - base) > glm::length(far - base)) far = v;
  const double length = glm::length(far - base);
  if (!(length > 0)) return false;
  const Vec3 direction = (far - base) / length;
  Vec3 normal(0.0);  // Newell's normal of the outline
  for (std::size_t i = 0; i < vertices.size(); ++i) normal += glm::cross(vertices[i], vertices[(i + 1) % vertices.size()]);
  normal -= direction * glm::dot(normal, direction);
  if (glm::length(normal) < 1e-12 * length * length) normal = fallbackNormal - direction * glm::dot(fallbackNormal, direction);
  if (glm::length(normal) < 1e-12) return false;
  normal = glm::normalize(normal);
  const Vec3 side = glm::cross(normal, direction);
  double low = 0, high = 0;
  for (const Vec3& v : vertices) {
    const double x = glm::dot(v - base, side);
    low = std::min(low, x);
    high = std::max(high, x);
  }
  if (!(high - low > 1e-9 * length)) return false;
  leaf.position = base;
  leaf.direction = direction;
  leaf.normal = normal;
  leaf.length = length;
  leaf.width = high - low;
  return true;
}

namespace {

struct OpenPolygon {
  std::vector<Vec3> vertices;
  std::int32_t node = 0;
  int colour = 0;
};

// Each node's children as a linked list (first child, next sibling): a few words a node for strings of 10^7 modules.
struct Children {
  std::vector<std::int32_t> first, next;
};

// The node an F from `from` to `to` arrives at: the one an earlier F drew there, or a new one. A grammar may draw
// a line twice (ABOP 1.24b and c: a branch leaving where, and as, its mother axis goes on derives the same subtree
// as that axis): two stems on top of each other are one branch, not a skeleton whose meshes run through each other.
std::int32_t internode(BranchGraph& graph, Children& children, std::int32_t from, const Vec3& to, double radius, double length,
                       std::size_t& segments) {
  // Both ends agree to rounding: the same line reached by other turns (-+ against none) differs in the last bits.
  const double near = 1e-9 * length;
  for (std::int32_t c = children.first[static_cast<std::size_t>(from)]; c >= 0; c = children.next[static_cast<std::size_t>(c)]) {
    BranchNode& n = graph.nodes[static_cast<std::size_t>(c)];
    if (glm::length(n.position - to) <= near) {
      n.radius = std::max(n.radius, radius);
      return c;
    }
  }
  const auto node = static_cast<std::int32_t>(graph.nodes.size());
  graph.nodes.push_back({to, from, radius, -1});
  children.first.push_back(-1);
  children.next.push_back(children.first[static_cast<std::size_t>(from)]);
  children.first[static_cast<std::size_t>(from)] = node;
  ++segments;
  return node;
}

}  // namespace

Interpretation interpret(const ModuleString& str, const TurtleSettings& settings, bool recordDrawing) {
  Interpretation out;
  TurtleState t = settings.start;
  const double angle = radians(settings.angle);
  const bool tropism = settings.susceptibility != 0 && glm::length(settings.tropism) > 0;
  std::vector<TurtleState> stack;
  std::vector<OpenPolygon> polygons;
  out.graph.nodes.push_back({t.position, -1, t.width > 0 ? t.width / 2 : 0, -1});
  Children children;
  children.first.push_back(-1);
  children.next.push_back(-1);
  t.node = 0;
  const std::size_t n = str.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Module& m = str.modules[i];
    const double* p = str.parametersOf(m);
    switch (m.symbol) {
      case 'F': {
        const double l = m.count ? p[0] : settings.step;
        const Vec3 next = t.position + t.heading * l;
        if (!polygons.empty()) {  // inside a polygon F only traces its outline
          t.position = next;
          polygons.back().vertices.push_back(next);
          break;
        }
        if (l == 0) break;
        if (recordDrawing) out.drawing.push_back({t.position, next, t.width, t.colour});
        t.node = internode(out.graph, children, t.node, next, t.width > 0 ? t.width / 2 : 0, std::abs(l), out.segments);
        t.position = next;
        if (tropism) bend(t, settings.tropism, settings.susceptibility);
        break;
      }
      case 'f':
        t.position += t.heading * (m.count ? p[0] : settings.step);
        if (!polygons.empty()) polygons.back().vertices.push_back(t.position);
        break;
      case '+': turn(t, m.count ? radians(p[0]) : angle); break;
      case '-': turn(t, -(m.count ? radians(p[0]) : angle)); break;
      case '&': pitch(t, m.count ? radians(p[0]) : angle); break;
      case '^': pitch(t, -(m.count ? radians(p[0]) : angle)); break;
      case '/': roll(t, m.count ? radians(p[0]) : angle); break;
      case '\\': roll(t, -(m.count ? radians(p[0]) : angle)); break;
      case '|': turnAround(t); break;
      case '$': rollHorizontal(t, settings.vertical); break;
      case '[': stack.push_back(t); break;
      case ']':
        if (stack.empty())
          throw InputError(settings.file, "module " + std::to_string(i + 1) + " of the derived string", "']' without a '[' before it");
        t = stack.back();
        stack.pop_back();
        break;
      case '!': t.width = m.count ? p[0] : t.width * settings.widthFactor; break;
      case '\'': t.colour = m.count ? static_cast<int>(p[0]) : t.colour + 1; break;
      case '{': polygons.push_back({{t.position}, t.node, t.colour}); break;
      case '.':
        if (!polygons.empty()) polygons.back().vertices.push_back(t.position);
        break;
      case '}': {
        if (polygons.empty()) break;
        GraphLeaf leaf;
        if (polygonLeaf(polygons.back().vertices, t.up, leaf)) {
          leaf.node = polygons.back().node;
          leaf.kind = static_cast<std::uint8_t>(settings.leafKind);
          out.graph.leaves.push_back(leaf);
        }
        if (recordDrawing) out.polygons.push_back({std::move(polygons.back().vertices), polygons.back().colour});
        polygons.pop_back();
        break;
      }
      case '%': {  // cut: skip to the ']' closing this branch, which then pops the state as usual
        int depth = 0;
        for (++i; i < n; ++i) {
          const char c = str.modules[i].symbol;
          if (c == '[') ++depth;
          else if (c == ']' && depth-- == 0) break;
        }
        if (i < n) --i;
        break;
      }
      default: break;  // modules without a turtle meaning (A, B, X, ...) draw nothing
    }
  }
  out.last = t;
  return out;
}

}  // namespace arbor::lsys
