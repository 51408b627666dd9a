#pragma once
// The graphics pipelines: sky, ground, the tree in three modes (flat, PN-triangles, ACC), each also as
// wireframe, and coloured lines; one descriptor set layout and pipeline layout shared by all.
#include "vk/context.hpp"

namespace arbor::render {

enum class RenderMode { Flat, PN, ACC };
const char* renderModeName(RenderMode mode);

struct Pipelines {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE, ground = VK_NULL_HANDLE;
  VkPipeline tree[3] = {};       // by RenderMode
  VkPipeline wireframe[3] = {};  // null where the device has no fillModeNonSolid
  VkPipeline twoSided[3] = {};   // no culling: back faces seen through cracks show (crack tests)
  VkPipeline leaves = VK_NULL_HANDLE;     // null where the device has no geometry shaders
  VkPipeline impostors = VK_NULL_HANDLE;  // fake branches; null likewise
  VkPipeline ceiling = VK_NULL_HANDLE;    // ACC's patches with trivial stages (bench tess)
  VkPipeline lines = VK_NULL_HANDLE;      // unlit coloured line lists (the modeller's wireframes)
  VkShaderStageFlags pushStages = 0;   // every stage the layout's push constants and bindings reach

  void destroy(VkDevice device);
};

// Push constants: the tree's model matrix, the first patch of the draw, the tree's leaf count.
struct DrawConstants {
  float model[16];
  std::uint32_t patchBase;
  std::uint32_t leafCount;
  std::uint32_t pad[2];
};

// One end of a wireframe line: object-space position (w unused) and colour (a unused); 32 bytes.
struct LineVertex {
  float position[4];
  float color[4];
};
static_assert(sizeof(LineVertex) == 32, "line.vert reads two vec4 per vertex");

Pipelines createPipelines(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples);

}  // namespace arbor::render
