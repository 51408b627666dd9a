#include "pipelines.hpp"

#include <array>
#include <vector>

#include "spirv_acc_tesc.h"
#include "spirv_acc_tese.h"
#include "spirv_acc_vert.h"
#include "spirv_line_frag.h"
#include "spirv_line_vert.h"
#include "spirv_flat_vert.h"
#include "spirv_ground_frag.h"
#include "spirv_ground_vert.h"
#include "spirv_leaf_frag.h"
#include "spirv_leaf_geom.h"
#include "spirv_point_vert.h"
#include "spirv_ceiling_tesc.h"
#include "spirv_ceiling_tese.h"
#include "spirv_ceiling_frag.h"
#include "spirv_impostor_geom.h"
#include "spirv_impostor_frag.h"
#include "spirv_pn_tesc.h"
#include "spirv_pn_tese.h"
#include "spirv_pn_vert.h"
#include "spirv_sky_frag.h"
#include "spirv_sky_vert.h"
#include "spirv_tree_frag.h"

namespace arbor::render {

const char* renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Flat: return "flat";
    case RenderMode::PN: return "pn";
    case RenderMode::ACC: return "acc";
  }
  return "acc";
}

namespace {

struct Stage {
  VkShaderStageFlagBits stage;
  const std::uint32_t* code;
  std::size_t bytes;
};

template <std::size_t N>
Stage stage(VkShaderStageFlagBits s, const std::uint32_t (&code)[N]) {
  return Stage{s, code, sizeof(code)};
}

struct PipelineSpec {
  std::vector<Stage> stages;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  std::uint32_t patchPoints = 0;   // > 0: tessellated
  bool treeVertices = false;       // vertex input: the tree's vertex buffer
  bool lineVertices = false;       // vertex input: LineVertex (position, colour)
  bool depthWrite = true;
  bool wireframe = false;
  bool cullBack = true;
};

VkShaderModule module(VkDevice device, const Stage& s) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = s.bytes;
  info.pCode = s.code;
  VkShaderModule m = VK_NULL_HANDLE;
  vk::check(vkCreateShaderModule(device, &info, nullptr, &m), "vkCreateShaderModule");
  return m;
}

VkPipeline build(VkDevice device, VkRenderPass renderPass, VkPipelineLayout layout, VkSampleCountFlagBits samples,
                 const PipelineSpec& spec) {
  std::vector<VkShaderModule> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (const Stage& s : spec.stages) {
    modules.push_back(module(device, s));
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = s.stage;
    info.module = modules.back();
    info.pName = "main";
    stages.push_back(info);
  }
  // The tree vertex: position + radius, normal + level, uvw (three vec4, 48 bytes).
  const VkVertexInputBindingDescription binding{0, 48, VK_VERTEX_INPUT_RATE_VERTEX};
  const std::array<VkVertexInputAttributeDescription, 3> attributes{{{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0},
                                                                      {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16},
                                                                      {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 32}}};
  const VkVertexInputBindingDescription lineBinding{0, sizeof(LineVertex), VK_VERTEX_INPUT_RATE_VERTEX};
  const std::array<VkVertexInputAttributeDescription, 2> lineAttributes{{{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0},
                                                                          {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16}}};
  VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  if (spec.lineVertices) {
    input.vertexBindingDescriptionCount = 1;
    input.pVertexBindingDescriptions = &lineBinding;
    input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(lineAttributes.size());
    input.pVertexAttributeDescriptions = lineAttributes.data();
  }
  if (spec.treeVertices) {
    input.vertexBindingDescriptionCount = 1;
    input.pVertexBindingDescriptions = &binding;
    input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes.size());
    input.pVertexAttributeDescriptions = attributes.data();
  }
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = spec.patchPoints > 0 ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : spec.topology;
  VkPipelineTessellationDomainOriginStateCreateInfo origin{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_DOMAIN_ORIGIN_STATE_CREATE_INFO};
  origin.domainOrigin = VK_TESSELLATION_DOMAIN_ORIGIN_LOWER_LEFT;  // (u, v) as in OpenGL and the thesis
  VkPipelineTessellationStateCreateInfo tessellation{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  tessellation.pNext = &origin;
  tessellation.patchControlPoints = spec.patchPoints;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = spec.wireframe ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
  raster.cullMode = spec.cullBack ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;  // outward CCW faces; the projection flips y, keeping the winding
  raster.lineWidth = 1.0f;
  if (spec.wireframe) {
    raster.depthBiasEnable = VK_TRUE;  // the overlay sits on the surface it outlines
    raster.depthBiasConstantFactor = -1.0f;
    raster.depthBiasSlopeFactor = -1.0f;
  }
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = samples;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = spec.depthWrite ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  const std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamicStates.size());
  dynamic.pDynamicStates = dynamicStates.data();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pTessellationState = spec.patchPoints > 0 ? &tessellation : nullptr;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = renderPass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
  vk::check(result, "vkCreateGraphicsPipelines");
  return pipeline;
}

}  // namespace

void Pipelines::destroy(VkDevice device) {
  for (VkPipeline p : {sky, ground, tree[0], tree[1], tree[2], wireframe[0], wireframe[1], wireframe[2], twoSided[0],
                       twoSided[1], twoSided[2], leaves, impostors, ceiling, lines}) {
    if (p) vkDestroyPipeline(device, p, nullptr);
  }
  if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
  if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
  *this = Pipelines{};
}

Pipelines createPipelines(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples) {
  const VkDevice device = context.device();
  Pipelines p;
  const bool geometry = context.features().geometryShader == VK_TRUE;  // leaves need it
  const VkShaderStageFlags all = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
                                 VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT | VK_SHADER_STAGE_FRAGMENT_BIT |
                                 (geometry ? VkShaderStageFlags{VK_SHADER_STAGE_GEOMETRY_BIT} : VkShaderStageFlags{0});
  p.pushStages = all;
  // Each binding reaches only the stages that read it: every extra stage costs lavapipe work on each of the
  // thousands of split tessellation draws (adaptive ACC went from 1.4 to 2.1 s with two bindings for all).
  const VkShaderStageFlags control = VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;  // the stage that fetches vertices
  const VkShaderStageFlags pointStages = geometry ? VkShaderStageFlags{VK_SHADER_STAGE_GEOMETRY_BIT} : VkShaderStageFlags{VK_SHADER_STAGE_VERTEX_BIT};
  const std::array<VkDescriptorSetLayoutBinding, 11> bindings{{
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, control, nullptr},
      {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, control, nullptr},
      {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, control, nullptr},
      {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, nullptr},
      {7, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, nullptr},
      {8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, pointStages, nullptr},
      {9, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, pointStages, nullptr},
  }};
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
  setInfo.pBindings = bindings.data();
  vk::check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &p.setLayout), "vkCreateDescriptorSetLayout");
  const VkPushConstantRange push{all, 0, sizeof(DrawConstants)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &p.setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  vk::check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &p.layout), "vkCreatePipelineLayout");

  PipelineSpec sky{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_sky_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_sky_frag)}};
  sky.depthWrite = false;
  sky.cullBack = false;
  p.sky = build(device, renderPass, p.layout, samples, sky);
  PipelineSpec ground{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_ground_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_ground_frag)}};
  ground.cullBack = false;
  p.ground = build(device, renderPass, p.layout, samples, ground);

  const auto treeFrag = stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_tree_frag);
  PipelineSpec flat{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_flat_vert), treeFrag}};
  flat.treeVertices = true;
  PipelineSpec pn{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_pn_vert), stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, spirv_pn_tesc),
                   stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, spirv_pn_tese), treeFrag}};
  pn.patchPoints = 3;  // the vertex stage fetches its triangle's corners from the index buffer
  PipelineSpec acc{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_acc_vert), stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, spirv_acc_tesc),
                    stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, spirv_acc_tese), treeFrag}};
  acc.patchPoints = 4;  // the quad's corners; the 1-ring comes from the points buffer
  PipelineSpec ceiling{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_acc_vert), stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, spirv_ceiling_tesc),
                        stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, spirv_ceiling_tese),
                        stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_ceiling_frag)}};
  ceiling.patchPoints = 4;
  p.ceiling = build(device, renderPass, p.layout, samples, ceiling);
  PipelineSpec lines{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_line_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_line_frag)}};
  lines.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
  lines.lineVertices = true;
  lines.cullBack = false;
  p.lines = build(device, renderPass, p.layout, samples, lines);
  const PipelineSpec* specs[3] = {&flat, &pn, &acc};
  for (int m = 0; m < 3; ++m) {
    p.tree[m] = build(device, renderPass, p.layout, samples, *specs[m]);
    PipelineSpec twoSided = *specs[m];
    twoSided.cullBack = false;
    p.twoSided[m] = build(device, renderPass, p.layout, samples, twoSided);
    if (context.features().fillModeNonSolid) {
      PipelineSpec wire = *specs[m];
      wire.wireframe = true;
      wire.cullBack = false;
      p.wireframe[m] = build(device, renderPass, p.layout, samples, wire);
    }
  }
  if (geometry) {
    const auto points = stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_point_vert);
    PipelineSpec leaves{{points, stage(VK_SHADER_STAGE_GEOMETRY_BIT, spirv_leaf_geom), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_leaf_frag)}};
    leaves.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    leaves.cullBack = false;  // a leaf is seen from both sides
    p.leaves = build(device, renderPass, p.layout, samples, leaves);
    PipelineSpec impostors{{points, stage(VK_SHADER_STAGE_GEOMETRY_BIT, spirv_impostor_geom),
                            stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_impostor_frag)}};
    impostors.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    impostors.cullBack = false;  // the rectangle's winding depends on which way the branch points on screen
    p.impostors = build(device, renderPass, p.layout, samples, impostors);
  }
  return p;
}

}  // namespace arbor::render
