#include "texture.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "buffer.hpp"

namespace arbor::vk {

GpuImage::GpuImage(const VulkanContext& context, std::uint32_t width, std::uint32_t height, VkFormat format,
                   VkImageUsageFlags usage, VkSampleCountFlagBits samples, std::uint32_t mipLevels)
    : device_(context.device()), format_(format), width_(width), height_(height), mipLevels_(mipLevels) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mipLevels;
  info.arrayLayers = 1;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device_, &info, nullptr, &image_), "vkCreateImage");
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device_, image_, &requirements);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = context.memoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(vkAllocateMemory(device_, &alloc, nullptr, &memory_), "vkAllocateMemory");
  check(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image_;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {static_cast<VkImageAspectFlags>(isDepthFormat(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                           0, mipLevels, 0, 1};
  check(vkCreateImageView(device_, &view, nullptr, &view_), "vkCreateImageView");
}

GpuImage::~GpuImage() { release(); }

void GpuImage::release() {
  if (!device_) return;
  vkDestroyImageView(device_, view_, nullptr);
  vkDestroyImage(device_, image_, nullptr);
  vkFreeMemory(device_, memory_, nullptr);
  device_ = VK_NULL_HANDLE;
}

GpuImage::GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    format_ = other.format_;
    width_ = other.width_;
    height_ = other.height_;
    mipLevels_ = other.mipLevels_;
  }
  return *this;
}

bool isDepthFormat(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D16_UNORM;
}

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                     std::uint32_t mipLevels) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, mipLevels, 0, 1};
  // Coarse but always correct: wait for everything before, block everything after.
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &barrier);
}

GpuImage uploadTexture(const VulkanContext& context, const std::vector<std::uint8_t>& rgba, std::uint32_t width,
                       std::uint32_t height, bool srgb) {
  // The mip chain on the CPU: each level averages 2 x 2 texels of the one above, wrapping at the edges.
  std::vector<std::vector<std::uint8_t>> levels{rgba};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sizes{{width, height}};
  while (sizes.back().first > 1 || sizes.back().second > 1) {
    const auto [w, h] = sizes.back();
    const std::uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
    const auto& src = levels.back();
    std::vector<std::uint8_t> dst(static_cast<std::size_t>(nw) * nh * 4);
    for (std::uint32_t y = 0; y < nh; ++y) {
      for (std::uint32_t x = 0; x < nw; ++x) {
        for (std::uint32_t c = 0; c < 4; ++c) {
          unsigned sum = 0;
          for (std::uint32_t dy = 0; dy < 2; ++dy)
            for (std::uint32_t dx = 0; dx < 2; ++dx) sum += src[((((2 * y + dy) % h) * w) + (2 * x + dx) % w) * 4 + c];
          dst[(static_cast<std::size_t>(y) * nw + x) * 4 + c] = static_cast<std::uint8_t>((sum + 2) / 4);
        }
      }
    }
    levels.push_back(std::move(dst));
    sizes.emplace_back(nw, nh);
  }
  std::size_t total = 0;
  for (const auto& l : levels) total += l.size();
  Buffer staging = hostBuffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::vector<VkBufferImageCopy> regions;
  std::size_t offset = 0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    std::memcpy(static_cast<std::uint8_t*>(staging.mapped()) + offset, levels[i].data(), levels[i].size());
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<std::uint32_t>(i), 0, 1};
    region.imageExtent = {sizes[i].first, sizes[i].second, 1};
    regions.push_back(region);
    offset += levels[i].size();
  }
  const auto mips = static_cast<std::uint32_t>(levels.size());
  GpuImage image(context, width, height, srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_SAMPLE_COUNT_1_BIT, mips);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    transitionImage(cmd, image.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, mips);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<std::uint32_t>(regions.size()), regions.data());
    transitionImage(cmd, image.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, mips);
  });
  return image;
}

VkSampler createRepeatSampler(const VulkanContext& context, float maxLod, float maxAnisotropy) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.maxLod = maxLod;
  const bool useAnisotropy = maxAnisotropy > 1.0f && context.features().samplerAnisotropy;
  info.anisotropyEnable = useAnisotropy;
  info.maxAnisotropy = useAnisotropy ? std::min(maxAnisotropy, context.properties().limits.maxSamplerAnisotropy) : 1.0f;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(context.device(), &info, nullptr, &sampler), "vkCreateSampler");
  return sampler;
}

}  // namespace arbor::vk
