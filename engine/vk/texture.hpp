#pragma once
// Images with their memory and view: render targets, depth buffers and mip-mapped textures.
#include <cstdint>
#include <vector>

#include "context.hpp"

namespace arbor::vk {

class GpuImage {
 public:
  GpuImage() = default;
  GpuImage(const VulkanContext& context, std::uint32_t width, std::uint32_t height, VkFormat format,
           VkImageUsageFlags usage, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT, std::uint32_t mipLevels = 1);
  ~GpuImage();
  GpuImage(GpuImage&& other) noexcept;
  GpuImage& operator=(GpuImage&& other) noexcept;
  GpuImage(const GpuImage&) = delete;
  GpuImage& operator=(const GpuImage&) = delete;

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t mipLevels() const { return mipLevels_; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  std::uint32_t width_ = 0, height_ = 0, mipLevels_ = 1;
};

bool isDepthFormat(VkFormat format);

// A layout transition with the usual stage/access pairs for the two layouts.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                     std::uint32_t mipLevels = 1);

// A sampled RGBA8 texture with a full mip chain made on the CPU (box filter, wrapping: textures tile).
GpuImage uploadTexture(const VulkanContext& context, const std::vector<std::uint8_t>& rgba, std::uint32_t width,
                       std::uint32_t height, bool srgb);

// Repeat addressing, trilinear filtering, anisotropy up to `maxAnisotropy` where the device has it (1: none;
// lavapipe takes minutes per frame for anisotropic lookups whose level maxLod clamps).
VkSampler createRepeatSampler(const VulkanContext& context, float maxLod, float maxAnisotropy);

}  // namespace arbor::vk
