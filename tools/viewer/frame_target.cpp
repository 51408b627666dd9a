#include "frame_target.hpp"

#include <array>

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
      swapchain_.recreate(window_.framebufferSize());
      return false;
    }
    before(cmd);
    recordPass(cmd, swapchain_.renderPass(), swapchain_.framebuffer(), swapchain_.extent(), inside);
    if (screenshot) swapchain_.recordScreenshot(cmd);
    // Frames run behind the recording (two in flight) except when the picture or its figures are wanted now.
    completed_ = screenshot;
    if (!swapchain_.endFrame(screenshot)) swapchain_.recreate(window_.framebufferSize());  // shown, but out of date now
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

class OffscreenFrames final : public FrameTarget {
 public:
  OffscreenFrames(const vk::VulkanContext& context, VkExtent2D size)
      : context_(context), target_(std::make_unique<render::OffscreenTarget>(context, size.width, size.height)) {}

  // Every target of one context has the same formats, so a renderer made for the first draws into any later one.
  VkRenderPass renderPass() const override { return target_->renderPass(); }
  VkExtent2D extent() const override { return target_->extent(); }
  std::uint32_t imageCount() const override { return 1; }
  bool draw(const Recorder& before, const Recorder& inside, bool screenshot) override {
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      before(cmd);
      recordPass(cmd, target_->renderPass(), target_->framebuffer(), target_->extent(), inside);
      if (screenshot) target_->recordReadback(cmd);
    });
    return true;
  }
  bool lastFrameCompleted() const override { return true; }
  Image screenshot() const override { return target_->readback(); }
  void resize(VkExtent2D size) override {
    if (size.width == extent().width && size.height == extent().height) return;
    waitIdle();
    target_ = std::make_unique<render::OffscreenTarget>(context_, size.width, size.height);
  }
  void waitIdle() const override { vkQueueWaitIdle(context_.queue()); }

 private:
  const vk::VulkanContext& context_;
  std::unique_ptr<render::OffscreenTarget> target_;
};

}  // namespace

std::unique_ptr<FrameTarget> windowTarget(const vk::VulkanContext& context, window::Window& window, VkSurfaceKHR surface, bool vsync) {
  return std::make_unique<WindowTarget>(context, window, surface, vsync);
}

std::unique_ptr<FrameTarget> offscreenTarget(const vk::VulkanContext& context, VkExtent2D size) {
  return std::make_unique<OffscreenFrames>(context, size);
}

}  // namespace arbor::viewer
