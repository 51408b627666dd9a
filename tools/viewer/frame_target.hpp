#pragma once
// Where the viewer's frames go: a window's swapchain, or an offscreen image where no display is (tests, CI).
// The frame loop records the same commands into either.
#include <functional>
#include <memory>

#include "image/png_io.hpp"
#include "render/offscreen.hpp"
#include "vk/context.hpp"
#include "window/swapchain.hpp"
#include "window/window.hpp"

namespace arbor::viewer {

using Recorder = std::function<void(VkCommandBuffer)>;

class FrameTarget {
 public:
  virtual ~FrameTarget() = default;
  virtual VkRenderPass renderPass() const = 0;
  virtual VkExtent2D extent() const = 0;
  virtual std::uint32_t imageCount() const = 0;  // images the overlay's backend cycles through
  // One frame: `before` outside the render pass (uploads, query resets), `inside` within it; with `screenshot`
  // the picture is kept for screenshot(). False when nothing was shown (the target was out of date and has been
  // recreated).
  virtual bool draw(const Recorder& before, const Recorder& inside, bool screenshot) = 0;
  virtual Image screenshot() const = 0;  // of the last frame drawn with `screenshot`
  // Whether the frame drawn last has finished on the device (its statistics can be read); a window's frames
  // run behind the recording unless drawn with `screenshot`.
  virtual bool lastFrameCompleted() const = 0;
  virtual void resize(VkExtent2D size) = 0;
  virtual void waitIdle() const = 0;
};

// The window's swapchain; follows the window's framebuffer size.
std::unique_ptr<FrameTarget> windowTarget(const vk::VulkanContext& context, window::Window& window, VkSurfaceKHR surface, bool vsync);
// An offscreen colour + depth image of this size, read back for screenshots.
std::unique_ptr<FrameTarget> offscreenTarget(const vk::VulkanContext& context, VkExtent2D size);

}  // namespace arbor::viewer
