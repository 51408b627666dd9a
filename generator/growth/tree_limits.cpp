#include "tree_limits.hpp"

#include <cmath>
#include <cstdio>

#include "common/text_util.hpp"

namespace arbor {

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, x < 1e6 ? "%.0f" : "%.2g", x);
  return buf;
}

}  // namespace

std::string outOfReach(double coordinate) {
  if (std::abs(coordinate) <= kMaxCoordinate) return "";
  return formatNumber(coordinate) + " m lies too far from the origin; allowed: within " + formatNumber(kMaxCoordinate) +
         " m on each axis (the mesh's float positions resolve 8 mm there)";
}

std::string TreeEstimate::excess(const TreeLimits& limits, double margin) const {
  if (nodes > margin * static_cast<double>(limits.nodes)) {
    return "the tree would have about " + number(nodes) + " nodes, more than the limit of " + number(static_cast<double>(limits.nodes)) +
           " (the most stems are on " + drivers + "); " + lowerNodes;
  }
  if (leaves > margin * static_cast<double>(limits.leaves)) {
    return "the tree would have about " + number(leaves) + " leaves, more than the limit of " + number(static_cast<double>(limits.leaves)) +
           "; " + lowerLeaves;
  }
  return "";
}

}  // namespace arbor
