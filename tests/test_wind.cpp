// Wind (generator/tree/wind, docs/wind.md): a child's base moves exactly with its parent, the motion loops with
// the gusts, still air and the trunk's base do not move, and the strength sets the trunk's bend.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "growth/weber_penn/weber_penn.hpp"
#include "tree/build_tree.hpp"
#include "tree/wind.hpp"
#include "test_support.hpp"

using namespace arbor;

namespace {

Skeleton growPreset(const std::string& name) {
  GrowthOptions o;
  o.seed = 2;
  return generateSkeleton(test::loadPreset(name), o);
}

bool samePoint(const WindPoint& a, const WindPoint& b) {
  for (std::size_t l = 0; l < 3; ++l) {
    if (std::abs(a.reach[l] - b.reach[l]) > 1e-6f * std::max(1.0f, a.reach[l])) return false;
    if (a.reach[l] > 0.0f && a.phase[l] != b.phase[l]) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("wind: every child's base moves exactly as its parent there", "[wind]") {
  for (const std::string& preset : {std::string("black-tupelo"), std::string("weeping-willow"), std::string("palm")}) {
    INFO(preset);
    const Skeleton s = growPreset(preset);
    std::size_t children = 0, mismatched = 0;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& stem = s.stems[i];
      if (stem.parentStem < 0 || stem.cloneOf >= 0) continue;
      ++children;
      // The child's own reach is 0 at its base; what is left is its parent's at the attachment.
      const WindPoint base = stemWindPoint(s, static_cast<int>(i), 0.0);
      const WindPoint parent = stemWindPoint(s, stem.parentStem, stem.offsetOnParent);
      mismatched += samePoint(base, parent) ? 0 : 1;
    }
    CHECK(children > 10);
    CHECK(mismatched == 0);
  }
}

TEST_CASE("wind: the motion loops with the gust period, still air and the base stay put", "[wind]") {
  const Skeleton s = growPreset("quaking-aspen");
  const TreeMesh tree = buildTree(s, BuildOptions{{}, false}).mesh;
  const std::vector<WindPoint> points = meshWindPoints(s, tree);
  REQUIRE(points.size() == tree.mesh.vertexCount());
  const double height = windHeight(s);
  WindSettings wind;
  wind.strength = 1.0;
  wind.azimuth = 30.0;
  wind.gustFrequency = 0.2;
  double worstLoop = 0.0, moved = 0.0;
  for (std::size_t v = 0; v < points.size(); v += 7) {
    const glm::vec3 p = tree.mesh.positions[v];
    for (const double t : {0.3, 1.7, 4.1}) {
      const glm::vec3 a = windOffset(p, points[v], wind, height, 0.7, t), b = windOffset(p, points[v], wind, height, 0.7, t + wind.period());
      worstLoop = std::max(worstLoop, static_cast<double>(glm::distance(a, b)));
      moved = std::max(moved, static_cast<double>(glm::length(a)));
    }
    WindSettings still = wind;
    still.strength = 0.0;
    CHECK(glm::length(windOffset(p, points[v], still, height, 0.7, 1.0)) == 0.0f);
  }
  CHECK(worstLoop < 1e-4);
  CHECK(moved > 0.01 * height);
  // The trunk's base does not move; its top bends along the wind by about 4 % of the height in a full gust.
  CHECK(glm::length(windOffset(glm::vec3(0.1f, 0.0f, 0.0f), WindPoint{}, wind, height, 0.7, 1.0)) == 0.0f);
  double top = 0.0;
  const glm::vec3 along(std::cos(glm::radians(30.0f)), std::sin(glm::radians(30.0f)), 0.0f);
  for (int k = 0; k < 100; ++k) top = std::max(top, static_cast<double>(glm::dot(windOffset(glm::vec3(0, 0, float(height)), WindPoint{}, wind, height, 0.0, k * 0.05), along)));
  CHECK(top > 0.033 * height);
  CHECK(top <= 0.04 * height + 1e-6);
}

TEST_CASE("wind: vertices of a stem sway more towards its tip", "[wind]") {
  const Skeleton s = growPreset("black-tupelo");
  const TreeMesh tree = buildTree(s, BuildOptions{{}, false}).mesh;
  const std::vector<WindPoint> points = meshWindPoints(s, tree);
  // Along each ring sequence of a level-1 stem, the level-1 reach never decreases (a^2 / L grows with a).
  std::size_t checked = 0, decreasing = 0;
  std::map<int, float> lastReach;
  for (const MeshRing& ring : tree.rings) {
    if (ring.arc < 0.0 || ring.stem < 0 || s.stems[static_cast<std::size_t>(ring.stem)].level != 1) continue;
    const float reach = points[ring.vertices[1]].reach[0];
    if (const auto it = lastReach.find(ring.stem); it != lastReach.end()) {
      ++checked;
      decreasing += reach + 1e-4f < it->second ? 1 : 0;
    }
    lastReach[ring.stem] = reach;
  }
  CHECK(checked > 100);
  CHECK(decreasing <= checked / 100);
}
