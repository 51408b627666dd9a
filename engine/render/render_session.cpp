#include "render_session.hpp"

#include <algorithm>
#include <array>
#include <chrono>

namespace arbor::render {

RenderSession::RenderSession(const vk::VulkanContext& context, std::uint32_t width, std::uint32_t height,
                             VkSampleCountFlagBits samples, const TreeTextures& textures)
    : context_(context),
      target_(context, width, height, samples),
      renderer_(context, target_.renderPass(), samples, textures) {}

void RenderSession::setTree(const QuadMesh& mesh, const PatchSet& patches, const std::vector<Leaf>& leaves,
                            const std::vector<ImpostorSegment>& impostors, const TreeWind* wind) {
  renderer_.setTree(nullptr);
  tree_ = std::make_unique<GpuTree>(uploadTree(context_, mesh, patches, leaves, impostors, {}, false, wind));
  renderer_.setTree(tree_.get());
}

FrameResult RenderSession::render(const Camera& camera, const RenderSettings& settings) {
  return render(camera, settings, treeInstances());
}

std::vector<TreeInstance> RenderSession::treeInstances() const {
  return tree_ ? std::vector<TreeInstance>{{0, plantedModel(*tree_)}} : std::vector<TreeInstance>{};
}

RenderSession::~RenderSession() {
  vkDeviceWaitIdle(context_.device());
  for (VkFence fence : fences_) {
    if (fence) vkDestroyFence(context_.device(), fence, nullptr);
  }
  if (commands_[0]) vkFreeCommandBuffers(context_.device(), context_.commandPool(), TreeRenderer::kFramesInFlight, commands_.data());
}

void RenderSession::recordFrame(VkCommandBuffer cmd, const Camera& camera, const RenderSettings& settings,
                                const std::vector<TreeInstance>& instances) {
  renderer_.beginFrame(cmd, camera, target_.extent(), settings, instances);
  std::array<VkClearValue, 3> clear{};
  clear[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = target_.renderPass();
  begin.framebuffer = target_.framebuffer();
  begin.renderArea = {{0, 0}, target_.extent()};
  begin.clearValueCount = static_cast<std::uint32_t>(clear.size());
  begin.pClearValues = clear.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  renderer_.draw(cmd, target_.extent(), settings, instances);
  vkCmdEndRenderPass(cmd);
}

std::vector<double> RenderSession::renderInFlight(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances,
                                                  int frames, FrameResult& last) {
  const VkDevice device = context_.device();
  if (!commands_[0]) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context_.commandPool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = TreeRenderer::kFramesInFlight;
    vk::check(vkAllocateCommandBuffers(device, &alloc, commands_.data()), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    for (VkFence& f : fences_) vk::check(vkCreateFence(device, &fence, nullptr, &f), "vkCreateFence");
  }
  vkDeviceWaitIdle(device);  // frames before this run were waited for one by one; start from a quiet device
  std::vector<double> intervals;
  auto previous = std::chrono::steady_clock::now();
  const auto waitFor = [&](std::uint32_t slot) {
    vk::check(vkWaitForFences(device, 1, &fences_[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences");
  };
  for (int f = 0; f < frames; ++f) {
    // The renderer cycles its slots with each beginFrame, as this loop cycles its command buffers and fences.
    const auto slot = static_cast<std::uint32_t>(f) % TreeRenderer::kFramesInFlight;
    waitFor(slot);
    if (f >= static_cast<int>(TreeRenderer::kFramesInFlight)) {
      const auto now = std::chrono::steady_clock::now();  // frame f - kFramesInFlight is done
      intervals.push_back(std::chrono::duration<double, std::milli>(now - previous).count());
      previous = now;
    }
    vk::check(vkResetFences(device, 1, &fences_[slot]), "vkResetFences");
    const VkCommandBuffer cmd = commands_[slot];
    vk::check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    recordFrame(cmd, camera, settings, instances);
    vk::check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    vk::check(vkQueueSubmit(context_.queue(), 1, &submit, fences_[slot]), "vkQueueSubmit");
  }
  for (int f = std::max(0, frames - static_cast<int>(TreeRenderer::kFramesInFlight)); f < frames; ++f) {
    waitFor(static_cast<std::uint32_t>(f) % TreeRenderer::kFramesInFlight);
    const auto now = std::chrono::steady_clock::now();
    intervals.push_back(std::chrono::duration<double, std::milli>(now - previous).count());
    previous = now;
  }
  last.gpu = renderer_.stats();
  last.cpuMilliseconds = intervals.empty() ? 0.0 : intervals.back();
  return intervals;
}

FrameResult RenderSession::render(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances) {
  const auto start = std::chrono::steady_clock::now();
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    recordFrame(cmd, camera, settings, instances);
    target_.recordReadback(cmd);
  });
  FrameResult result;
  result.cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.gpu = renderer_.stats();
  return result;
}

TreeTextures loadTreeTextures(const std::string& assetDirectory) {
  const std::string dir = assetDirectory + "/textures/";
  return TreeTextures{readPng(dir + "bark_color.png"), readPng(dir + "bark_height.png"), readPng(dir + "leaf_atlas.png")};
}

}  // namespace arbor::render
