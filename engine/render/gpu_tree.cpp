#include "gpu_tree.hpp"

#include <algorithm>
#include <atomic>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>

#include "interface.h"
#include "patches/acc.hpp"

namespace arbor::render {

namespace {

struct GpuVertex {
  glm::vec4 positionRadius;
  glm::vec4 normalLevel;
  glm::vec4 uvw;
};

struct GpuLeaf {
  glm::vec4 positionLength, directionWidth, normalKind;
};

struct GpuImpostor {
  glm::vec4 fromRadius, toRadius, barkV;
};

std::uint32_t pack(const std::array<std::uint8_t, 4>& bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
         (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
}

}  // namespace

GpuTree uploadTree(const vk::VulkanContext& context, const QuadMesh& mesh, const PatchSet& patches,
                   const std::vector<Leaf>& leaves, const std::vector<ImpostorSegment>& impostors,
                   const std::vector<ImpostorSegment>& sketch, bool far, const TreeWind* wind) {
  std::vector<GpuVertex> vertices(mesh.vertexCount());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {glm::vec4(mesh.positions[i], mesh.radius[i]), glm::vec4(mesh.normals[i], mesh.level[i]),
                   glm::vec4(mesh.uvw[i], 0.0f)};
  }
  const auto triangles = triangulate(mesh);
  std::vector<glm::uvec4> records(patches.size());
  GpuTree tree;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    records[p] = glm::uvec4(patches.offset[p], pack(patches.valence[p]), pack(patches.prefix[p]),
                            static_cast<std::uint32_t>(patches.kind[p]));
    tree.regular += patches.kind[p] == PatchKind::Regular ? 1 : 0;
    tree.extraordinary += patches.kind[p] == PatchKind::Extraordinary ? 1 : 0;
    tree.fallback += patches.kind[p] == PatchKind::Fallback ? 1 : 0;
  }
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  tree.vertices = vk::uploadBuffer(context, vertices.data(), vertices.size() * sizeof(GpuVertex),
                                   storage | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (far && !vertices.empty()) {
    const LimitVertices limit = limitVertices(mesh, patches);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      vertices[i].positionRadius = glm::vec4(limit.positions[i], mesh.radius[i]);
      vertices[i].normalLevel = glm::vec4(limit.normals[i], mesh.level[i]);
    }
    tree.farVertices = vk::uploadBuffer(context, vertices.data(), vertices.size() * sizeof(GpuVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  }
  tree.indices = vk::uploadBuffer(context, triangles.data(), triangles.size() * sizeof(triangles[0]), storage | VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  tree.patches = vk::uploadBuffer(context, records.data(), records.size() * sizeof(glm::uvec4), storage);
  tree.points = vk::uploadBuffer(context, patches.points.data(), patches.points.size() * sizeof(std::uint32_t), storage);
  tree.triangles = static_cast<std::uint32_t>(triangles.size());
  tree.vertexCount = static_cast<std::uint32_t>(mesh.vertexCount());
  tree.patchCount = static_cast<std::uint32_t>(patches.size());
  // Leaves in a random order (Nystad 6.5): thinning and self-shadowing take prefixes of it.
  std::vector<GpuLeaf> leafRecords;
  leafRecords.reserve(leaves.size());
  for (const Leaf& l : leaves) {
    leafRecords.push_back({glm::vec4(glm::vec3(l.position), static_cast<float>(l.length)),
                           glm::vec4(glm::normalize(glm::vec3(l.direction)), static_cast<float>(0.5 * l.width)),
                           glm::vec4(glm::normalize(glm::vec3(l.normal)), static_cast<float>(l.kind))});
  }
  std::vector<std::size_t> leafOrder(leafRecords.size());
  for (std::size_t i = 0; i < leafOrder.size(); ++i) leafOrder[i] = i;
  std::mt19937 shuffle(0x1eaf5eedu);
  for (std::size_t i = leafRecords.size(); i > 1; --i) {
    const std::size_t j = std::uniform_int_distribution<std::size_t>(0, i - 1)(shuffle);
    std::swap(leafRecords[i - 1], leafRecords[j]);
    std::swap(leafOrder[i - 1], leafOrder[j]);
  }
  tree.leafCount = static_cast<std::uint32_t>(leafRecords.size());
  if (!leaves.empty()) tree.leafBounds = {glm::vec3(leaves.front().position), glm::vec3(leaves.front().position)};
  for (const Leaf& l : leaves) {
    tree.leafBounds.lo = glm::min(tree.leafBounds.lo, glm::vec3(l.position));
    tree.leafBounds.hi = glm::max(tree.leafBounds.hi, glm::vec3(l.position));
  }
  if (!leafRecords.empty()) {
    tree.leaves = vk::uploadBuffer(context, leafRecords.data(), leafRecords.size() * sizeof(GpuLeaf), storage);
  }
  std::vector<GpuImpostor> impostorRecords;
  impostorRecords.reserve(impostors.size() + sketch.size());
  for (const auto* list : {&impostors, &sketch}) {
    for (const ImpostorSegment& s : *list) {
      impostorRecords.push_back({glm::vec4(glm::vec3(s.from), static_cast<float>(s.fromRadius)),
                                 glm::vec4(glm::vec3(s.to), static_cast<float>(s.toRadius)),
                                 glm::vec4(static_cast<float>(s.fromV), static_cast<float>(s.toV), static_cast<float>(s.level), 0.0f)});
    }
  }
  tree.impostorCount = static_cast<std::uint32_t>(impostors.size());
  tree.sketchCount = static_cast<std::uint32_t>(sketch.size());
  if (!impostorRecords.empty()) {
    tree.impostors = vk::uploadBuffer(context, impostorRecords.data(), impostorRecords.size() * sizeof(GpuImpostor), storage);
  }
  // Wind records, when the tree has them for every vertex, leaf and segment end (the leaves in their shuffled order).
  const std::size_t segments = impostors.size() + sketch.size();
  if (wind && wind->height > 0.0 && wind->mesh.size() == mesh.vertexCount() && wind->leaves.size() == leaves.size() &&
      wind->segmentEnds.size() == 2 * segments) {
    std::vector<glm::vec4> windRecords;
    windRecords.reserve(ARBOR_WIND_VEC4S * (mesh.vertexCount() + leaves.size() + 2 * segments));
    auto add = [&windRecords, wind](const WindPoint& p, float flutterPhase) {
      windRecords.emplace_back(p.reach[0], p.reach[1], p.reach[2], static_cast<float>(wind->phase));
      windRecords.emplace_back(p.phase[0], p.phase[1], p.phase[2], flutterPhase);
    };
    for (const WindPoint& p : wind->mesh) add(p, 0.0f);
    tree.leafWindBase = static_cast<std::uint32_t>(windRecords.size());
    for (const std::size_t i : leafOrder) add(wind->leaves[i], leafFlutterPhase(static_cast<std::uint32_t>(i)));
    tree.impostorWindBase = static_cast<std::uint32_t>(windRecords.size());
    for (const WindPoint& p : wind->segmentEnds) add(p, 0.0f);
    tree.wind = vk::uploadBuffer(context, windRecords.data(), windRecords.size() * sizeof(glm::vec4), storage);
    tree.windHeight = static_cast<float>(wind->height);
  }
  tree.bytes = tree.vertices.size() + tree.farVertices.size() + tree.indices.size() + tree.patches.size() + tree.points.size() + tree.leaves.size() +
               tree.impostors.size() + tree.wind.size();
  static std::atomic<std::uint64_t> uploads{0};
  tree.id = ++uploads;
  tree.bounds = meshBounds(mesh);
  // Planted so that the limit surface is at full width at the ground: the closed base's corners (limit
  // positions) are pulled up and in, and the rounding reaches about half a radius above them.
  const float baseBand = tree.bounds.lo.z + 1e-3f * (tree.bounds.hi.z - tree.bounds.lo.z);
  float baseRadius = 0.0f, limitTop = tree.bounds.lo.z;
  const auto position = [&mesh](std::uint32_t v) { return glm::dvec3(mesh.positions[v]); };
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches.kind[p] == PatchKind::Fallback) continue;
    constexpr std::size_t kBezierCorner[4] = {0, 3, 15, 12};  // quad corner i's limit point among the 16
    std::array<glm::dvec3, 16> bezier{};
    bool built = false;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::uint32_t v = mesh.quads[p][i];
      if (mesh.level[v] != 0 || mesh.positions[v].z > baseBand) continue;
      if (!built) bezier = accControlPoints(patches, p, position), built = true;
      baseRadius = std::max(baseRadius, mesh.radius[v]);
      limitTop = std::max(limitTop, static_cast<float>(bezier[kBezierCorner[i]].z));
    }
  }
  tree.plantingDepth = limitTop - tree.bounds.lo.z + 0.5f * baseRadius;
  // The fake branches are part of the tree too: a camera framing the bounds frames them (planted by the mesh alone).
  for (const auto* list : {&impostors, &sketch}) {
    for (const ImpostorSegment& seg : *list) {
      for (const auto& [p, r] : {std::pair{seg.from, seg.fromRadius}, std::pair{seg.to, seg.toRadius}}) {
        tree.bounds.lo = glm::min(tree.bounds.lo, glm::vec3(p) - glm::vec3(static_cast<float>(r)));
        tree.bounds.hi = glm::max(tree.bounds.hi, glm::vec3(p) + glm::vec3(static_cast<float>(r)));
      }
    }
  }
  return tree;
}

glm::mat4 plantedModel(const GpuTree& tree) {
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -tree.plantingDepth));
}

Bounds plantedBounds(const GpuTree& tree) {
  const glm::vec3 down(0.0f, 0.0f, tree.plantingDepth);
  return Bounds{tree.bounds.lo - down, tree.bounds.hi - down};
}

}  // namespace arbor::render
