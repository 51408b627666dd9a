#include "forest.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace arbor::render {

namespace {

struct Plane {
  glm::vec3 normal;
  float offset;
};

// The six planes of a Vulkan view-projection (depth 0..1), pointing inwards (Gribb & Hartmann).
std::array<Plane, 6> frustumPlanes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::vec4 r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  const glm::vec4 rows[6] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
  std::array<Plane, 6> planes{};
  for (int i = 0; i < 6; ++i) {
    const float length = glm::length(glm::vec3(rows[i]));
    planes[static_cast<std::size_t>(i)] = {glm::vec3(rows[i]) / length, rows[i].w / length};
  }
  return planes;
}

glm::mat4 placementModel(const ForestPlacement& p, float plantingDepth) {
  const glm::mat4 at = glm::translate(glm::mat4(1.0f), glm::vec3(p.position, -plantingDepth));
  return glm::rotate(at, p.rotation, glm::vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace

std::vector<ForestPlacement> placeTrees(const std::vector<float>& crownRadii, std::uint32_t count, std::uint64_t seed, float& areaRadius) {
  std::vector<ForestPlacement> placed;
  if (crownRadii.empty() || count == 0) return placed;
  std::mt19937_64 random(seed * 0x9e3779b97f4a7c15ull + 0x5eed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  double area = 0.0;
  for (std::uint32_t i = 0; i < count; ++i) area += std::pow(crownRadii[i % crownRadii.size()], 2.0);
  // Crowns cover about a third of the disc: dense enough to walk through a forest, sparse enough to place.
  areaRadius = static_cast<float>(std::sqrt(area / 0.33));
  for (std::uint32_t i = 0; i < count; ++i) {
    const auto kind = static_cast<std::uint32_t>(i % crownRadii.size());
    const float r = crownRadii[kind];
    ForestPlacement p{kind, glm::vec2(0.0f), unit(random) * 2.0f * std::numbers::pi_v<float>};
    for (int attempt = 0; i > 0; ++attempt) {
      if (attempt > 0 && attempt % 500 == 0) areaRadius *= 1.1f;  // too crowded: widen the forest
      const float a = unit(random) * 2.0f * std::numbers::pi_v<float>, d = areaRadius * std::sqrt(unit(random));
      p.position = glm::vec2(std::cos(a), std::sin(a)) * d;
      const bool clear = std::all_of(placed.begin(), placed.end(), [&](const ForestPlacement& q) {
        return glm::distance(p.position, q.position) >= r + crownRadii[q.tree];
      });
      if (clear) break;
    }
    placed.push_back(p);
  }
  return placed;
}

Forest::Forest(const vk::VulkanContext& context, const std::vector<DetailedTree>& trees, std::uint32_t instances, std::uint64_t seed) {
  if (trees.empty()) throw std::invalid_argument("a forest needs at least one tree");
  for (const DetailedTree& built : trees) {
    if (built.details.size() != kDetailLevels) throw std::invalid_argument("a forest tree needs " + std::to_string(kDetailLevels) + " details");
    ForestTree tree;
    tree.label = built.label;
    float reach = 0.0f;
    for (std::uint32_t d = 0; d < kDetailLevels; ++d) {
      const TreeGeometry& g = built.details[d];
      tree.detail[d] = uploadTree(context, g.mesh.mesh, g.patches, built.leaves, g.impostors, g.sketch, true, &g.wind);
    }
    for (const glm::vec3& p : built.details[0].mesh.mesh.positions) reach = std::max(reach, glm::length(glm::vec2(p)));
    tree.bounds = tree.detail[0].bounds;
    for (const Leaf& leaf : built.leaves) {
      const glm::vec3 p(leaf.position);
      const auto length = static_cast<float>(leaf.length);
      reach = std::max(reach, glm::length(glm::vec2(p)) + length);
      tree.bounds.lo = glm::min(tree.bounds.lo, p - glm::vec3(length));
      tree.bounds.hi = glm::max(tree.bounds.hi, p + glm::vec3(length));
    }
    tree.bounds.lo.z -= tree.detail[0].plantingDepth;
    tree.bounds.hi.z -= tree.detail[0].plantingDepth;
    tree.crownRadius = reach;
    trees_.push_back(std::move(tree));
  }
  std::vector<float> radii;
  for (const ForestTree& t : trees_) radii.push_back(t.crownRadius);
  placements_ = placeTrees(radii, std::max(1u, instances), seed, radius_);
  if (instances <= 1) placements_.front().rotation = 0.0f;  // a single tree as `arbor render` shows it
}

std::vector<const GpuTree*> Forest::gpuTrees() const {
  std::vector<const GpuTree*> gpu;
  for (const ForestTree& t : trees_) {
    for (const GpuTree& d : t.detail) gpu.push_back(&d);
  }
  return gpu;
}

ForestFrame Forest::frame(const Camera& camera, float aspect, const DetailDistances& distances) const {
  const auto planes = frustumPlanes(projectionMatrix(camera, aspect) * viewMatrix(camera));
  ForestFrame f;
  for (const ForestPlacement& p : placements_) {
    const ForestTree& tree = trees_[p.tree];
    const float height = tree.bounds.hi.z - tree.bounds.lo.z;
    const glm::vec3 center(p.position, 0.5f * (tree.bounds.lo.z + tree.bounds.hi.z));
    const float radius = std::sqrt(tree.crownRadius * tree.crownRadius + 0.25f * height * height);
    const bool inside = std::all_of(planes.begin(), planes.end(), [&](const Plane& q) { return glm::dot(q.normal, center) + q.offset >= -radius; });
    if (!inside) {
      ++f.culled;
      continue;
    }
    const float distance = std::max(0.0f, glm::distance(camera.eye, center) - radius);
    const std::uint32_t detail = distance < distances.full ? 0u : distance < distances.reduced ? 1u : 2u;
    ++f.perDetail[detail];
    ++f.visible;
    const bool far = distance >= distances.far;
    f.far += far ? 1 : 0;
    f.instances.push_back({kDetailLevels * p.tree + detail, placementModel(p, tree.detail[0].plantingDepth), far});
  }
  return f;
}

Camera Forest::overview(float aspect) const {
  float top = 0.0f;
  for (const ForestTree& t : trees_) top = std::max(top, t.bounds.hi.z);
  if (placements_.size() == 1) {
    const ForestTree& t = trees_.front();
    return frameBounds(t.bounds, 25.0f, 6.0f, aspect);
  }
  Bounds all{glm::vec3(1e30f), glm::vec3(-1e30f)};  // the crowns as placed
  for (const ForestPlacement& p : placements_) {
    const float r = trees_[p.tree].crownRadius;
    all.lo = glm::min(all.lo, glm::vec3(p.position - glm::vec2(r), 0.0f));
    all.hi = glm::max(all.hi, glm::vec3(p.position + glm::vec2(r), top));
  }
  return frameBounds(all, 25.0f, 20.0f, aspect);
}

std::vector<Camera> Forest::tour(float aspect) const {
  std::vector<Camera> stops{overview(aspect)};
  const ForestTree& first = trees_.front();
  if (placements_.size() == 1) {
    for (float azimuth : {115.0f, 205.0f}) stops.push_back(frameBounds(first.bounds, azimuth, 6.0f, aspect));
    return stops;
  }
  const float eyeHeight = 1.7f, crownMiddle = 0.6f * first.bounds.hi.z;
  Camera edge;
  edge.eye = glm::vec3(0.0f, -(radius_ + first.crownRadius + 6.0f), eyeHeight);
  edge.target = glm::vec3(0.0f, 0.0f, crownMiddle);
  stops.push_back(edge);
  Camera inside;
  inside.eye = glm::vec3(0.5f * first.crownRadius + 1.0f, -1.5f * first.crownRadius - 1.0f, eyeHeight);
  inside.target = glm::vec3(0.0f, 0.0f, crownMiddle);
  stops.push_back(inside);
  return stops;
}

}  // namespace arbor::render
