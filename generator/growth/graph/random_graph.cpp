#include "random_graph.hpp"

#include <algorithm>
#include <cmath>

#include "growth/random.hpp"

namespace arbor {

namespace {

// A unit vector at `angle` from `axis`, at a random azimuth about it.
Vec3 around(const Vec3& axis, double angle, Rng& rng) {
  Vec3 u = glm::cross(axis, std::abs(axis.z) < 0.9 ? kUp : Vec3(1.0, 0.0, 0.0));
  u = glm::normalize(u);
  const Vec3 v = glm::cross(axis, u);
  const double azimuth = 2.0 * 3.14159265358979323846 * rng.uniform();
  return glm::normalize(std::cos(angle) * axis + std::sin(angle) * (std::cos(azimuth) * u + std::sin(azimuth) * v));
}

}  // namespace

BranchGraph randomBranchGraph(std::uint64_t seed, int nodes, const GraphOptions& options) {
  Rng rng(seed, kStreamTree);
  const auto n = static_cast<std::size_t>(std::max(2, nodes));
  BranchGraph g;
  g.nodes.resize(n);
  std::vector<int> childCount(n, 0);
  // Topology: mostly chains, sometimes a burst of children on one node, sometimes a child anywhere.
  std::size_t burstNode = 0;
  int burstLeft = 0;
  for (std::size_t i = 1; i < n; ++i) {
    std::size_t parent = i - 1;
    const double pick = rng.uniform();
    if (burstLeft > 0 && childCount[burstNode] < 6) {
      parent = burstNode;
      --burstLeft;
    } else if (pick < 0.08) {
      burstNode = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
      burstLeft = 2 + static_cast<int>(rng.uniform() * 4.0);
      parent = burstNode;
    } else if (pick < 0.35) {
      parent = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
    }
    while (childCount[parent] >= 6) parent = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
    ++childCount[parent];
    g.nodes[i].parent = static_cast<std::int32_t>(parent);
  }
  for (std::size_t i = 0; i < n; ++i) g.nodes[i].id = static_cast<std::int64_t>(i);

  // Some radii given, then lengths in units of the radii the converter will use.
  for (std::size_t i = 1; i < n; ++i) {
    if (rng.uniform() < 0.1) g.nodes[i].radius = -1.0;  // marked; set from the pipe model below
  }
  BranchGraph plain = g;
  for (BranchNode& node : plain.nodes) node.radius = 0.0;
  const std::vector<double> pipe = pipeRadii(plain, options);
  for (std::size_t i = 0; i < n; ++i) {
    if (g.nodes[i].radius < 0.0) g.nodes[i].radius = pipe[i] * (0.7 + 0.9 * rng.uniform());
  }
  const std::vector<double> radius = pipeRadii(g, options);

  std::vector<Vec3> direction(n, kUp);
  for (std::size_t i = 1; i < n; ++i) {  // parents come first: indices grow away from the root
    const auto parent = static_cast<std::size_t>(g.nodes[i].parent);
    const double kind = rng.uniform();
    double angle = std::acos(1.0 - 2.0 * rng.uniform());  // uniform on the sphere
    if (kind < 0.33) angle = 0.17 * rng.uniform();
    else if (kind < 0.455) angle = 2.09 + 1.05 * rng.uniform();
    direction[i] = around(direction[parent], angle, rng);
    const double length = radius[i] * std::pow(10.0, -2.0 + 3.0 * rng.uniform());
    g.nodes[i].position = g.nodes[parent].position + direction[i] * length;
  }

  for (std::size_t i = 1; i < n; ++i) {
    if (childCount[i] != 0 || rng.uniform() >= 0.25) continue;
    GraphLeaf leaf;
    leaf.node = static_cast<std::int32_t>(i);
    leaf.position = g.nodes[i].position;
    leaf.direction = around(direction[i], 0.7, rng);
    leaf.length = 5.0 * options.tipRadius;
    leaf.width = 2.0 * options.tipRadius;
    g.leaves.push_back(leaf);
  }
  return g;
}

}  // namespace arbor
