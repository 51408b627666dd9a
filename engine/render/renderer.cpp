#include "renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "cards.hpp"

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
  glm::vec4 wind;       // direction xy, strength, gust frequency
  glm::vec4 windClock;  // seconds into the gust period
};

constexpr std::uint32_t kCaptureHeader = 16;  // count, capacity, two words of padding
constexpr std::uint32_t kCaptureEntryBytes = 48;  // three vec4: patch and (u, v), point, displaced point
constexpr std::uint32_t kTimestampCount = 2;
constexpr std::uint32_t kLavapipeInputVerticesPerDraw = 4096;  // beyond it lavapipe garbles patches (one vertex each)
constexpr std::uint32_t kCounters = ARBOR_COUNTERS;

std::uint32_t bit(bool on, PassFlag flag) { return on ? static_cast<std::uint32_t>(flag) : 0u; }

// A pipeline barrier for buffer memory: what `from` wrote, `to` may read.
void barrier(VkCommandBuffer cmd, VkPipelineStageFlags fromStage, VkAccessFlags from, VkPipelineStageFlags toStage, VkAccessFlags to) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = from;
  b.dstAccessMask = to;
  vkCmdPipelineBarrier(cmd, fromStage, toStage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

// Tessellated vertices one patch emits at `level` with equal spacing (which rounds levels up). A triangle is
// tessellated as concentric rings of 3L, 3(L - 2), ... vertices, ending in a point (L even) or a triangle.
std::uint32_t verticesPerPatch(RenderMode mode, float level) {
  const auto l = static_cast<std::uint32_t>(std::ceil(std::clamp(level, 1.0f, 64.0f)));
  if (renderModeInfo(mode).primitive == PatchPrimitive::Quad) return (l + 1) * (l + 1);
  return l % 2 == 0 ? 1 + 3 * l * (l + 2) / 4 : 3 * ((l + 1) / 2) * ((l + 1) / 2);
}

// Whether this tree moves in this frame's wind (it has wind records and the wind blows).
bool movesInWind(const RenderSettings& s, const GpuTree& tree) { return s.wind.on() && tree.windHeight > 0.0f; }

// The bark colour with the height in its alpha (unused before), so the bark fragment stage reads both in one
// filtered lookup instead of two (the same picture, bit for bit).
Image colorWithHeight(const Image& color, const Image& height) {
  if (color.width != height.width || color.height != height.height) {
    throw std::invalid_argument("the bark height texture is " + std::to_string(height.width) + "x" + std::to_string(height.height) +
                                ", the colour texture " + std::to_string(color.width) + "x" + std::to_string(color.height) +
                                ": they must be the same size");
  }
  Image out = color;
  for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = height.rgba[i - 3];
  return out;
}

}  // namespace

TreeRenderer::TreeRenderer(const vk::VulkanContext& context, VkRenderPass renderPass, VkSampleCountFlagBits samples,
                           const TreeTextures& textures)
    : context_(context) {
  const Image bark = colorWithHeight(textures.barkColor, textures.barkHeight);  // first: it may throw, with nothing created yet
  pipelines_ = createPipelines(context, renderPass, samples);
  const auto upload = [&context](const Image& image, bool srgb) {
    return vk::uploadTexture(context, image.rgba, static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height), srgb);
  };
  barkColor_ = upload(bark, true);
  barkHeight_ = upload(textures.barkHeight, false);
  leafAtlas_ = upload(textures.leafAtlas, true);
  sampler_ = vk::createRepeatSampler(context, static_cast<float>(barkColor_.mipLevels()), textures.barkAnisotropy);
  // Coarse MIP levels average a cutout's alpha below the leaf shader's test and whole leaves would vanish with
  // distance: the atlas stops at the level where the blades still hold their shape.
  leafSampler_ = vk::createRepeatSampler(context, 3.0f, 1.0f);  // clamped + anisotropic: lavapipe minutes/frame
  for (FrameSlot& frame : slots_) frame.scene = vk::hostBuffer(context, sizeof(SceneUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  setCapture(0);
  const std::vector<std::uint32_t> cards = cardIndices(kCardsPerDraw);
  cardIndices_ = vk::uploadBuffer(context, cards.data(), cards.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

  const VkDevice device = context.device();
  constexpr std::uint32_t kSets = kMaxTrees * kFramesInFlight;
  const std::array<VkDescriptorPoolSize, 3> sizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kSets},
                                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 6 * kSets},
                                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * kSets}}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = kMaxTrees * kFramesInFlight;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  vk::check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
  // Compute sets come and go with the trees (one per distinct tree shown).
  const std::array<VkDescriptorPoolSize, 2> computeSizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kSets},
                                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, (ARBOR_COMPUTE_BINDINGS - 1) * kSets}}};
  VkDescriptorPoolCreateInfo computePoolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  computePoolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  computePoolInfo.maxSets = kSets;
  computePoolInfo.poolSizeCount = static_cast<std::uint32_t>(computeSizes.size());
  computePoolInfo.pPoolSizes = computeSizes.data();
  vk::check(vkCreateDescriptorPool(device, &computePoolInfo, nullptr, &computePool_), "vkCreateDescriptorPool");
  for (FrameSlot& frame : slots_) {
    ensureFrameBuffers(frame, 1, kCounters, 1);
    if (context.features().pipelineStatisticsQuery) {
      VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
      q.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
      q.queryCount = 1;
      q.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT;
      vk::check(vkCreateQueryPool(device, &q, nullptr, &frame.statistics), "vkCreateQueryPool");
    }
    if (context.properties().limits.timestampComputeAndGraphics) {
      VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
      q.queryType = VK_QUERY_TYPE_TIMESTAMP;
      q.queryCount = kTimestampCount;
      vk::check(vkCreateQueryPool(device, &q, nullptr, &frame.timestamps), "vkCreateQueryPool");
    }
  }
  setTree(nullptr);
}

TreeRenderer::~TreeRenderer() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  for (FrameSlot& frame : slots_) {
    if (frame.statistics) vkDestroyQueryPool(device, frame.statistics, nullptr);
    if (frame.timestamps) vkDestroyQueryPool(device, frame.timestamps, nullptr);
  }
  vkDestroyDescriptorPool(device, pool_, nullptr);
  vkDestroyDescriptorPool(device, computePool_, nullptr);
  vkDestroySampler(device, sampler_, nullptr);
  vkDestroySampler(device, leafSampler_, nullptr);
  pipelines_.destroy();
}

void TreeRenderer::setCapture(std::uint32_t capacity) {
  vkDeviceWaitIdle(context_.device());  // frames in flight may write the old buffer
  captureCapacity_ = capacity;
  capture_ = vk::hostBuffer(context_, kCaptureHeader + static_cast<std::size_t>(std::max(capacity, 1u)) * kCaptureEntryBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memset(capture_.mapped(), 0, kCaptureHeader);
  static_cast<std::uint32_t*>(capture_.mapped())[1] = capacity;
  if (!slots_[0].sets.empty()) setTrees(trees_);
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
  vkDeviceWaitIdle(context_.device());  // frames in flight read the sets rewritten here
  trees_ = trees;
  // Control points of trees no longer shown go (their GpuTree may be gone); the others stay built.
  for (auto it = controls_.begin(); it != controls_.end();) {
    const bool kept = std::any_of(trees.begin(), trees.end(), [&](const GpuTree* t) { return t && t->id == it->first; });
    if (kept) {
      it->second.boundMode.fill(-1);  // the tree's graphics sets are rewritten below
      ++it;
      continue;
    }
    for (VkDescriptorSet set : it->second.computeSet) {
      if (set) vkFreeDescriptorSets(context_.device(), computePool_, 1, &set);
    }
    it = controls_.erase(it);
  }
  const std::size_t wanted = std::max<std::size_t>(1, trees.size());  // sky and ground need a set without trees too
  for (FrameSlot& frame : slots_) {
    while (frame.sets.size() < wanted) {
      VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
      alloc.descriptorPool = pool_;
      alloc.descriptorSetCount = 1;
      alloc.pSetLayouts = &pipelines_.setLayout;
      VkDescriptorSet set = VK_NULL_HANDLE;
      vk::check(vkAllocateDescriptorSets(context_.device(), &alloc, &set), "vkAllocateDescriptorSets");
      frame.sets.push_back(set);
    }
    for (std::size_t i = 0; i < wanted; ++i) writeSet(frame, frame.sets[i], i < trees.size() ? trees[i] : nullptr);
  }
}

void TreeRenderer::writeSet(const FrameSlot& frame, VkDescriptorSet set, const GpuTree* tree) {
  // Without a tree the storage bindings still point at a valid buffer: every binding is always written.
  const VkBuffer fallback = capture_.handle();
  const VkDescriptorBufferInfo sceneInfo{frame.scene.handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo leafInfo{tree && tree->leafCount > 0 ? tree->leaves.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo impostorInfo{tree && tree->impostorCount > 0 ? tree->impostors.handle() : fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorImageInfo atlasInfo{leafSampler_, leafAtlas_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorBufferInfo captureInfo{capture_.handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorImageInfo colorInfo{sampler_, barkColor_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorImageInfo heightInfo{sampler_, barkHeight_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  // The control points are bound when a tessellated mode first draws the tree (bindControl).
  const VkDescriptorBufferInfo controlInfo{fallback, 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo visibleInfo{frame.visible.handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo windInfo{tree && tree->wind.handle() != VK_NULL_HANDLE ? tree->wind.handle() : fallback, 0, VK_WHOLE_SIZE};
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
  const std::array<VkWriteDescriptorSet, 10> writes{
      write(ARBOR_BINDING_SCENE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &sceneInfo, nullptr),
      write(ARBOR_BINDING_BARK_COLOR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &colorInfo),
      write(ARBOR_BINDING_BARK_HEIGHT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &heightInfo),
      write(ARBOR_BINDING_CAPTURE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &captureInfo, nullptr),
      write(ARBOR_BINDING_LEAVES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &leafInfo, nullptr),
      write(ARBOR_BINDING_LEAF_ATLAS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &atlasInfo),
      write(ARBOR_BINDING_IMPOSTORS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &impostorInfo, nullptr),
      write(ARBOR_BINDING_CONTROL, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &controlInfo, nullptr),
      write(ARBOR_BINDING_VISIBLE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &visibleInfo, nullptr),
      write(ARBOR_BINDING_WIND, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &windInfo, nullptr)};
  vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

void TreeRenderer::ensureFrameBuffers(FrameSlot& frame, std::size_t entries, std::size_t counters, std::size_t commands) {
  const auto fits = [](const vk::Buffer& b, std::size_t bytes) { return b.handle() != VK_NULL_HANDLE && b.size() >= bytes; };
  const std::size_t entryBytes = entries * 2 * sizeof(std::uint32_t), counterBytes = counters * sizeof(std::uint32_t);
  const std::size_t commandBytes = commands * ARBOR_DRAW_COMMAND_BYTES;
  const bool hostVisible = inspect_ == (frame.visible.mapped() != nullptr);
  if (fits(frame.visible, entryBytes) && fits(frame.counts, counterBytes) && fits(frame.commands, commandBytes) && hostVisible) return;
  // Half again what is asked, so that a growing forest does not reallocate every frame. This frame's earlier
  // use has completed (beginFrame's contract), so its buffers may go.
  const auto grown = [](std::size_t bytes) { return std::max<std::size_t>(256, bytes + bytes / 2); };
  const VkMemoryPropertyFlags memory = inspect_ ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                                : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  if (!fits(frame.visible, entryBytes) || !hostVisible) frame.visible = vk::Buffer(context_, grown(entryBytes), storage, memory);
  if (!fits(frame.commands, commandBytes) || !hostVisible) {
    frame.commands = vk::Buffer(context_, grown(commandBytes), storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, memory);
  }
  if (!fits(frame.counts, counterBytes)) {
    frame.counts = vk::Buffer(context_, grown(counterBytes),
                              storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    frame.countsReadback = vk::hostBuffer(context_, frame.counts.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  }
  ++frame.generation;
  for (std::size_t i = 0; i < frame.sets.size(); ++i) writeSet(frame, frame.sets[i], i < trees_.size() ? trees_[i] : nullptr);
  const auto index = static_cast<std::size_t>(&frame - slots_.data());
  for (auto& [id, control] : controls_) control.boundMode[index] = -1;
}

void TreeRenderer::setInspection(bool on) {
  vkDeviceWaitIdle(context_.device());
  inspect_ = on;
  for (FrameSlot& frame : slots_) {
    ensureFrameBuffers(frame, frame.visible.size() / 8, frame.counts.size() / 4, frame.commands.size() / ARBOR_DRAW_COMMAND_BYTES);
  }
}

std::vector<glm::vec4> TreeRenderer::readControl(const GpuTree& tree, RenderMode mode, bool hulls) const {
  const auto found = controls_.find(tree.id);
  if (found == controls_.end()) return {};
  const vk::Buffer& source = (hulls ? found->second.hulls : found->second.control)[static_cast<std::size_t>(mode)];
  if (source.handle() == VK_NULL_HANDLE) return {};
  const vk::Buffer staging = vk::hostBuffer(context_, source.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy copy{0, 0, source.size()};
    vkCmdCopyBuffer(cmd, source.handle(), staging.handle(), 1, &copy);
  });
  std::vector<glm::vec4> records(source.size() / sizeof(glm::vec4));
  std::memcpy(records.data(), staging.mapped(), records.size() * sizeof(glm::vec4));
  return records;
}

std::size_t TreeRenderer::controlBytes(RenderMode mode) const {
  std::size_t bytes = 0;
  for (const auto& [id, c] : controls_) bytes += c.control[static_cast<std::size_t>(mode)].size() + c.hulls[static_cast<std::size_t>(mode)].size();
  return bytes;
}

std::vector<PatchDraw> TreeRenderer::inspectDraws() const {
  std::vector<PatchDraw> draws;
  if (!inspect_) throw std::logic_error("inspectDraws needs setInspection(true) before the frame");
  const FrameSlot& frame = slot();
  const auto* counts = static_cast<const std::uint32_t*>(frame.countsReadback.mapped());
  const auto* commands = static_cast<const std::uint32_t*>(frame.commands.mapped());
  const auto* entries = static_cast<const std::uint32_t*>(frame.visible.mapped());
  // The corner draw counts vertices (a quad's 6, a triangle's 3 per patch), the tessellated ones patches.
  const std::uint32_t cornerVertices = renderModeInfo(frame.mode).cornerVertices;
  for (std::size_t i = 0; i < frame.planOf.size(); ++i) {
    if (frame.planOf[i] < 0) continue;
    const InstancePlan& plan = frame.plans[static_cast<std::size_t>(frame.planOf[i])];
    auto add = [&](const std::uint32_t* command, bool tessellated) {
      PatchDraw draw;
      draw.instance = static_cast<std::uint32_t>(i);
      draw.tessellated = tessellated;
      const std::uint32_t patches = tessellated ? command[0] : command[0] / cornerVertices;
      const std::uint32_t first = tessellated ? command[2] : command[2] / cornerVertices;
      for (std::uint32_t k = 0; k < patches; ++k) {
        const std::uint32_t* entry = entries + 2 * (first + k);
        draw.patches.push_back({entry[0], {entry[1] & 0xffu, (entry[1] >> 8) & 0xffu, (entry[1] >> 16) & 0xffu, entry[1] >> 24}});
      }
      draws.push_back(std::move(draw));
    };
    if (counts[plan.counterBase + ARBOR_BUCKETS] > 0) add(commands + 4 * plan.commandBase, false);
    for (std::uint32_t c = 0; c < counts[plan.counterBase + ARBOR_BUCKETS + 1]; ++c) add(commands + 4 * (plan.commandBase + 1 + c), true);
  }
  return draws;
}

TreeRenderer::DrawSizes TreeRenderer::drawSizes(const RenderSettings& settings) const {
  DrawSizes sizes;
  sizes.perDraw.fill(1u << 30);
  if (settings.patchesPerDraw > 0) {
    sizes.perDraw.fill(settings.patchesPerDraw);
    return sizes;
  }
  if (!context_.isLavapipe() || !isTessellated(settings.mode)) return sizes;
  // Two lavapipe limits, both measured on Mesa 22.3.6 (docs/rendering.md): 65535 tessellated vertices per
  // draw, and 4096 input vertices (here patches) per tessellated draw, whatever the factor.
  const auto perDraw = [&](float level) {
    return std::max(1u, std::min(kLavapipeInputVerticesPerDraw, 65535u / verticesPerPatch(settings.mode, level)));
  };
  if (settings.adaptivePixels <= 0.0f || settings.ceiling) {
    sizes.perDraw.fill(perDraw(settings.tessLevel));  // one factor: every draw sized for it
  } else if (!settings.bucketed) {
    sizes.perDraw.fill(perDraw(settings.maxLevel));  // every draw sized for the largest factor allowed
  } else {
    sizes.bucketed = true;
    for (std::uint32_t b = 1; b < ARBOR_BUCKETS; ++b) sizes.perDraw[b] = perDraw(static_cast<float>(1u << b));
  }
  return sizes;
}

bool TreeRenderer::drawnTessellated(const TreeInstance& instance, const RenderSettings& s) const {
  const GpuTree& tree = *trees_[instance.tree];
  const bool far = instance.far && tree.farVertices.handle() != VK_NULL_HANDLE && !s.ceiling;
  return isTessellated(s.mode) && !far && (renderModeInfo(s.mode).primitive == PatchPrimitive::Quad ? tree.patchCount : tree.triangles) > 0;
}

void TreeRenderer::bindControl(std::uint32_t treeIndex, RenderMode mode, bool posed) {
  const GpuTree& tree = *trees_[treeIndex];
  TreeControl& c = controls_[tree.id];
  const auto m = static_cast<std::size_t>(mode);
  const FrameSlot& frame = slot();
  if (c.boundMode[current_] == static_cast<int>(mode) && c.boundGeneration[current_] == frame.generation && c.boundPosed[current_] == posed) return;
  VkDescriptorSet& computeSet = c.computeSet[current_];
  if (!computeSet) {
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = computePool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &pipelines_.computeSetLayout;
    vk::check(vkAllocateDescriptorSets(context_.device(), &alloc, &computeSet), "vkAllocateDescriptorSets");
  }
  // With wind the control passes read the posed cage; wind.comp reads the rest one and the wind records.
  const VkBuffer wind = tree.wind.handle() != VK_NULL_HANDLE ? tree.wind.handle() : tree.vertices.handle();
  const std::array<VkBuffer, ARBOR_COMPUTE_BINDINGS> buffers{
      frame.scene.handle(), posed ? c.posed.handle() : tree.vertices.handle(), tree.patches.handle(), tree.points.handle(), tree.indices.handle(),
      c.control[m].handle(), c.hulls[m].handle(), frame.visible.handle(), frame.counts.handle(), frame.commands.handle(),
      tree.vertices.handle(), wind};
  std::array<VkDescriptorBufferInfo, ARBOR_COMPUTE_BINDINGS> infos{};
  std::array<VkWriteDescriptorSet, ARBOR_COMPUTE_BINDINGS + 1> writes{};
  for (std::uint32_t b = 0; b < ARBOR_COMPUTE_BINDINGS; ++b) {
    infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
    writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = computeSet;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = b == ARBOR_COMPUTE_SCENE ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  // The tree's graphics set reads the same control points.
  const VkDescriptorBufferInfo controlInfo{c.control[m].handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet& graphics = writes[ARBOR_COMPUTE_BINDINGS];
  graphics = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  graphics.dstSet = frame.sets[treeIndex];
  graphics.dstBinding = ARBOR_BINDING_CONTROL;
  graphics.descriptorCount = 1;
  graphics.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  graphics.pBufferInfo = &controlInfo;
  vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  c.boundMode[current_] = static_cast<int>(mode);
  c.boundGeneration[current_] = frame.generation;
  c.boundPosed[current_] = posed;
}

void TreeRenderer::beginFrame(VkCommandBuffer cmd, const Camera& camera, VkExtent2D extent, const RenderSettings& s,
                              const std::vector<TreeInstance>& instances) {
  // The slot this frame reuses last served kFramesInFlight frames ago, which has completed: keep its figures.
  current_ = static_cast<std::uint32_t>(framesBegun_++ % kFramesInFlight);
  FrameSlot& frame = slot();
  if (frame.used) completed_ = statsOf(frame);
  frame.used = true;
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
  u.tess = glm::vec4(std::clamp(s.tessLevel, 1.0f, 64.0f), s.ceiling ? 0.0f : s.adaptivePixels, std::clamp(s.maxLevel, 1.0f, 64.0f),
                     s.cull ? 1.0f : 0.0f);
  u.displace = glm::vec4(s.displacement, s.displacementBias, s.seamFade, s.textureRepeat);
  u.skyTop = glm::vec4(0.32f, 0.52f, 0.82f, 1.0f);
  u.skyHorizon = glm::vec4(0.78f, 0.85f, 0.92f, 1.0f);
  // The ground fades fully into the horizon colour at this distance from the eye (and ends at four times it).
  const float groundRadius = s.groundRadius > 0.0f ? s.groundRadius
                             : !trees_.empty() ? std::clamp(10.0f * glm::length(trees_[0]->bounds.hi - trees_[0]->bounds.lo), 60.0f, 400.0f)
                                               : 100.0f;
  u.ground = glm::vec4(0.30f, 0.36f, 0.20f, groundRadius);
  u.flags = glm::uvec4(0u, 0u, s.revealBackFaces ? 1u : 0u, 0u);
  u.leafLod = glm::vec4(s.leafLodDistance, std::clamp(s.leafDensity, 0.0f, 1.0f),
                        0.0f, static_cast<float>(s.shadowLeaves));
  u.lens = glm::vec4(0.5f * static_cast<float>(extent.height) / std::tan(0.5f * camera.fovY), 0.0f, 0.0f, 0.0f);
  // The clock folded into the gust period (every motion repeats with it), so floats keep their precision.
  const double azimuth = glm::radians(s.wind.azimuth);
  u.wind = glm::vec4(static_cast<float>(std::cos(azimuth)), static_cast<float>(std::sin(azimuth)), s.wind.on() ? static_cast<float>(s.wind.strength) : 0.0f,
                     static_cast<float>(s.wind.gustFrequency));
  u.windClock = glm::vec4(s.wind.on() ? static_cast<float>(std::fmod(s.windSeconds, s.wind.period())) : 0.0f, 0.0f, 0.0f, 0.0f);
  std::memcpy(frame.scene.mapped(), &u, sizeof u);
  if (captureCapacity_ > 0) static_cast<std::uint32_t*>(capture_.mapped())[0] = 0;
  if (frame.statistics) vkCmdResetQueryPool(cmd, frame.statistics, 0, 1);
  if (frame.timestamps) vkCmdResetQueryPool(cmd, frame.timestamps, 0, kTimestampCount);

  // Each tessellated instance gets a slice of this frame's lists: a list per bucket, counters, draw commands.
  const DrawSizes sizes = drawSizes(s);
  const bool quads = renderModeInfo(s.mode).primitive == PatchPrimitive::Quad;
  frame.plans.clear();
  frame.planOf.assign(instances.size(), -1);
  frame.mode = s.mode;
  std::size_t entries = 0, commands = 0;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    if (instances[i].tree >= trees_.size()) throw std::out_of_range("tree instance names tree " + std::to_string(instances[i].tree));
    if (!drawnTessellated(instances[i], s)) continue;
    InstancePlan plan;
    plan.tree = instances[i].tree;
    plan.primitives = quads ? trees_[plan.tree]->patchCount : trees_[plan.tree]->triangles;
    plan.listBase = static_cast<std::uint32_t>(entries);
    plan.counterBase = static_cast<std::uint32_t>(frame.plans.size() * kCounters);
    plan.commandBase = static_cast<std::uint32_t>(commands);
    for (std::uint32_t b = sizes.bucketed ? 1 : ARBOR_BUCKETS - 1; b < ARBOR_BUCKETS; ++b) {
      plan.maxCommands += (plan.primitives + sizes.perDraw[b] - 1) / sizes.perDraw[b];
    }
    entries += static_cast<std::size_t>(plan.primitives) * ARBOR_BUCKETS;
    commands += 1 + plan.maxCommands;  // the corner draw, then the tessellated ones
    if (entries > 0xffffffffu || commands > 0xffffffffu) throw std::runtime_error("the scene has more patches than one frame's lists index");
    frame.planOf[i] = static_cast<int>(frame.plans.size());
    frame.plans.push_back(plan);
  }
  if (frame.plans.empty()) return;
  ensureFrameBuffers(frame, entries, frame.plans.size() * kCounters, commands);

  // Control points of meshes drawn for the first time in this mode: once per mesh, then kept. With wind, every
  // frame: the rest cage posed first (wind.comp), then its control points and hulls built anew.
  const RenderMode controlMode = s.mode;
  const auto m = static_cast<std::size_t>(controlMode);
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  auto windy = [&](const GpuTree& tree) { return movesInWind(s, tree); };
  // Returns whether the buffers were missing.
  auto ensureControl = [&](TreeControl& c, const InstancePlan& plan) {
    if (c.control[m].handle() != VK_NULL_HANDLE) return false;
    c.control[m] = vk::Buffer(context_, std::size_t{plan.primitives} * renderModeInfo(controlMode).controlVec4s * 16, storage,
                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    c.hulls[m] = vk::Buffer(context_, std::size_t{plan.primitives} * ARBOR_HULL_VEC4S * 16, storage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    c.boundMode.fill(-1);
    return true;
  };
  std::vector<char> posedThisFrame(trees_.size(), 0);
  bool posing = false;
  for (const InstancePlan& plan : frame.plans) {
    const GpuTree& tree = *trees_[plan.tree];
    if (!windy(tree) || posedThisFrame[plan.tree]) continue;
    if (!posing) {
      // The posed cages and control points may still be read by the frame before (its commands came earlier).
      barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0);
      posing = true;
    }
    posedThisFrame[plan.tree] = 1;
    TreeControl& c = controls_[tree.id];
    if (c.posed.handle() == VK_NULL_HANDLE) {
      c.posed = vk::Buffer(context_, tree.vertices.size(), storage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      c.boundMode.fill(-1);
    }
    ensureControl(c, plan);
    bindControl(plan.tree, controlMode, true);
    PassConstants pass{};
    pass.primitiveCount = tree.vertexCount;
    pass.windHeight = tree.windHeight;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.wind);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.computeLayout, 0, 1, &c.computeSet[current_], 0, nullptr);
    vkCmdPushConstants(cmd, pipelines_.computeLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pass, &pass);
    vkCmdDispatch(cmd, (pass.primitiveCount + ARBOR_COMPUTE_GROUP - 1) / ARBOR_COMPUTE_GROUP, 1, 1);
  }
  if (posing) {
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
  }
  bool built = false;
  std::vector<char> builtThisFrame(trees_.size(), 0);
  for (const InstancePlan& plan : frame.plans) {
    const GpuTree& tree = *trees_[plan.tree];
    TreeControl& c = controls_[tree.id];
    const bool missing = ensureControl(c, plan);
    bindControl(plan.tree, controlMode, windy(tree));
    // A mesh whose control points were built from a posed cage is rebuilt at rest once the wind stops.
    const bool stale = !windy(tree) && c.posedBuild[m];
    if ((!missing && !windy(tree) && !stale) || builtThisFrame[plan.tree]) continue;
    builtThisFrame[plan.tree] = 1;
    c.posedBuild[m] = windy(tree);
    PassConstants pass{};
    pass.primitiveCount = plan.primitives;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.modes[m].build);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.computeLayout, 0, 1, &c.computeSet[current_], 0, nullptr);
    vkCmdPushConstants(cmd, pipelines_.computeLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pass, &pass);
    vkCmdDispatch(cmd, (plan.primitives + ARBOR_COMPUTE_GROUP - 1) / ARBOR_COMPUTE_GROUP, 1, 1);
    built = true;
  }
  if (built) {
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
  }

  // Cull, set factors and bucket every tessellated instance's patches, then turn the buckets into draws.
  vkCmdFillBuffer(cmd, frame.counts.handle(), 0, frame.plans.size() * kCounters * sizeof(std::uint32_t), 0);
  barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  // Back faces stay when displacement may turn them towards the eye, and when the crack test wants them seen.
  const bool backFaces = s.cull && s.displacement == 0.0f && !s.revealBackFaces;
  // Factor-1 patches skip the tessellator, except where the tessellator itself is measured or its points captured.
  const bool corners = s.cornerPatches && !s.ceiling && captureCapacity_ == 0;
  const std::uint32_t flags = bit(s.cull, kCullFrustum) | bit(backFaces, kCullBackFaces) | bit(sizes.bucketed, kBucketed) |
                              bit(context_.drawIndirectCount() == nullptr, kZeroFill) | bit(!quads, kTriangles) |
                              bit(corners, kCornerBucket);
  auto passFor = [&](std::size_t i, const InstancePlan& plan) {
    PassConstants pass{};
    std::memcpy(pass.model, glm::value_ptr(instances[i].model), sizeof pass.model);
    pass.primitiveCount = plan.primitives;
    pass.listBase = plan.listBase;
    pass.counterBase = plan.counterBase;
    pass.commandBase = plan.commandBase;
    pass.flags = flags;
    pass.maxCommands = plan.maxCommands;
    std::copy(sizes.perDraw.begin(), sizes.perDraw.end(), pass.perDraw);
    return pass;
  };
  for (int step = 0; step < 2; ++step) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, step == 0 ? pipelines_.cull : pipelines_.drawCommands);
    for (std::size_t i = 0; i < instances.size(); ++i) {
      if (frame.planOf[i] < 0) continue;
      const InstancePlan& plan = frame.plans[static_cast<std::size_t>(frame.planOf[i])];
      const PassConstants pass = passFor(i, plan);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.computeLayout, 0, 1,
                              &controls_[trees_[plan.tree]->id].computeSet[current_], 0, nullptr);
      vkCmdPushConstants(cmd, pipelines_.computeLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pass, &pass);
      vkCmdDispatch(cmd, step == 0 ? (plan.primitives + ARBOR_COMPUTE_GROUP - 1) / ARBOR_COMPUTE_GROUP : 1, 1, 1);
    }
    if (step == 0) {
      barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
              VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
  }
  barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
          VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
  const VkBufferCopy copy{0, 0, frame.plans.size() * kCounters * sizeof(std::uint32_t)};
  vkCmdCopyBuffer(cmd, frame.counts.handle(), frame.countsReadback.handle(), 1, &copy);
  barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void TreeRenderer::drawLines(VkCommandBuffer cmd, VkBuffer vertices, std::uint32_t count, const glm::mat4& model) {
  if (count == 0) return;
  DrawConstants constants{};
  std::memcpy(constants.model, glm::value_ptr(model), sizeof constants.model);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout, 0, 1, &slot().sets[0], 0, nullptr);
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
  FrameSlot& frame = slot();
  DrawConstants constants{};
  auto bindTree = [&](std::uint32_t tree, const glm::mat4& model) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout, 0, 1, &frame.sets[tree], 0, nullptr);
    std::memcpy(constants.model, glm::value_ptr(model), sizeof constants.model);
    constants.leafCount = tree < trees_.size() ? trees_[tree]->leafCount : 0u;
    const bool windy = tree < trees_.size() && movesInWind(s, *trees_[tree]);
    constants.windHeight = windy ? trees_[tree]->windHeight : 0.0f;
    constants.leafWindBase = windy ? trees_[tree]->leafWindBase : 0u;
    constants.impostorWindBase = windy ? trees_[tree]->impostorWindBase : 0u;
    vkCmdPushConstants(cmd, pipelines_.layout, stages, 0, sizeof constants, &constants);
  };
  bindTree(0, glm::mat4(1.0f));
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.sky);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  if (s.ground) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.ground);
    vkCmdDraw(cmd, 6, 1, 0, 0);
  }
  frame.drewTree = false;
  frame.draws = 0;
  if (instances.size() != frame.planOf.size()) throw std::logic_error("draw got other instances than beginFrame");
  for (const TreeInstance& instance : instances) {
    if (instance.tree >= trees_.size()) throw std::out_of_range("tree instance names tree " + std::to_string(instance.tree));
    const GpuTree& tree = *trees_[instance.tree];
    frame.drewTree = frame.drewTree || (renderModeInfo(s.mode).primitive == PatchPrimitive::Quad ? tree.patchCount : tree.triangles) > 0;
  }
  if (!frame.drewTree) return;

  // An instance is drawn flat (the flat mode, or far: its mesh at the limit positions, ACC's factor 1 without
  // the tessellator) or by the indirect draws its slice of the culling pass wrote.
  auto drawMesh = [&](std::size_t i, const GpuTree& tree, bool wire) {
    const int planIndex = frame.planOf[i];
    const RenderMode drawn = planIndex >= 0 ? s.mode : RenderMode::Flat;
    const bool displaced = s.displacement != 0.0f;
    const bool windy = movesInWind(s, tree);
    auto pick = [&](const SurfacePipelines& p) { return wire ? p.wireframe : s.revealBackFaces ? p.twoSided : p.fill; };
    if (planIndex < 0) {
      const VkPipeline pipeline = pick(pipelines_.surface(RenderMode::Flat, pipelineVariant(false, false, windy)));
      if (!pipeline) return;
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      const VkDeviceSize offset = 0;
      const bool far = isTessellated(s.mode) && tree.farVertices.handle() != VK_NULL_HANDLE;
      const VkBuffer vertices = far ? tree.farVertices.handle() : tree.vertices.handle();
      vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
      vkCmdBindIndexBuffer(cmd, tree.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(cmd, 3 * tree.triangles, 1, 0, 0, 0);
      if (!wire) ++frame.draws;
      return;
    }
    const InstancePlan& plan = frame.plans[static_cast<std::size_t>(planIndex)];
    // `slot`: the counter holding how many of the `most` commands from `first` the culling pass wrote.
    auto drawIndirect = [&](VkPipeline pipeline, std::uint32_t first, std::uint32_t slot, std::uint32_t most) {
      if (!pipeline) return;
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      const VkDeviceSize offset = VkDeviceSize{first} * ARBOR_DRAW_COMMAND_BYTES;
      if (const PFN_vkCmdDrawIndirectCountKHR drawCount = context_.drawIndirectCount()) {
        drawCount(cmd, frame.commands.handle(), offset, frame.counts.handle(), slot * sizeof(std::uint32_t), most, ARBOR_DRAW_COMMAND_BYTES);
      } else if (context_.features().multiDrawIndirect) {
        vkCmdDrawIndirect(cmd, frame.commands.handle(), offset, most, ARBOR_DRAW_COMMAND_BYTES);  // padded with empty draws
      } else {
        for (std::uint32_t c = 0; c < most; ++c) {
          vkCmdDrawIndirect(cmd, frame.commands.handle(), offset + VkDeviceSize{c} * ARBOR_DRAW_COMMAND_BYTES, 1, ARBOR_DRAW_COMMAND_BYTES);
        }
      }
    };
    if (!s.ceiling) drawIndirect(pick(pipelines_.corners(drawn, displaced)), plan.commandBase, plan.counterBase + ARBOR_BUCKETS, 1);
    drawIndirect(s.ceiling && !wire ? pipelines_.ceiling : pick(pipelines_.surface(drawn, pipelineVariant(displaced, captureCapacity_ > 0))),
                 plan.commandBase + 1, plan.counterBase + ARBOR_BUCKETS + 1, plan.maxCommands);
  };
  // `count` cards from `first`: gl_VertexIndex / 4 counts from `first` (the vertex offset), one draw per kCardsPerDraw.
  auto drawCards = [&](VkPipeline pipeline, std::uint32_t count, std::uint32_t first = 0) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindIndexBuffer(cmd, cardIndices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (std::uint32_t done = 0; done < count; done += kCardsPerDraw) {
      const std::uint32_t cards = std::min(kCardsPerDraw, count - done);
      vkCmdDrawIndexed(cmd, 6 * cards, 1, 0, static_cast<std::int32_t>(4 * (first + done)), 0);
      ++frame.draws;
    }
  };

  if (frame.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, frame.timestamps, 0);
  if (frame.statistics) vkCmdBeginQuery(cmd, frame.statistics, 0, 0);
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const TreeInstance& instance = instances[i];
    const GpuTree& tree = *trees_[instance.tree];
    bindTree(instance.tree, instance.model);
    drawMesh(i, tree, false);
    const bool sketch = instance.far && tree.sketchCount > 0;
    const std::uint32_t impostors = sketch ? tree.sketchCount : tree.impostorCount;
    if (s.impostors && impostors > 0) drawCards(pipelines_.cards(false, movesInWind(s, tree)), impostors, sketch ? tree.impostorCount : 0u);
    if (s.leaves && tree.leafCount > 0) {
      // The vertex stage keeps a leaf when its rank (i + 1/2) / N is within the density, thinned with the square of
      // its distance beyond leafLodDistance: no leaf of this tree is nearer than its leaf box, so the leaves past
      // the share kept there need no draw (a far forest runs the vertex stage for a few percent of its leaves).
      double share = std::clamp(static_cast<double>(s.leafDensity), 0.0, 1.0);
      if (s.leafLodDistance > 0.0f) {
        const glm::vec3 eye(glm::inverse(instance.model) * glm::vec4(eye_, 1.0f));
        const float nearest = glm::distance(eye, glm::clamp(eye, tree.leafBounds.lo, tree.leafBounds.hi));
        share *= std::min(1.0, std::pow(static_cast<double>(s.leafLodDistance) / std::max(static_cast<double>(nearest), 1e-3), 2.0));
      }
      const double kept = share * tree.leafCount;
      drawCards(pipelines_.cards(true, movesInWind(s, tree)), std::min(tree.leafCount, static_cast<std::uint32_t>(kept + 0.5) + 1u));
    }
  }
  if (frame.statistics) vkCmdEndQuery(cmd, frame.statistics, 0);
  if (frame.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, frame.timestamps, 1);
  if (s.wireframe) {
    for (std::size_t i = 0; i < instances.size(); ++i) {
      bindTree(instances[i].tree, instances[i].model);
      drawMesh(i, *trees_[instances[i].tree], true);
    }
  }
}

FrameStats TreeRenderer::stats() const { return statsOf(slot()); }

FrameStats TreeRenderer::statsOf(const FrameSlot& frame) const {
  FrameStats f;
  f.draws = frame.draws;
  if (!frame.drewTree) return f;
  if (!frame.plans.empty()) {
    const auto* counts = static_cast<const std::uint32_t*>(frame.countsReadback.mapped());
    for (const InstancePlan& plan : frame.plans) {
      std::uint64_t drawn = 0;
      for (std::uint32_t b = 0; b < ARBOR_BUCKETS; ++b) drawn += counts[plan.counterBase + b];
      f.patchesDrawn += drawn;
      f.patchesCulled += plan.primitives - drawn;
      f.draws += counts[plan.counterBase + ARBOR_BUCKETS] + counts[plan.counterBase + ARBOR_BUCKETS + 1];
    }
  }
  const VkDevice device = context_.device();
  if (frame.statistics) {
    std::uint64_t primitives = 0;
    if (vkGetQueryPoolResults(device, frame.statistics, 0, 1, sizeof primitives, &primitives, sizeof primitives,
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      f.triangles = primitives;
      f.hasTriangles = true;
    }
  }
  if (frame.timestamps) {
    std::uint64_t t[kTimestampCount] = {};
    if (vkGetQueryPoolResults(device, frame.timestamps, 0, kTimestampCount, sizeof t, t, sizeof t[0],
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      f.gpuMilliseconds = static_cast<double>(t[1] - t[0]) * context_.properties().limits.timestampPeriod * 1e-6;
      f.hasTime = true;
    }
  }
  return f;
}

}  // namespace arbor::render
