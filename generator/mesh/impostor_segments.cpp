#include "impostor_segments.hpp"

#include <glm/geometric.hpp>

#include "mesh_attributes.hpp"

namespace arbor {

namespace {

// The segment from node i's parent node to node i, its bark's v running on from `startV`.
ImpostorSegment segmentTo(const Skeleton& skeleton, std::size_t i, double startV) {
  const SkeletonNode& node = skeleton.nodes[i];
  const SkeletonNode& parent = skeleton.nodes[static_cast<std::size_t>(node.parent)];
  const double length = glm::distance(parent.world.position, node.world.position);
  const double v = startV + barkTextureAdvance(length, 0.5 * (node.startRadius + node.radius));
  return {parent.world.position, node.world.position, node.startRadius, node.radius, startV, v, node.level, node.parent, static_cast<std::int32_t>(i)};
}

}  // namespace

std::vector<ImpostorSegment> impostorSegments(const Skeleton& skeleton, int fromLevel) {
  std::vector<ImpostorSegment> segments;
  // Texture v at each node, so that a stem's bark runs on from segment to segment (and clones continue
  // their source's); a stem leaving a meshed parent starts at 0.
  std::vector<double> v(skeleton.nodes.size(), 0.0);
  // Stubs are never meshed, so they are fake branches at every level.
  auto faked = [&](const SkeletonNode& node) {
    return node.level >= fromLevel || (node.stem >= 0 && skeleton.stems[static_cast<std::size_t>(node.stem)].stub);
  };
  for (std::size_t i = 0; i < skeleton.nodes.size(); ++i) {
    const SkeletonNode& node = skeleton.nodes[i];
    if (node.parent < 0 || !faked(node)) continue;
    const auto parentIndex = static_cast<std::size_t>(node.parent);
    const SkeletonNode& parent = skeleton.nodes[parentIndex];
    segments.push_back(segmentTo(skeleton, i, faked(parent) && parentIndex < i ? v[parentIndex] : 0.0));
    v[i] = segments.back().toV;
  }
  return segments;
}

std::vector<ImpostorSegment> stemSegments(const Skeleton& skeleton, const std::vector<int>& stems) {
  std::vector<ImpostorSegment> segments;
  for (const int s : stems) {
    const SkeletonStem& stem = skeleton.stems[static_cast<std::size_t>(s)];
    double v = 0.0;
    for (int n = stem.firstNode; n < stem.firstNode + stem.nodeCount; ++n) {
      if (skeleton.nodes[static_cast<std::size_t>(n)].parent < 0) continue;
      segments.push_back(segmentTo(skeleton, static_cast<std::size_t>(n), v));
      v = segments.back().toV;
    }
  }
  return segments;
}

std::vector<ImpostorSegment> leftOutSegments(const Skeleton& skeleton, int fromLevel, const std::vector<int>& fakedStems) {
  std::vector<ImpostorSegment> segments = impostorSegments(skeleton, fromLevel);
  const std::vector<ImpostorSegment> faked = stemSegments(skeleton, fakedStems);
  segments.insert(segments.end(), faked.begin(), faked.end());
  return segments;
}

std::vector<ImpostorSegment> sketchSegments(const Skeleton& skeleton, int fromLevel, int belowLevel) {
  std::vector<ImpostorSegment> segments;
  for (const SkeletonStem& stem : skeleton.stems) {
    if (stem.level < fromLevel || stem.level >= belowLevel || stem.nodeCount <= 0) continue;
    int from = stem.attachNode >= 0 ? stem.attachNode : stem.firstNode;
    double v = 0.0;
    for (int n = stem.firstNode; n < stem.firstNode + stem.nodeCount; ++n) {
      const SkeletonNode& node = skeleton.nodes[static_cast<std::size_t>(n)];
      const bool last = n + 1 == stem.firstNode + stem.nodeCount;
      if (!last && node.kind != NodeKind::Joint) continue;  // branch points and their neighbours: not drawn from afar
      const SkeletonNode& start = skeleton.nodes[static_cast<std::size_t>(from)];
      const double length = glm::distance(start.world.position, node.world.position);
      const double fromRadius = from == stem.attachNode ? stem.startRadius : start.radius;
      const double next = v + barkTextureAdvance(length, 0.5 * (fromRadius + node.radius));
      if (length > 0.0) segments.push_back({start.world.position, node.world.position, fromRadius, node.radius, v, next, stem.level, from, n});
      v = next;
      from = n;
    }
  }
  return segments;
}

}  // namespace arbor
