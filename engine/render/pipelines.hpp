#pragma once
// The pipelines: sky, ground, the tree in every render mode (render_modes.hpp) filled, as wireframe and
// two-sided, coloured lines; and the compute passes that build control points and cull, bucket and draw patches.
// One descriptor set layout and pipeline layout for the graphics pipelines, one for the compute passes.
#include <array>

#include "interface.h"
#include "render_modes.hpp"
#include "vk/context.hpp"

namespace arbor::render {

// A surface pipeline filled, as wireframe and two-sided.
struct SurfacePipelines {
  VkPipeline fill = VK_NULL_HANDLE;
  VkPipeline wireframe = VK_NULL_HANDLE;  // null where the device has no fillModeNonSolid
  VkPipeline twoSided = VK_NULL_HANDLE;   // no culling: back faces seen through cracks show (crack tests)
};

// Pipeline variants (interface.h's specialization constants): lavapipe runs both sides of every branch, so
// displacement, the test capture and the wind are compiled into their own variants instead. Tessellated modes
// vary by displacement and capture (their wind is the posed cage), the flat mode and the cards by wind.
constexpr std::size_t kPipelineVariants = 8;
constexpr std::size_t pipelineVariant(bool displaced, bool capture, bool windy = false) {
  return (displaced ? 1u : 0u) + (capture ? 2u : 0u) + (windy ? 4u : 0u);
}

// One render mode's pipelines.
struct ModePipelines {
  // By pipelineVariant, each built on first use (Pipelines::surface).
  std::array<SurfacePipelines, kPipelineVariants> surface;
  std::array<SurfacePipelines, 2> corners;  // tessellated modes: patches at factor 1 without the tessellator, by displaced
  VkPipeline build = VK_NULL_HANDLE;        // compute: control points once per mesh (tessellated modes)
};

struct Pipelines {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE, computeSetLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE, computeLayout = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE, ground = VK_NULL_HANDLE;
  std::array<ModePipelines, kRenderModeCount> modes{};  // by RenderMode
  VkPipeline cull = VK_NULL_HANDLE;          // per frame: cull, set factors, bucket (patch_cull.comp)
  VkPipeline drawCommands = VK_NULL_HANDLE;  // per frame: buckets -> indirect draws (draw_commands.comp)
  VkPipeline wind = VK_NULL_HANDLE;          // per frame with wind: the rest cage posed (wind.comp)
  std::array<VkPipeline, 2> leaves{};     // cards (cards.hpp), still and windy: use cards()
  std::array<VkPipeline, 2> impostors{};  // fake branches, cards likewise
  VkPipeline ceiling = VK_NULL_HANDLE;    // ACC's patches with trivial stages (bench tess)
  VkPipeline lines = VK_NULL_HANDLE;      // unlit coloured line lists (the modeller's wireframes)
  VkShaderStageFlags pushStages = 0;   // every stage the layout's push constants and bindings reach

  // A mode's surface or factor-1 pipelines in a variant (pipelineVariant), built the first time one is asked for:
  // most sessions never displace or capture. Capture variants have no wireframe; a mode that cannot capture
  // (RenderModeInfo::captures) gives its variant without capture.
  const SurfacePipelines& surface(RenderMode mode, std::size_t variant);
  const SurfacePipelines& corners(RenderMode mode, bool displaced);
  // The leaf (or fake-branch) cards, still or moving with the wind, likewise built on first use.
  VkPipeline cards(bool leafCards, bool windy);
  void destroy();

  // What building a variant later (and destroy) needs.
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  bool wireframes = false;  // the device has fillModeNonSolid
};

// Push constants of the graphics pipelines: the tree's model matrix and leaf count (scene.glsl's Draw).
struct DrawConstants {
  float model[16];
  std::uint32_t leafCount;
  float windHeight;                // 0: the tree has no wind records
  std::uint32_t leafWindBase;      // vec4 index of the leaves' wind records
  std::uint32_t impostorWindBase;  // and of the fake-branch ends'
};
static_assert(sizeof(DrawConstants) == ARBOR_DRAW_CONSTANTS_BYTES, "scene.glsl's Draw block");

// Push constants of the compute passes (compute.glsl's Pass block): one instance's slice of this frame's lists.
struct PassConstants {
  float model[16];
  std::uint32_t primitiveCount;  // patches or triangles
  std::uint32_t listBase;        // first entry of the instance's lists (bucket b at listBase + b * primitiveCount)
  std::uint32_t counterBase;     // first of its ARBOR_COUNTERS counters
  std::uint32_t commandBase;     // first of its draw commands
  std::uint32_t flags;           // PassFlag bits
  std::uint32_t maxCommands;
  float windHeight;              // wind.comp: the tree's height (primitiveCount: its vertices)
  std::uint32_t pad;
  std::uint32_t perDraw[8];      // patches per draw in each bucket
};
static_assert(sizeof(PassConstants) == ARBOR_PASS_CONSTANTS_BYTES, "compute.glsl's Pass block");
static_assert(ARBOR_BUCKETS <= 8, "PassConstants::perDraw holds eight buckets");

// compute.glsl's pass flags.
enum PassFlag : std::uint32_t { kCullFrustum = 1, kCullBackFaces = 2, kBucketed = 4, kZeroFill = 8, kTriangles = 16, kCornerBucket = 32 };

// One end of a wireframe line: object-space position (w unused) and colour (a unused); 32 bytes.
struct LineVertex {
  float position[4];
  float color[4];
};
static_assert(sizeof(LineVertex) == 32, "line.vert reads two vec4 per vertex");

Pipelines createPipelines(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples);

}  // namespace arbor::render
