#pragma once
// A buffer with its own memory. Host-visible buffers stay mapped; device-local ones are filled through a
// staging copy.
#include <cstddef>

#include "context.hpp"

namespace arbor::vk {

class Buffer {
 public:
  Buffer() = default;
  Buffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags memory);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // null unless host-visible

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// A device-local buffer holding `bytes`, uploaded through a staging buffer.
Buffer uploadBuffer(const VulkanContext& context, const void* data, std::size_t bytes, VkBufferUsageFlags usage);

// A host-visible, coherent buffer (read back by the CPU, or rewritten every frame).
Buffer hostBuffer(const VulkanContext& context, std::size_t bytes, VkBufferUsageFlags usage);

}  // namespace arbor::vk
