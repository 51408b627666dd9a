#include "impostor_segments.hpp"

#include <glm/geometric.hpp>

#include "mesh_attributes.hpp"

namespace arbor {

std::vector<ImpostorSegment> impostorSegments(const Skeleton& skeleton, int fromLevel) {
  std::vector<ImpostorSegment> segments;
  // Texture v at each node, so that a stem's bark runs on from segment to segment (and clones continue
  // their source's); a stem leaving a meshed parent starts at 0.
  std::vector<double> v(skeleton.nodes.size(), 0.0);
  for (std::size_t i = 0; i < skeleton.nodes.size(); ++i) {
    const SkeletonNode& node = skeleton.nodes[i];
    if (node.parent < 0 || node.level < fromLevel) continue;
    const auto parentIndex = static_cast<std::size_t>(node.parent);
    const SkeletonNode& parent = skeleton.nodes[parentIndex];
    const double start = parent.level >= fromLevel && parentIndex < i ? v[parentIndex] : 0.0;
    const double length = glm::distance(parent.world.position, node.world.position);
    v[i] = start + barkTextureAdvance(length, 0.5 * (node.startRadius + node.radius));
    segments.push_back({parent.world.position, node.world.position, node.startRadius, node.radius, start, v[i], node.level});
  }
  return segments;
}

FakedTree meshWithFakeBranches(const Skeleton& skeleton, int meshLevels) {
  const bool faked = meshLevels < skeleton.levels;
  MeshOptions options;
  options.levels = faked ? meshLevels : 0;
  return {buildTreeMesh(skeleton, options), faked ? impostorSegments(skeleton, meshLevels) : std::vector<ImpostorSegment>{}};
}

}  // namespace arbor
