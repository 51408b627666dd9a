#pragma once
// An offscreen colour + depth target (optionally multisampled, resolved), and its readback to an image.
#include "image/png_io.hpp"
#include "vk/buffer.hpp"
#include "vk/texture.hpp"

namespace arbor::render {

class OffscreenTarget {
 public:
  OffscreenTarget(const vk::VulkanContext& context, std::uint32_t width, std::uint32_t height,
                  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  VkRenderPass renderPass() const { return renderPass_; }
  VkFramebuffer framebuffer() const { return framebuffer_; }
  VkExtent2D extent() const { return {width_, height_}; }
  VkSampleCountFlagBits samples() const { return samples_; }

  // After the render pass: copy the (resolved) colour into the readback buffer.
  void recordReadback(VkCommandBuffer cmd) const;
  // Once the commands have completed: the picture, row 0 at the top.
  Image readback() const;

 private:
  const vk::VulkanContext& context_;
  std::uint32_t width_, height_;
  VkSampleCountFlagBits samples_;
  vk::GpuImage color_, resolve_, depth_;
  vk::Buffer readbackBuffer_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace arbor::render
