#include "frame_target.hpp"

#include <array>

#include "render/renderer.hpp"
#include "vk/frame_ring.hpp"

namespace arbor::viewer {

namespace {

void recordPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent, const Recorder& inside) {
  std::array<VkClearValue, 3> clear{};  // colour, depth and (multisampled targets) the resolve image
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = static_cast<std::uint32_t>(clear.size());
  begin.pClearValues = clear.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  inside(cmd);
  vkCmdEndRenderPass(cmd);
}

class WindowTarget final : public FrameTarget {
 public:
  WindowTarget(const vk::VulkanContext& context, window::Window& window, VkSurfaceKHR surface, bool vsync)
      : window_(window), swapchain_(context, surface, window.framebufferSize(), vsync) {}

  VkRenderPass renderPass() const override { return swapchain_.renderPass(); }
  VkExtent2D extent() const override { return swapchain_.extent(); }
  std::uint32_t imageCount() const override { return swapchain_.imageCount(); }
  bool draw(const Recorder& before, const Recorder& inside, bool screenshot) override {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (!swapchain_.beginFrame(cmd)) {
      swapchain_.recreate(window_.queryFramebufferSize());
      return false;
    }
    before(cmd);
    recordPass(cmd, swapchain_.renderPass(), swapchain_.framebuffer(), swapchain_.extent(), inside);
    if (screenshot) swapchain_.recordScreenshot(cmd);
    // Frames run behind the recording (two in flight) except when the picture or its figures are wanted now.
    completed_ = screenshot;
    if (!swapchain_.endFrame(screenshot)) swapchain_.recreate(window_.queryFramebufferSize());  // shown, but out of date now
    return true;
  }
  bool lastFrameCompleted() const override { return completed_; }
  Image screenshot() const override { return swapchain_.screenshot(); }
  void resize(VkExtent2D size) override { swapchain_.recreate(size); }
  void waitIdle() const override { swapchain_.waitIdle(); }

 private:
  window::Window& window_;
  window::Swapchain swapchain_;
  bool completed_ = false;
};

// Offscreen frames run two in flight, as the window's do, each into its own image: the viewer's pace offscreen is
// then the slower of recording and drawing, not their sum. A frame waits to complete only when its picture is wanted.
class OffscreenFrames final : public FrameTarget {
 public:
  static constexpr std::uint32_t kFrames = window::Swapchain::kFramesInFlight;
  static_assert(kFrames <= render::TreeRenderer::kFramesInFlight, "the renderer keeps per-frame resources for every frame in flight");

  OffscreenFrames(const vk::VulkanContext& context, VkExtent2D size) : context_(context), frames_(context, kFrames) { makeTargets(size); }

  // Every target of one context has the same formats, so a renderer made for the first draws into any later one.
  VkRenderPass renderPass() const override { return targets_[0]->renderPass(); }
  VkExtent2D extent() const override { return targets_[0]->extent(); }
  std::uint32_t imageCount() const override { return kFrames; }
  bool draw(const Recorder& before, const Recorder& inside, bool screenshot) override {
    // The frame that last used this slot (its image, commands and the renderer's per-frame resources) is waited for.
    const VkCommandBuffer cmd = frames_.begin(slot_);
    const render::OffscreenTarget& target = *targets_[slot_];
    before(cmd);
    recordPass(cmd, target.renderPass(), target.framebuffer(), target.extent(), inside);
    if (screenshot) target.recordReadback(cmd);
    frames_.submit(slot_);
    if (screenshot) frames_.wait(slot_);
    completed_ = screenshot;
    last_ = slot_;
    slot_ = (slot_ + 1) % kFrames;
    return true;
  }
  bool lastFrameCompleted() const override { return completed_; }
  Image screenshot() const override { return targets_[last_]->readback(); }
  void resize(VkExtent2D size) override {
    if (size.width == extent().width && size.height == extent().height) return;
    waitIdle();
    makeTargets(size);
  }
  void waitIdle() const override { vkQueueWaitIdle(context_.queue()); }

 private:
  void makeTargets(VkExtent2D size) {
    for (auto& t : targets_) t = std::make_unique<render::OffscreenTarget>(context_, size.width, size.height);
  }

  const vk::VulkanContext& context_;
  std::array<std::unique_ptr<render::OffscreenTarget>, kFrames> targets_;
  vk::FrameRing frames_;  // after the targets: destroyed first, it waits for the frames drawing into them
  std::uint32_t slot_ = 0, last_ = 0;
  bool completed_ = false;
};

}  // namespace

std::unique_ptr<FrameTarget> windowTarget(const vk::VulkanContext& context, window::Window& window, VkSurfaceKHR surface, bool vsync) {
  return std::make_unique<WindowTarget>(context, window, surface, vsync);
}

std::unique_ptr<FrameTarget> offscreenTarget(const vk::VulkanContext& context, VkExtent2D size) {
  return std::make_unique<OffscreenFrames>(context, size);
}

}  // namespace arbor::viewer
