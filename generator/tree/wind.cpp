#include "wind.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "common/mix64.hpp"

namespace arbor {

namespace {

// Per branch level 1, 2, 3+: how far a unit of reach moves at strength 1, and the sway's frequency in gusts
// (whole multiples, so every motion repeats with the gusts).
constexpr double kSway[3] = {0.10, 0.16, 0.24};
constexpr double kSwayHarmonic[3] = {3.0, 5.0, 7.0};
constexpr double kTrunkBend = 0.04;       // the top's bend at strength 1 and a full gust, in tree heights
constexpr double kFlutter = 0.25;         // a leaf tip's flutter at strength 1, in blade lengths
constexpr double kFlutterHarmonic = 11.0;

float phaseOf(std::uint64_t key) {
  return static_cast<float>(static_cast<double>(mix64(key) >> 11) * 0x1.0p-53 * 2.0 * std::numbers::pi);
}

// Clones sway with the stem they split from.
const SkeletonStem& swayingStem(const Skeleton& skeleton, int stem) {
  const SkeletonStem* s = &skeleton.stems[static_cast<std::size_t>(stem)];
  for (int guard = 0; s->cloneOf >= 0 && guard < 64; ++guard) s = &skeleton.stems[static_cast<std::size_t>(s->cloneOf)];
  return *s;
}

}  // namespace

WindPoint stemWindPoint(const Skeleton& skeleton, int stem, double arc) {
  WindPoint point;
  std::array<bool, 3> phased{};
  for (int s = stem, guard = 0; s >= 0 && s < static_cast<int>(skeleton.stems.size()) && guard < 64; ++guard) {
    const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(s)];
    if (st.level >= 1 && st.length > 0.0) {
      const auto slot = static_cast<std::size_t>(std::min<int>(st.level, 3) - 1);
      const double a = std::clamp(arc, 0.0, st.length);
      point.reach[slot] += static_cast<float>(a * a / st.length);
      if (!phased[slot]) point.phase[slot] = phaseOf(swayingStem(skeleton, s).key);
      phased[slot] = true;
    }
    arc = st.offsetOnParent;
    s = st.parentStem;
  }
  return point;
}

WindPoint nodeWindPoint(const Skeleton& skeleton, int node) {
  if (node < 0 || node >= static_cast<int>(skeleton.nodes.size())) return {};
  const SkeletonNode& n = skeleton.nodes[static_cast<std::size_t>(node)];
  return n.stem >= 0 ? stemWindPoint(skeleton, n.stem, n.offset) : WindPoint{};
}

std::vector<WindPoint> meshWindPoints(const Skeleton& skeleton, const TreeMesh& tree) {
  const QuadMesh& mesh = tree.mesh;
  // The stem of each vertex's lowest-level quad: a joint's shared vertices move with the parent.
  std::vector<int> stemOf(mesh.vertexCount(), -1);
  auto levelOf = [&](int stem) { return stem < 0 ? -1 : static_cast<int>(skeleton.stems[static_cast<std::size_t>(stem)].level); };
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const int stem = q < tree.quadStem.size() ? tree.quadStem[q] : -1;
    if (stem < 0) continue;  // the root hub: the trunk's
    for (const std::uint32_t v : mesh.quads[q]) {
      if (stemOf[v] < 0 || levelOf(stem) < levelOf(stemOf[v])) stemOf[v] = stem;
    }
  }
  std::vector<WindPoint> points(mesh.vertexCount());
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const int stem = stemOf[v];
    if (stem < 0 || stem >= static_cast<int>(skeleton.stems.size())) continue;
    const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(stem)];
    if (st.level < 1 || st.nodeCount <= 0) continue;  // the trunk bends by height alone
    // The arc length of the vertex's projection on the stem's skeleton, from its attachment on.
    const Vec3 p(mesh.positions[v]);
    double bestDistance = std::numeric_limits<double>::max(), arc = st.startOffset;
    Vec3 a = st.attachNode >= 0 ? skeleton.nodes[static_cast<std::size_t>(st.attachNode)].world.position
                                : skeleton.nodes[static_cast<std::size_t>(st.firstNode)].world.position;
    double arcA = st.startOffset;
    for (int n = st.firstNode; n < st.firstNode + st.nodeCount; ++n) {
      const SkeletonNode& node = skeleton.nodes[static_cast<std::size_t>(n)];
      const Vec3 b = node.world.position;
      const Vec3 ab = b - a;
      const double length2 = glm::dot(ab, ab);
      const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
      const double d = glm::distance(p, a + ab * t);
      if (d < bestDistance) {
        bestDistance = d;
        arc = arcA + (node.offset - arcA) * t;
      }
      a = b;
      arcA = node.offset;
    }
    points[v] = stemWindPoint(skeleton, stem, arc);
  }
  return points;
}

std::vector<WindPoint> leafWindPoints(const Skeleton& skeleton) {
  std::vector<WindPoint> points;
  points.reserve(skeleton.leaves.size());
  for (const Leaf& leaf : skeleton.leaves) points.push_back(nodeWindPoint(skeleton, leaf.node));
  return points;
}

double windHeight(const Skeleton& skeleton) {
  double top = 0.0;
  for (const SkeletonNode& n : skeleton.nodes) top = std::max(top, n.world.position.z);
  return top;
}

double windPhase(const Skeleton& skeleton) {
  std::uint64_t key = 0xcbf29ce484222325ull;  // FNV-1a of the species name, then the seed: stable everywhere
  for (const char c : skeleton.species) key = (key ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return phaseOf(key ^ skeleton.seed);
}

glm::vec3 windOffset(const glm::vec3& rest, const WindPoint& point, const WindSettings& wind, double treeHeight, double treePhase,
                     double seconds) {
  if (!wind.on() || !(treeHeight > 0.0)) return glm::vec3(0.0f);
  const double azimuth = wind.azimuth * std::numbers::pi / 180.0;
  const glm::dvec3 along(std::cos(azimuth), std::sin(azimuth), 0.0), side(-std::sin(azimuth), std::cos(azimuth), 0.0), up(0, 0, 1);
  const double w = 2.0 * std::numbers::pi * wind.gustFrequency * seconds + treePhase;
  const double gust = 0.65 + 0.25 * std::sin(w) + 0.10 * std::sin(2.0 * w + 1.3);
  // The trunk: bent along the wind as a cantilever, the top most; lowered so points keep their distance.
  const double z = std::max(static_cast<double>(rest.z), 0.0);
  const double h = std::min(z / treeHeight, 1.5);
  const double bend = wind.strength * gust * kTrunkBend * treeHeight * h * h;
  glm::dvec3 offset = along * bend - up * (0.5 * bend * bend / std::max(z, 1e-6));
  // Branches: pushed along the wind with the gusts, and swaying about that, each level faster.
  for (std::size_t l = 0; l < 3; ++l) {
    const double reach = point.reach[l];
    if (reach <= 0.0) continue;
    const double phase = point.phase[l];
    const double sway = std::sin(kSwayHarmonic[l] * w + phase), across = std::sin(kSwayHarmonic[l] * w + phase + 1.7);
    offset += wind.strength * kSway[l] * reach * (along * (0.6 * gust + 0.4 * sway) + side * (0.3 * across) + up * (0.15 * sway));
  }
  return glm::vec3(offset);
}

float leafFlutterPhase(std::uint32_t index) { return phaseOf(0x9E3779B97F4A7C15ull + index); }

double leafFlutter(const WindSettings& wind, std::uint32_t index, double seconds) {
  if (!wind.on()) return 0.0;
  const double w = 2.0 * std::numbers::pi * wind.gustFrequency * seconds;
  return wind.strength * kFlutter * std::sin(kFlutterHarmonic * w + leafFlutterPhase(index));
}

TreeWind treeWind(const Skeleton& skeleton, const TreeMesh& mesh, const std::vector<ImpostorSegment>& impostors,
                  const std::vector<ImpostorSegment>& sketch) {
  TreeWind wind;
  wind.height = windHeight(skeleton);
  wind.phase = windPhase(skeleton);
  wind.mesh = meshWindPoints(skeleton, mesh);
  wind.leaves = leafWindPoints(skeleton);
  for (const auto* list : {&impostors, &sketch}) {
    for (const ImpostorSegment& s : *list) {
      wind.segmentEnds.push_back(nodeWindPoint(skeleton, s.fromNode));
      wind.segmentEnds.push_back(nodeWindPoint(skeleton, s.toNode));
    }
  }
  return wind;
}

}  // namespace arbor
