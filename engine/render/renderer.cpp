#include "renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace arbor::render {

namespace {

// std140 image of shaders/scene.glsl's Scene block.
struct SceneUniforms {
  glm::mat4 viewProj;
  glm::mat4 view;
  glm::mat4 inverseViewProj;
  glm::vec4 cameraPos;
  glm::vec4 lightDir;
  glm::vec4 viewport;
  glm::vec4 tess;
  glm::vec4 displace;
  glm::vec4 skyTop;
  glm::vec4 skyHorizon;
  glm::vec4 ground;
  glm::uvec4 flags;
  glm::vec4 lens;
  glm::vec4 leafLod;
};

constexpr std::uint32_t kCaptureHeader = 16;  // count, capacity, two words of padding
constexpr std::uint32_t kCaptureEntryBytes = 48;  // three vec4: patch and (u, v), point, displaced point
constexpr std::uint32_t kTimestampCount = 2;
constexpr std::uint32_t kLavapipeInputVerticesPerDraw = 4096;  // beyond it lavapipe garbles patches

// Tessellated vertices one patch emits at `level` with equal spacing (which rounds levels up). A triangle is
// tessellated as concentric rings of 3L, 3(L - 2), ... vertices, ending in a point (L even) or a triangle.
std::uint32_t verticesPerPatch(RenderMode mode, float level) {
  const auto l = static_cast<std::uint32_t>(std::ceil(std::clamp(level, 1.0f, 64.0f)));
  if (mode == RenderMode::ACC) return (l + 1) * (l + 1);
  return l % 2 == 0 ? 1 + 3 * l * (l + 2) / 4 : 3 * ((l + 1) / 2) * ((l + 1) / 2);
}

}  // namespace

TreeRenderer::TreeRenderer(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples,
                           const TreeTextures& textures)
    : context_(context) {
  pipelines_ = createPipelines(context, renderPass, samples);
  const auto upload = [&context](const Image& image, bool srgb) {
    return vk::uploadTexture(context, image.rgba, static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height), srgb);
  };
  barkColor_ = upload(textures.barkColor, true);
  barkHeight_ = upload(textures.barkHeight, false);
  leafAtlas_ = upload(textures.leafAtlas, true);
  sampler_ = vk::createRepeatSampler(context, static_cast<float>(barkColor_.mipLevels()));
  // Coarse MIP levels average a cutout's alpha below the leaf shader's test and whole leaves would vanish with
  // distance: the atlas stops at the level where the blades still hold their shape.
  leafSampler_ = vk::createRepeatSampler(context, 3.0f, false);  // clamped + anisotropic: lavapipe minutes/frame
  scene_ = vk::hostBuffer(context, sizeof(SceneUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  setCapture(0);

  const VkDevice device = context.device();
  const std::array<VkDescriptorPoolSize, 3> sizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kMaxTrees},
                                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 7 * kMaxTrees},
                                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * kMaxTrees}}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = kMaxTrees;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  vk::check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
  setTree(nullptr);

  if (context.features().pipelineStatisticsQuery) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    q.queryCount = 1;
    q.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT;
    vk::check(vkCreateQueryPool(device, &q, nullptr, &statistics_), "vkCreateQueryPool");
  }
  if (context.properties().limits.timestampComputeAndGraphics) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_TIMESTAMP;
    q.queryCount = kTimestampCount;
    vk::check(vkCreateQueryPool(device, &q, nullptr, &timestamps_), "vkCreateQueryPool");
  }
}

TreeRenderer::~TreeRenderer() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  if (statistics_) vkDestroyQueryPool(device, statistics_, nullptr);
  if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
  vkDestroyDescriptorPool(device, pool_, nullptr);
  vkDestroySampler(device, sampler_, nullptr);
  vkDestroySampler(device, leafSampler_, nullptr);
  pipelines_.destroy(device);
}

void TreeRenderer::setCapture(std::uint32_t capacity) {
  captureCapacity_ = capacity;
  capture_ = vk::hostBuffer(context_, kCaptureHeader + static_cast<std::size_t>(std::max(capacity, 1u)) * kCaptureEntryBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memset(capture_.mapped(), 0, kCaptureHeader);
  static_cast<std::uint32_t*>(capture_.mapped())[1] = capacity;
  if (!sets_.empty()) setTrees(trees_);
}

std::vector<CapturedPoint> TreeRenderer::captured() const {
  const auto* header = static_cast<const std::uint32_t*>(capture_.mapped());
  const std::uint32_t count = std::min(header[0], captureCapacity_);
  const auto* entries = reinterpret_cast<const float*>(static_cast<const std::uint8_t*>(capture_.mapped()) + kCaptureHeader);
  std::vector<CapturedPoint> points(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const float* e = entries + kCaptureEntryBytes / sizeof(float) * i;
    points[i] = CapturedPoint{static_cast<std::uint32_t>(e[0]), e[1], e[2], glm::vec3(e[4], e[5], e[6]), glm::vec3(e[8], e[9], e[10]),
                              glm::vec3(e[3], e[7], e[11])};
  }
  return points;
}

void TreeRenderer::setTree(const GpuTree* tree) {
  setTrees(tree ? std::vector<const GpuTree*>{tree} : std::vector<const GpuTree*>{});
}

void TreeRenderer::setTrees(const std::vector<const GpuTree*>& trees) {
  if (trees.size() > kMaxTrees) {
    throw std::runtime_error("a scene may hold at most " + std::to_string(kMaxTrees) + " distinct trees, not " + std::to_string(trees.size()));
  }
  trees_ = trees;
  const std::size_t wanted = std::max<std::size_t>(1, trees.size());  // sky and ground need a set without trees too
  while (sets_.size() < wanted) {
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &pipelines_.setLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    vk::check(vkAllocateDescriptorSets(context_.device(), &alloc, &set), "vkAllocateDescriptorSets");
    sets_.push_back(set);
  }
  for (std::size_t i = 0; i < wanted; ++i) writeSet(sets_[i], i < trees.size() ? trees[i] : nullptr);
}

void TreeRenderer::writeSet(VkDescriptorSet set, const GpuTree* tree) {
  // Without a tree the storage bindings still point at a valid buffer: every binding is always written.
  const VkBuffer fallback = capture_.handle();
  const VkDescriptorBufferInfo sceneInfo{scene_.handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo vertexInfo{tree ? tree->vertices.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo patchInfo{tree ? tree->patches.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo pointInfo{tree ? tree->points.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo indexInfo{tree ? tree->indices.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo leafInfo{tree && tree->leafCount > 0 ? tree->leaves.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo impostorInfo{tree && tree->impostorCount > 0 ? tree->impostors.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorImageInfo atlasInfo{leafSampler_, leafAtlas_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorBufferInfo captureInfo{capture_.handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorImageInfo colorInfo{sampler_, barkColor_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorImageInfo heightInfo{sampler_, barkHeight_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  auto write = [&](std::uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* b, const VkDescriptorImageInfo* i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = b;
    w.pImageInfo = i;
    return w;
  };
  const std::array<VkWriteDescriptorSet, 11> writes{
      write(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &sceneInfo, nullptr),
      write(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &vertexInfo, nullptr),
      write(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &patchInfo, nullptr),
      write(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &pointInfo, nullptr),
      write(4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &colorInfo),
      write(5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &heightInfo),
      write(6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &captureInfo, nullptr),
      write(7, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &indexInfo, nullptr),
      write(8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &leafInfo, nullptr),
      write(9, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &atlasInfo),
      write(10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &impostorInfo, nullptr)};
  vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

std::uint32_t TreeRenderer::primitivesPerDraw(const RenderSettings& settings) const {
  if (settings.patchesPerDraw > 0) return settings.patchesPerDraw;
  if (settings.mode == RenderMode::Flat || !context_.isLavapipe()) return 1u << 30;
  const float level = settings.adaptivePixels > 0.0f ? settings.maxLevel : settings.tessLevel;
  // Two lavapipe limits, both measured on Mesa 22.3.6 (docs/rendering.md): 65535 tessellated vertices per
  // draw, and 4096 input vertices per non-indexed tessellated draw, whatever the factor.
  const std::uint32_t byOutput = std::max(1u, 65535u / verticesPerPatch(settings.mode, level));
  const std::uint32_t byInput = kLavapipeInputVerticesPerDraw / (settings.mode == RenderMode::ACC ? 4u : 3u);
  return std::min(byOutput, byInput);
}

void TreeRenderer::beginFrame(VkCommandBuffer cmd, const Camera& camera, VkExtent2D extent, const RenderSettings& s) {
  const float aspect = static_cast<float>(extent.width) / static_cast<float>(std::max(1u, extent.height));
  SceneUniforms u{};
  u.view = viewMatrix(camera);
  u.viewProj = projectionMatrix(camera, aspect) * u.view;
  u.inverseViewProj = glm::inverse(u.viewProj);
  u.cameraPos = glm::vec4(camera.eye, 1.0f);
  eye_ = camera.eye;
  u.lightDir = glm::vec4(glm::normalize(s.lightDirection), s.lightIntensity);
  u.viewport = glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height), 1.0f / static_cast<float>(extent.width),
                         1.0f / static_cast<float>(extent.height));
  u.tess = glm::vec4(std::clamp(s.tessLevel, 1.0f, 64.0f), s.adaptivePixels, std::clamp(s.maxLevel, 1.0f, 64.0f), s.cull ? 1.0f : 0.0f);
  u.displace = glm::vec4(s.displacement, s.displacementBias, s.seamFade, s.textureRepeat);
  u.skyTop = glm::vec4(0.32f, 0.52f, 0.82f, 1.0f);
  u.skyHorizon = glm::vec4(0.78f, 0.85f, 0.92f, 1.0f);
  // The ground fades fully into the horizon colour at this distance from the eye (and ends at four times it).
  const float groundRadius = s.groundRadius > 0.0f ? s.groundRadius
                             : !trees_.empty() ? std::clamp(10.0f * glm::length(trees_[0]->bounds.hi - trees_[0]->bounds.lo), 60.0f, 400.0f)
                                               : 100.0f;
  u.ground = glm::vec4(0.30f, 0.36f, 0.20f, groundRadius);
  u.flags = glm::uvec4(captureCapacity_ > 0 ? 1u : 0u, 0u, s.revealBackFaces ? 1u : 0u, 0u);
  u.leafLod = glm::vec4(s.leafLodDistance, std::clamp(s.leafDensity, 0.0f, 1.0f),
                        0.0f, static_cast<float>(s.shadowLeaves));
  u.lens = glm::vec4(0.5f * static_cast<float>(extent.height) / std::tan(0.5f * camera.fovY), 0.0f, 0.0f, 0.0f);
  std::memcpy(scene_.mapped(), &u, sizeof u);
  if (captureCapacity_ > 0) static_cast<std::uint32_t*>(capture_.mapped())[0] = 0;
  if (statistics_) vkCmdResetQueryPool(cmd, statistics_, 0, 1);
  if (timestamps_) vkCmdResetQueryPool(cmd, timestamps_, 0, kTimestampCount);
}

void TreeRenderer::drawLines(VkCommandBuffer cmd, VkBuffer vertices, std::uint32_t count, const glm::mat4& model) {
  if (count == 0) return;
  DrawConstants constants{};
  std::memcpy(constants.model, glm::value_ptr(model), sizeof constants.model);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout, 0, 1, &sets_[0], 0, nullptr);
  vkCmdPushConstants(cmd, pipelines_.layout, pipelines_.pushStages, 0, sizeof constants, &constants);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.lines);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdDraw(cmd, count, 1, 0, 0);
}

void TreeRenderer::draw(VkCommandBuffer cmd, VkExtent2D extent, const RenderSettings& s, const std::vector<TreeInstance>& instances) {
  const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  const VkShaderStageFlags stages = pipelines_.pushStages;
  DrawConstants constants{};
  auto bindTree = [&](std::uint32_t tree, const glm::mat4& model) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout, 0, 1, &sets_[tree], 0, nullptr);
    std::memcpy(constants.model, glm::value_ptr(model), sizeof constants.model);
    constants.patchBase = 0;
    constants.leafCount = tree < trees_.size() ? trees_[tree]->leafCount : 0u;
    vkCmdPushConstants(cmd, pipelines_.layout, stages, 0, sizeof constants, &constants);
  };
  bindTree(0, glm::mat4(1.0f));
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sky);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  if (s.ground) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.ground);
    vkCmdDraw(cmd, 6, 1, 0, 0);
  }
  drewTree_ = false;
  lastDraws_ = 0;
  for (const TreeInstance& instance : instances) {
    if (instance.tree >= trees_.size()) throw std::out_of_range("tree instance names tree " + std::to_string(instance.tree));
    const GpuTree& tree = *trees_[instance.tree];
    drewTree_ = drewTree_ || (s.mode == RenderMode::ACC ? tree.patchCount : tree.triangles) > 0;
  }
  if (!drewTree_) return;

  const std::uint32_t chunk = primitivesPerDraw(s);
  // Far trees skip the tessellator: their mesh at its limit positions is what ACC would draw at factor 1.
  const auto drawnFar = [&](const TreeInstance& instance, const GpuTree& tree) {
    return instance.far && tree.farVertices.handle() != VK_NULL_HANDLE && s.mode != RenderMode::Flat && !s.ceiling;
  };
  // `far`: the flat pipeline over the limit-surface vertices, however the tree is otherwise drawn.
  auto drawMesh = [&](const GpuTree& tree, VkPipeline pipeline, RenderMode drawn, bool far) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    if (drawn == RenderMode::Flat) {
      const VkDeviceSize offset = 0;
      const VkBuffer vertices = far ? tree.farVertices.handle() : tree.vertices.handle();
      vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
      vkCmdBindIndexBuffer(cmd, tree.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    }
    const std::uint32_t total = drawn == RenderMode::ACC ? tree.patchCount : tree.triangles;
    const std::uint32_t perDraw = drawn == s.mode ? chunk : total;  // only tessellated draws are split
    for (std::uint32_t base = 0; base < total; base += perDraw) {
      const std::uint32_t count = std::min(perDraw, total - base);
      constants.patchBase = base;
      vkCmdPushConstants(cmd, pipelines_.layout, stages, 0, sizeof constants, &constants);
      // PN and ACC fetch their corners in the control stage; only flat uses the vertex input.
      if (drawn == RenderMode::ACC) vkCmdDraw(cmd, 4 * count, 1, 4 * base, 0);
      else if (drawn == RenderMode::PN) vkCmdDraw(cmd, 3 * count, 1, 3 * base, 0);
      else vkCmdDrawIndexed(cmd, 3 * count, 1, 3 * base, 0, 0);
      ++lastDraws_;
    }
  };
  auto drawPoints = [&](VkPipeline pipeline, std::uint32_t count, std::uint32_t first = 0) {
    constants.patchBase = 0;
    vkCmdPushConstants(cmd, pipelines_.layout, stages, 0, sizeof constants, &constants);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdDraw(cmd, count, 1, first, 0);  // the point's index (gl_VertexIndex) counts from `first`
    ++lastDraws_;
  };

  if (timestamps_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_, 0);
  if (statistics_) vkCmdBeginQuery(cmd, statistics_, 0, 0);
  for (const TreeInstance& instance : instances) {
    const GpuTree& tree = *trees_[instance.tree];
    bindTree(instance.tree, instance.model);
    const bool far = drawnFar(instance, tree);
    const RenderMode drawn = far ? RenderMode::Flat : s.mode;
    const auto m = static_cast<std::size_t>(drawn);
    const VkPipeline mesh = s.ceiling && s.mode == RenderMode::ACC ? pipelines_.ceiling
                            : s.revealBackFaces                       ? pipelines_.twoSided[m]
                                                                      : pipelines_.tree[m];
    drawMesh(tree, mesh, drawn, far);
    const bool sketch = instance.far && tree.sketchCount > 0;
    const std::uint32_t impostors = sketch ? tree.sketchCount : tree.impostorCount;
    if (s.impostors && impostors > 0 && pipelines_.impostors) drawPoints(pipelines_.impostors, impostors, sketch ? tree.impostorCount : 0u);
    if (s.leaves && tree.leafCount > 0 && pipelines_.leaves) {
      // The geometry stage keeps a leaf when its rank (i + 1/2) / N is within the density, thinned with the square of
      // its distance beyond leafLodDistance: no leaf of this tree is nearer than its leaf box, so the leaves past
      // the share kept there need no draw (a far forest runs the geometry stage for a few percent of its leaves).
      double share = std::clamp(static_cast<double>(s.leafDensity), 0.0, 1.0);
      if (s.leafLodDistance > 0.0f) {
        const glm::vec3 eye(glm::inverse(instance.model) * glm::vec4(eye_, 1.0f));
        const float nearest = glm::distance(eye, glm::clamp(eye, tree.leafBounds.lo, tree.leafBounds.hi));
        share *= std::min(1.0, std::pow(static_cast<double>(s.leafLodDistance) / std::max(static_cast<double>(nearest), 1e-3), 2.0));
      }
      const double kept = share * tree.leafCount;
      drawPoints(pipelines_.leaves, std::min(tree.leafCount, static_cast<std::uint32_t>(kept + 0.5) + 1u));
    }
  }
  if (statistics_) vkCmdEndQuery(cmd, statistics_, 0);
  if (timestamps_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, 1);
  if (s.wireframe) {
    for (const TreeInstance& instance : instances) {
      const GpuTree& tree = *trees_[instance.tree];
      const bool far = drawnFar(instance, tree);
      const RenderMode drawn = far ? RenderMode::Flat : s.mode;
      const VkPipeline wire = pipelines_.wireframe[static_cast<std::size_t>(drawn)];
      if (!wire) continue;
      bindTree(instance.tree, instance.model);
      drawMesh(tree, wire, drawn, far);
    }
  }
}

FrameStats TreeRenderer::stats() const {
  FrameStats f;
  f.draws = lastDraws_;
  if (!drewTree_) return f;
  const VkDevice device = context_.device();
  if (statistics_) {
    std::uint64_t primitives = 0;
    if (vkGetQueryPoolResults(device, statistics_, 0, 1, sizeof primitives, &primitives, sizeof primitives,
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      f.triangles = primitives;
      f.hasTriangles = true;
    }
  }
  if (timestamps_) {
    std::uint64_t t[kTimestampCount] = {};
    if (vkGetQueryPoolResults(device, timestamps_, 0, kTimestampCount, sizeof t, t, sizeof t[0],
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      f.gpuMilliseconds = static_cast<double>(t[1] - t[0]) * context_.properties().limits.timestampPeriod * 1e-6;
      f.hasTime = true;
    }
  }
  return f;
}

}  // namespace arbor::render
