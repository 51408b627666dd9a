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
  std::vector<bool> branchStart(n, false);  // first node of a branch (its direction is drawn afresh)
  // Topology: branches are chains of 2 to 8 internodes, as growth models make them; each leaves an existing
  // node, and one time in four several leave one node together (a burst: 3 to 6 children there in all).
  std::size_t next = 1;
  auto grow = [&](std::size_t from, int count) {
    std::size_t parent = from;
    for (int k = 0; k < count && next < n && childCount[parent] < 6; ++k) {
      g.nodes[next].parent = static_cast<std::int32_t>(parent);
      branchStart[next] = k == 0;
      ++childCount[parent];
      parent = next++;
    }
  };
  grow(0, 6 + static_cast<int>(rng.uniform() * 10.0));
  while (next < n) {
    // Now and then the root itself: several trunks on a hub.
    auto at = rng.uniform() < 0.03 ? std::size_t{0} : static_cast<std::size_t>(rng.uniform() * static_cast<double>(next));
    if (childCount[at] >= 6) continue;
    int branches = 1;
    if (rng.uniform() < 0.25) branches = std::max(1, 3 + static_cast<int>(rng.uniform() * 4.0) - childCount[at]);
    for (int b = 0; b < branches && next < n; ++b) grow(at, 2 + static_cast<int>(rng.uniform() * 7.0));
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

  // Directions: a branch leaves near-parallel to its parent (5 to 15 degrees, one in five) or to an earlier
  // sibling (one in five where there is one), backward (120 to 180 degrees, one in seven), anywhere on the
  // sphere (one in six) or at an ordinary 30 to 80 degrees; along a branch each internode turns up to 15 degrees.
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  std::vector<Vec3> direction(n, kUp);
  std::vector<std::size_t> firstChild(n, 0);  // an earlier branch leaving the same node (0: none yet)
  for (std::size_t i = 1; i < n; ++i) {  // parents come first: indices grow away from the root
    const auto parent = static_cast<std::size_t>(g.nodes[i].parent);
    const double kind = rng.uniform();
    const double slight = (5.0 + 10.0 * rng.uniform()) * kDegree;
    if (!branchStart[i]) {
      direction[i] = around(direction[parent], 15.0 * kDegree * rng.uniform(), rng);
    } else if (kind < 0.2 && firstChild[parent] != 0) {
      direction[i] = around(direction[firstChild[parent]], slight, rng);
    } else if (kind < 0.4) {
      direction[i] = around(direction[parent], slight, rng);
    } else if (kind < 0.54) {
      direction[i] = around(direction[parent], (120.0 + 60.0 * rng.uniform()) * kDegree, rng);
    } else if (kind < 0.7) {
      direction[i] = around(direction[parent], std::acos(1.0 - 2.0 * rng.uniform()), rng);
    } else {
      direction[i] = around(direction[parent], (30.0 + 50.0 * rng.uniform()) * kDegree, rng);
    }
    if (branchStart[i] && firstChild[parent] == 0) firstChild[parent] = i;
    // Internodes 0.01 to 10 of their radii (log-uniform), three in four of them at least one radius, so
    // that most branches reach several of their parent's radii out of it.
    const double u = rng.uniform() < 0.25 ? rng.uniform() / 1.5 : 2.0 / 3.0 + rng.uniform() / 3.0;
    const double length = radius[i] * std::pow(10.0, -2.0 + 3.0 * u);
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
