#pragma once
// A tree on the GPU: its vertices (also read by the ACC control shader), triangle indices (flat, PN) and
// patches with their control point indices (ACC).
#include "camera.hpp"
#include "growth/skeleton.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/quad_mesh.hpp"
#include "patches/patch_set.hpp"
#include "tree/wind.hpp"
#include "vk/buffer.hpp"

namespace arbor::render {

struct GpuTree {
  vk::Buffer vertices;   // per vertex: position + radius, normal + level, uvw
  vk::Buffer farVertices;  // the same at the limit surface: far trees drawn flat look as ACC at factor 1
  vk::Buffer indices;    // triangles, three per quad pair
  vk::Buffer patches;    // per patch: point offset, valences, prefixes, kind
  vk::Buffer points;     // control point vertex indices
  vk::Buffer leaves;     // per leaf: base + length, direction + half width, normal + kind; in random order
  vk::Buffer impostors;  // per fake-branch segment: parent node + radius, node + radius, bark v at both, level
  vk::Buffer wind;       // wind records (interface.h): vertices, leaves (in their buffer's order), segment ends
  float windHeight = 0;  // the tree's height for the trunk's bend; 0: no wind records
  std::uint32_t leafWindBase = 0, impostorWindBase = 0;  // vec4 indices in `wind`
  std::uint32_t leafCount = 0, impostorCount = 0;
  std::uint32_t sketchCount = 0;  // the sketch's segments follow the impostors' in the same buffer
  std::uint32_t vertexCount = 0, triangles = 0, patchCount = 0;
  std::uint32_t regular = 0, extraordinary = 0, fallback = 0;
  std::size_t bytes = 0;  // all buffers together
  std::uint64_t id = 0;   // unique per upload: the renderer keeps this mesh's control points under it
  Bounds bounds;           // object space, of the mesh and the fake branches
  Bounds leafBounds;       // object space, of the leaves' bases: no leaf is nearer the eye than this box
  float plantingDepth = 0;  // how far the tree is sunk so that the closed base's rounded limit surface is underground
};

// Where the tree stands in the world: sunk by its planting depth.
glm::mat4 plantedModel(const GpuTree& tree);
// The world-space bounds of the planted tree.
Bounds plantedBounds(const GpuTree& tree);

// `leaves` (the skeleton's) are shuffled with a fixed seed, so any prefix of them is a fair sample of the crown.
// `impostors` are the fake branches standing in for the stems the mesh leaves out.
GpuTree uploadTree(const vk::VulkanContext& context, const QuadMesh& mesh, const PatchSet& patches,
                   const std::vector<Leaf>& leaves = {}, const std::vector<ImpostorSegment>& impostors = {},
                   const std::vector<ImpostorSegment>& sketch = {}, bool far = false, const TreeWind* wind = nullptr);

}  // namespace arbor::render
