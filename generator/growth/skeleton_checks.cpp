#include "skeleton_checks.hpp"

#include <algorithm>
#include <cmath>

namespace arbor {

SkeletonStats skeletonStats(const Skeleton& s) {
  SkeletonStats stats;
  stats.nodes = s.nodes.size();
  stats.stems = s.stems.size();
  stats.leaves = s.leaves.size();
  std::vector<int> outgoing(s.nodes.size(), 0);
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent >= 0) ++outgoing[static_cast<std::size_t>(n.parent)];
    stats.height = std::max(stats.height, n.world.position.z);
    stats.lowest = std::min(stats.lowest, n.world.position.z);
    stats.crownRadius = std::max(stats.crownRadius, std::hypot(n.world.position.x, n.world.position.y));
  }
  stats.branchPoints = static_cast<std::size_t>(std::count_if(outgoing.begin(), outgoing.end(), [](int c) { return c > 1; }));
  for (const SkeletonStem& st : s.stems) {
    const auto level = static_cast<std::size_t>(st.level);
    if (stats.stemsPerLevel.size() <= level) stats.stemsPerLevel.resize(level + 1, 0);
    ++stats.stemsPerLevel[level];
    stats.stubs += st.stub ? 1 : 0;
  }
  return stats;
}

double worstConservationError(const Skeleton& s) {
  std::vector<double> outgoingSum(s.nodes.size(), 0.0);
  std::vector<int> outgoing(s.nodes.size(), 0);
  double worst = 0.0;
  for (const SkeletonNode& n : s.nodes) {
    if (n.parent < 0) continue;
    const auto p = static_cast<std::size_t>(n.parent);
    outgoingSum[p] += std::pow(n.startRadius, s.exponent);
    ++outgoing[p];
  }
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (outgoing[i] == 0) continue;
    const double arriving = std::pow(s.nodes[i].radius, s.exponent);
    if (arriving <= 0.0) continue;
    worst = std::max(worst, std::fabs(outgoingSum[i] - arriving) / arriving);
  }
  return worst;
}

std::vector<std::string> structuralProblems(const Skeleton& s) {
  std::vector<std::string> problems;
  auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const SkeletonNode& n = s.nodes[i];
    const std::string id = "node " + std::to_string(i);
    if (n.parent >= static_cast<int>(i)) problems.push_back(id + " comes before its parent");
    if (!finite(n.world.position) || !std::isfinite(n.radius)) problems.push_back(id + " is not finite");
    if (n.radius < 0.0 || n.startRadius < 0.0) problems.push_back(id + " has a negative radius");
    if (problems.size() > 20) break;
  }
  for (std::size_t i = 0; i < s.leaves.size() && problems.size() <= 20; ++i) {
    if (!finite(s.leaves[i].position)) problems.push_back("leaf " + std::to_string(i) + " is not finite");
  }
  return problems;
}

}  // namespace arbor
