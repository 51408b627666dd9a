#pragma once
// Frames in flight without a swapchain: a command buffer and a fence per slot, each slot reused only once the
// frame that last used it has completed (the offscreen viewer, the benchmark's frames in flight).

#include <cstdint>
#include <vector>

#include "context.hpp"

namespace arbor::vk {

class FrameRing {
 public:
  FrameRing(const VulkanContext& context, std::uint32_t slots);
  ~FrameRing();  // waits for every slot's frame
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;

  // Waits until the frame that last used `slot` has completed.
  void wait(std::uint32_t slot) const;
  // Waits for the slot, then begins its command buffer for a new frame.
  VkCommandBuffer begin(std::uint32_t slot);
  // Ends the slot's command buffer and submits it; its fence signals when the frame completes.
  void submit(std::uint32_t slot);
  std::uint32_t size() const { return static_cast<std::uint32_t>(fences_.size()); }

 private:
  const VulkanContext& context_;
  std::vector<VkCommandBuffer> commands_;
  std::vector<VkFence> fences_;
};

}  // namespace arbor::vk
