#include "joint_checks.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "stem_polyline.hpp"

namespace arbor {

namespace {

// First and last ring of every stem, in build order (a stem's rings are in order along it).
struct StemRings {
  std::vector<int> first, last;
  // (arc length, radius) of the rings on the stem's own skeleton, by arc length: the first is where its tube begins.
  std::vector<std::vector<std::pair<double, double>>> onSkeleton;
};

StemRings stemRings(const Skeleton& skeleton, const TreeMesh& tree) {
  StemRings r{std::vector<int>(skeleton.stems.size(), -1), std::vector<int>(skeleton.stems.size(), -1),
              std::vector<std::vector<std::pair<double, double>>>(skeleton.stems.size())};
  for (std::size_t i = 0; i < tree.rings.size(); ++i) {
    const int stem = tree.rings[i].stem;
    if (stem < 0) continue;
    const auto s = static_cast<std::size_t>(stem);
    if (r.first[s] < 0) r.first[s] = static_cast<int>(i);
    r.last[s] = static_cast<int>(i);
    if (tree.rings[i].arc >= 0.0) r.onSkeleton[s].emplace_back(tree.rings[i].arc, tree.rings[i].radius);
  }
  for (auto& arcs : r.onSkeleton) std::sort(arcs.begin(), arcs.end());
  return r;
}

}  // namespace

std::vector<ChildPlacement> childPlacements(const Skeleton& skeleton, const TreeMesh& tree) {
  const StemRings rings = stemRings(skeleton, tree);
  std::vector<ChildPlacement> out;
  std::optional<StemPolyline> parentLine;  // a parent's children are mostly in a row: its polyline made once for them
  int lineOf = -1;
  for (std::size_t c = 0; c < skeleton.stems.size(); ++c) {
    const SkeletonStem& st = skeleton.stems[c];
    if (st.parentStem < 0 || st.cloneOf >= 0 || rings.first[c] < 0) continue;
    // Rings of the parent's own sub-boxes carry the parent's stem id; the child's first ring is its own.
    if (lineOf != st.parentStem) parentLine.emplace(skeleton, lineOf = st.parentStem);
    const StemPolyline& parent = *parentLine;
    double s = -1.0;
    for (int i = 0; i < parent.pointCount(); ++i) {
      if (parent.node(i) == st.attachNode) s = parent.arcLength(i);
    }
    if (s < 0.0) continue;
    const Vec3 attach = skeleton.nodes[static_cast<std::size_t>(st.attachNode)].world.position;
    // Where a child is thicker than its parent there, the parent's cross sections widen to hold it: the
    // radius is that of the parent's cross sections on either side of the attachment, as built.
    double ra = std::max(parent.radius(s - 1e-9), 1e-12);
    const auto& arcs = rings.onSkeleton[static_cast<std::size_t>(st.parentStem)];
    const auto above = std::lower_bound(arcs.begin(), arcs.end(), std::pair<double, double>{s, 0.0});
    if (above != arcs.end()) ra = std::max(ra, above->second);
    if (above != arcs.begin()) ra = std::max(ra, std::prev(above)->second);
    const Vec3 d = tree.rings[static_cast<std::size_t>(rings.first[c])].center - attach;
    out.push_back(ChildPlacement{static_cast<int>(c), st.parentStem, std::abs(glm::dot(d, parent.direction(s))) / ra, s, ra,
                                 !arcs.empty() && s < arcs.front().first});
  }
  return out;
}

std::vector<TipOvershoot> tipOvershoots(const Skeleton& skeleton, const TreeMesh& tree) {
  const StemRings rings = stemRings(skeleton, tree);
  std::vector<TipOvershoot> out;
  for (std::size_t i = 0; i < skeleton.stems.size(); ++i) {
    const SkeletonStem& st = skeleton.stems[i];
    if (rings.last[i] < 0 || st.nodeCount == 0) continue;
    const SkeletonNode& tip = skeleton.nodes[static_cast<std::size_t>(st.firstNode + st.nodeCount - 1)];
    if (tip.kind != NodeKind::Tip) continue;
    const StemPolyline poly(skeleton, static_cast<int>(i));
    const Vec3 d = tree.rings[static_cast<std::size_t>(rings.last[i])].center - tip.world.position;
    out.push_back(TipOvershoot{static_cast<int>(i), glm::dot(d, poly.endDirection()), tip.radius, poly.length(), st.startRadius});
  }
  return out;
}

}  // namespace arbor
