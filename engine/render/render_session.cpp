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

RenderSession::~RenderSession() { vkDeviceWaitIdle(context_.device()); }

void RenderSession::recordFrame(VkCommandBuffer cmd, const OffscreenTarget& target, const Camera& camera, const RenderSettings& settings,
                                const std::vector<TreeInstance>& instances) {
  renderer_.beginFrame(cmd, camera, target.extent(), settings, instances);
  std::array<VkClearValue, 3> clear{};
  clear[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = target.renderPass();
  begin.framebuffer = target.framebuffer();
  begin.renderArea = {{0, 0}, target.extent()};
  begin.clearValueCount = static_cast<std::uint32_t>(clear.size());
  begin.pClearValues = clear.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  renderer_.draw(cmd, target.extent(), settings, instances);
  vkCmdEndRenderPass(cmd);
}

std::vector<double> RenderSession::renderInFlight(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances,
                                                  int frames, FrameResult& last) {
  if (!frames_) {
    frames_ = std::make_unique<vk::FrameRing>(context_, TreeRenderer::kFramesInFlight);
    for (std::uint32_t slot = 1; slot < TreeRenderer::kFramesInFlight; ++slot) {
      inFlightTargets_.push_back(std::make_unique<OffscreenTarget>(context_, target_.extent().width, target_.extent().height, target_.samples()));
    }
  }
  vkDeviceWaitIdle(context_.device());  // frames before this run were waited for one by one; start from a quiet device
  std::vector<double> intervals;
  auto previous = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    // The renderer cycles its slots with each beginFrame, as this loop cycles the ring's.
    const auto slot = static_cast<std::uint32_t>(f) % TreeRenderer::kFramesInFlight;
    frames_->wait(slot);
    if (f >= static_cast<int>(TreeRenderer::kFramesInFlight)) {
      const auto now = std::chrono::steady_clock::now();  // frame f - kFramesInFlight is done
      intervals.push_back(std::chrono::duration<double, std::milli>(now - previous).count());
      previous = now;
    }
    recordFrame(frames_->begin(slot), slot == 0 ? target_ : *inFlightTargets_[slot - 1], camera, settings, instances);
    frames_->submit(slot);
  }
  for (int f = std::max(0, frames - static_cast<int>(TreeRenderer::kFramesInFlight)); f < frames; ++f) {
    frames_->wait(static_cast<std::uint32_t>(f) % TreeRenderer::kFramesInFlight);
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
    recordFrame(cmd, target_, camera, settings, instances);
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
