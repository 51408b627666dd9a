#include "gpu_tree.hpp"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>

namespace arbor::render {

namespace {

struct GpuVertex {
  glm::vec4 positionRadius;
  glm::vec4 normalLevel;
  glm::vec4 uvw;
};

std::uint32_t pack(const std::array<std::uint8_t, 4>& bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
         (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
}

}  // namespace

GpuTree uploadTree(const vk::VulkanContext& context, const QuadMesh& mesh, const PatchSet& patches) {
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
  tree.indices = vk::uploadBuffer(context, triangles.data(), triangles.size() * sizeof(triangles[0]), storage | VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  tree.patches = vk::uploadBuffer(context, records.data(), records.size() * sizeof(glm::uvec4), storage);
  tree.points = vk::uploadBuffer(context, patches.points.data(), patches.points.size() * sizeof(std::uint32_t), storage);
  tree.triangles = static_cast<std::uint32_t>(triangles.size());
  tree.patchCount = static_cast<std::uint32_t>(patches.size());
  tree.bytes = tree.vertices.size() + tree.indices.size() + tree.patches.size() + tree.points.size();
  tree.bounds = meshBounds(mesh);
  const float baseBand = tree.bounds.lo.z + 1e-3f * (tree.bounds.hi.z - tree.bounds.lo.z);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (mesh.level[i] == 0 && mesh.positions[i].z <= baseBand) tree.plantingDepth = std::max(tree.plantingDepth, mesh.radius[i]);
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
