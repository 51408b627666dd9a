#pragma once
// The window's swapchain with a colour + depth render pass like the offscreen target's, kFramesInFlight frames
// in flight (as many as the renderer has per-frame resources for), recreated on resize, and screenshots read
// back from it.
#include <array>
#include <vector>

#include "image/png_io.hpp"
#include "vk/buffer.hpp"
#include "vk/texture.hpp"

namespace arbor::window {

class Swapchain {
 public:
  // vsync: FIFO; otherwise MAILBOX or IMMEDIATE where offered.
  Swapchain(const vk::VulkanContext& context, VkSurfaceKHR surface, VkExtent2D size, bool vsync);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  VkRenderPass renderPass() const { return renderPass_; }  // the same across recreations
  VkExtent2D extent() const { return extent_; }
  std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  void recreate(VkExtent2D size);

  static constexpr std::uint32_t kFramesInFlight = 2;

  // Waits until the frame kFramesInFlight back has completed, acquires an image and begins a command buffer;
  // false: out of date.
  bool beginFrame(VkCommandBuffer& cmd);
  VkFramebuffer framebuffer() const { return framebuffers_[current_]; }
  // After the render pass: copy the image for screenshot() (valid once the frame is done).
  void recordScreenshot(VkCommandBuffer cmd);
  // Ends the command buffer, submits and presents; with `wait`, also waits until the frame has completed (for
  // a screenshot or statistics). False: out of date or suboptimal (recreate).
  bool endFrame(bool wait);
  void waitIdle() const;
  Image screenshot() const;  // RGBA, row 0 at the top, of the last frame that recorded one

 private:
  void build(VkExtent2D size);
  void destroyImages();
  void acquireNext();
  void dropAcquiredAhead() noexcept;

  const vk::VulkanContext& context_;
  VkSurfaceKHR surface_;
  bool vsync_;
  VkSurfaceFormatKHR format_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  vk::GpuImage depth_;
  vk::Buffer readback_;
  std::array<VkCommandBuffer, kFramesInFlight> cmd_{};
  std::array<VkSemaphore, kFramesInFlight> imageAvailable_{}, renderFinished_{};
  std::array<VkFence, kFramesInFlight> inFlight_{};
  std::uint32_t frame_ = 0;    // which of the frames in flight is being recorded
  std::uint32_t current_ = 0;  // the acquired image
  bool swizzle_ = false;  // BGRA images
  // On a software device (lavapipe) presenting sends the picture to the X server, and every acquire asks the server
  // for the window's size, a round trip that waits until the server has taken in the picture sent before: acquired
  // before presenting, the next image is there at once and the next frame's work overlaps the server's reading.
  bool acquireAhead_ = false;
  bool ahead_ = false;          // an image is acquired for the next frame, its semaphore imageAvailable_[frame_]
  std::uint32_t aheadImage_ = 0;
};

}  // namespace arbor::window
