#include "frame_ring.hpp"

#include <cstdint>

namespace arbor::vk {

FrameRing::FrameRing(const VulkanContext& context, std::uint32_t slots) : context_(context), commands_(slots), fences_(slots) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = context.commandPool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = slots;
  check(vkAllocateCommandBuffers(context.device(), &alloc, commands_.data()), "vkAllocateCommandBuffers");
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // nothing to wait for before the first frames
  for (VkFence& f : fences_) check(vkCreateFence(context.device(), &fence, nullptr, &f), "vkCreateFence");
}

FrameRing::~FrameRing() {
  const VkDevice device = context_.device();
  vkWaitForFences(device, size(), fences_.data(), VK_TRUE, UINT64_MAX);
  for (VkFence f : fences_) vkDestroyFence(device, f, nullptr);
  vkFreeCommandBuffers(device, context_.commandPool(), size(), commands_.data());
}

void FrameRing::wait(std::uint32_t slot) const {
  check(vkWaitForFences(context_.device(), 1, &fences_[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

VkCommandBuffer FrameRing::begin(std::uint32_t slot) {
  wait(slot);
  check(vkResetFences(context_.device(), 1, &fences_[slot]), "vkResetFences");
  const VkCommandBuffer cmd = commands_[slot];
  check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  return cmd;
}

void FrameRing::submit(std::uint32_t slot) {
  const VkCommandBuffer cmd = commands_[slot];
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  info.commandBufferCount = 1;
  info.pCommandBuffers = &cmd;
  check(vkQueueSubmit(context_.queue(), 1, &info, fences_[slot]), "vkQueueSubmit");
}

}  // namespace arbor::vk
