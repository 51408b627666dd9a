#include "pipelines.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "spirv_draw_commands_comp.h"
#include "spirv_patch_cull_comp.h"
#include "spirv_wind_comp.h"
#include "spirv_patch_vert.h"
#include "spirv_line_frag.h"
#include "spirv_line_vert.h"
#include "spirv_ground_frag.h"
#include "spirv_ground_vert.h"
#include "spirv_leaf_frag.h"
#include "spirv_leaf_vert.h"
#include "spirv_ceiling_tesc.h"
#include "spirv_ceiling_tese.h"
#include "spirv_ceiling_frag.h"
#include "spirv_impostor_vert.h"
#include "spirv_impostor_frag.h"
#include "spirv_sky_frag.h"
#include "spirv_sky_vert.h"
#include "spirv_tree_frag.h"

namespace arbor::render {

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

Stage stage(VkShaderStageFlagBits s, const SpirvCode& code) { return Stage{s, code.words, code.bytes}; }

struct PipelineSpec {
  std::vector<Stage> stages;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  std::uint32_t patchPoints = 0;   // > 0: tessellated
  bool treeVertices = false;       // vertex input: the tree's vertex buffer
  bool lineVertices = false;       // vertex input: LineVertex (position, colour)
  bool depthWrite = true;
  bool wireframe = false;
  bool cullBack = true;
  std::array<VkBool32, 3> specialization{};  // ARBOR_SPEC_DISPLACED, _CAPTURE and _WIND, for every stage
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
  // A stage that declares neither constant ignores them.
  const std::array<VkSpecializationMapEntry, 3> entries{{{ARBOR_SPEC_DISPLACED, 0, sizeof(VkBool32)},
                                                         {ARBOR_SPEC_CAPTURE, sizeof(VkBool32), sizeof(VkBool32)},
                                                         {ARBOR_SPEC_WIND, 2 * sizeof(VkBool32), sizeof(VkBool32)}}};
  const VkSpecializationInfo specialization{static_cast<std::uint32_t>(entries.size()), entries.data(), sizeof spec.specialization,
                                            spec.specialization.data()};
  std::vector<VkShaderModule> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (const Stage& s : spec.stages) {
    modules.push_back(module(device, s));
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = s.stage;
    info.module = modules.back();
    info.pName = "main";
    info.pSpecializationInfo = &specialization;
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

VkPipeline buildCompute(VkDevice device, VkPipelineLayout layout, const Stage& s) {
  const VkShaderModule m = module(device, s);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = VkPipelineShaderStageCreateInfo{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = m;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device, m, nullptr);
  vk::check(result, "vkCreateComputePipelines");
  return pipeline;
}

// A descriptor set layout of these bindings and a pipeline layout of that one set and one push-constant range.
void createLayouts(VkDevice device, const VkDescriptorSetLayoutBinding* bindings, std::uint32_t count, const VkPushConstantRange& push,
                   VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout) {
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = count;
  setInfo.pBindings = bindings;
  vk::check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  vk::check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
}

// The compute passes' set: the scene, a tree's buffers, the control points and this frame's lists.
void createComputeLayouts(VkDevice device, Pipelines& p) {
  std::array<VkDescriptorSetLayoutBinding, ARBOR_COMPUTE_BINDINGS> bindings{};
  for (std::uint32_t b = 0; b < bindings.size(); ++b) {
    bindings[b] = {b, b == ARBOR_COMPUTE_SCENE ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                   VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  }
  createLayouts(device, bindings.data(), static_cast<std::uint32_t>(bindings.size()),
                {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PassConstants)}, p.computeSetLayout, p.computeLayout);
}

// A surface pipeline filled, two-sided and (where asked and the device can) as wireframe.
SurfacePipelines buildSurface(const Pipelines& p, const PipelineSpec& spec, bool wireframe) {
  SurfacePipelines s;
  s.fill = build(p.device, p.renderPass, p.layout, p.samples, spec);
  PipelineSpec twoSided = spec;
  twoSided.cullBack = false;
  s.twoSided = build(p.device, p.renderPass, p.layout, p.samples, twoSided);
  if (wireframe && p.wireframes) {
    PipelineSpec wire = spec;
    wire.wireframe = true;
    wire.cullBack = false;
    s.wireframe = build(p.device, p.renderPass, p.layout, p.samples, wire);
  }
  return s;
}

// The tree in `info`'s mode: its own stages (or its factor-1 vertex stage) with the bark fragment stage.
PipelineSpec treeSpec(const RenderModeInfo& info, bool corners, bool displaced, bool capture, bool windy) {
  const Stage fragment = stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_tree_frag);
  PipelineSpec spec{{stage(VK_SHADER_STAGE_VERTEX_BIT, corners ? info.corners : info.vertex), fragment}};
  spec.specialization = {displaced ? VK_TRUE : VK_FALSE, capture ? VK_TRUE : VK_FALSE, windy ? VK_TRUE : VK_FALSE};
  if (info.primitive == PatchPrimitive::None) {
    spec.treeVertices = true;
  } else if (!corners) {
    spec.stages.insert(spec.stages.begin() + 1, {stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, info.control),
                                                 stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, info.evaluation)});
    spec.patchPoints = 1;  // the patch's entry in this frame's list; its points come from the control buffer
  }
  return spec;
}

}  // namespace

const SurfacePipelines& Pipelines::surface(RenderMode mode, std::size_t variant) {
  const RenderModeInfo& info = renderModeInfo(mode);
  const bool tessellated = info.primitive != PatchPrimitive::None;
  const bool displaced = tessellated && (variant & 1u) != 0;
  const bool capture = info.captures && (variant & 2u) != 0;
  const bool windy = !tessellated && (variant & 4u) != 0;
  SurfacePipelines& s = modes[static_cast<std::size_t>(mode)].surface[pipelineVariant(displaced, capture, windy)];
  if (!s.fill) s = buildSurface(*this, treeSpec(info, false, displaced, capture, windy), !capture);
  return s;
}

VkPipeline Pipelines::cards(bool leafCards, bool windy) {
  VkPipeline& p = (leafCards ? leaves : impostors)[windy ? 1 : 0];
  if (p) return p;
  // Indexed triangles whose vertex stage reads its leaf or segment by gl_VertexIndex (cards.hpp).
  PipelineSpec spec{leafCards ? std::vector<Stage>{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_leaf_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_leaf_frag)}
                              : std::vector<Stage>{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_impostor_vert),
                                                   stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_impostor_frag)}};
  spec.cullBack = false;  // a leaf is seen from both sides; a fake branch's winding depends on its direction on screen
  spec.specialization[2] = windy ? VK_TRUE : VK_FALSE;
  p = build(device, renderPass, layout, samples, spec);
  return p;
}

const SurfacePipelines& Pipelines::corners(RenderMode mode, bool displaced) {
  const RenderModeInfo& info = renderModeInfo(mode);
  if (info.primitive == PatchPrimitive::None) throw std::logic_error("the flat mode draws no patches at factor 1");
  SurfacePipelines& s = modes[static_cast<std::size_t>(mode)].corners[displaced ? 1 : 0];
  if (!s.fill) s = buildSurface(*this, treeSpec(info, true, displaced, false, false), true);
  return s;
}

void Pipelines::destroy() {
  std::vector<VkPipeline> all{sky, ground, leaves[0], leaves[1], impostors[0], impostors[1], ceiling, lines, cull, drawCommands, wind};
  for (const ModePipelines& m : modes) {
    all.push_back(m.build);
    auto add = [&](const SurfacePipelines& s) { all.insert(all.end(), {s.fill, s.wireframe, s.twoSided}); };
    for (const SurfacePipelines& s : m.surface) add(s);
    for (const SurfacePipelines& s : m.corners) add(s);
  }
  for (VkPipeline p : all) {
    if (p) vkDestroyPipeline(device, p, nullptr);
  }
  for (VkPipelineLayout l : {layout, computeLayout}) {
    if (l) vkDestroyPipelineLayout(device, l, nullptr);
  }
  for (VkDescriptorSetLayout l : {setLayout, computeSetLayout}) {
    if (l) vkDestroyDescriptorSetLayout(device, l, nullptr);
  }
  *this = Pipelines{};
}

Pipelines createPipelines(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples) {
  const VkDevice device = context.device();
  Pipelines p;
  p.device = device;
  p.renderPass = renderPass;
  p.samples = samples;
  p.wireframes = context.features().fillModeNonSolid;
  const VkShaderStageFlags all = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
                                 VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  p.pushStages = all;
  // Each binding reaches only the stages that read it: every extra stage costs lavapipe work on each of the
  // thousands of split tessellation draws (adaptive ACC went from 1.4 to 2.1 s with two bindings for all).
  const VkShaderStageFlags evaluation = VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
  const std::array<VkDescriptorSetLayoutBinding, 10> bindings{{
      {ARBOR_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
      {ARBOR_BINDING_BARK_COLOR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {ARBOR_BINDING_BARK_HEIGHT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_VERTEX_BIT | evaluation, nullptr},
      {ARBOR_BINDING_CAPTURE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, evaluation, nullptr},
      {ARBOR_BINDING_LEAVES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {ARBOR_BINDING_LEAF_ATLAS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {ARBOR_BINDING_IMPOSTORS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {ARBOR_BINDING_CONTROL, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | evaluation, nullptr},
      {ARBOR_BINDING_VISIBLE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {ARBOR_BINDING_WIND, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
  }};
  createLayouts(device, bindings.data(), static_cast<std::uint32_t>(bindings.size()), {all, 0, sizeof(DrawConstants)}, p.setLayout,
                p.layout);

  PipelineSpec sky{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_sky_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_sky_frag)}};
  sky.depthWrite = false;
  sky.cullBack = false;
  p.sky = build(device, renderPass, p.layout, samples, sky);
  PipelineSpec ground{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_ground_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_ground_frag)}};
  ground.cullBack = false;
  p.ground = build(device, renderPass, p.layout, samples, ground);

  PipelineSpec ceiling{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_patch_vert), stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, spirv_ceiling_tesc),
                        stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, spirv_ceiling_tese),
                        stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_ceiling_frag)}};
  ceiling.patchPoints = 1;
  p.ceiling = build(device, renderPass, p.layout, samples, ceiling);
  PipelineSpec lines{{stage(VK_SHADER_STAGE_VERTEX_BIT, spirv_line_vert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, spirv_line_frag)}};
  lines.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
  lines.lineVertices = true;
  lines.cullBack = false;
  p.lines = build(device, renderPass, p.layout, samples, lines);
  createComputeLayouts(device, p);
  p.cull = buildCompute(device, p.computeLayout, stage(VK_SHADER_STAGE_COMPUTE_BIT, spirv_patch_cull_comp));
  p.drawCommands = buildCompute(device, p.computeLayout, stage(VK_SHADER_STAGE_COMPUTE_BIT, spirv_draw_commands_comp));
  p.wind = buildCompute(device, p.computeLayout, stage(VK_SHADER_STAGE_COMPUTE_BIT, spirv_wind_comp));
  for (const RenderModeInfo& info : renderModes()) {
    if (info.primitive == PatchPrimitive::None) continue;
    p.modes[static_cast<std::size_t>(info.mode)].build = buildCompute(device, p.computeLayout, stage(VK_SHADER_STAGE_COMPUTE_BIT, info.build));
  }
  return p;
}

}  // namespace arbor::render
