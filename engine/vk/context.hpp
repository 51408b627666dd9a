#pragma once
// The Vulkan instance, the chosen physical device, the logical device with its one graphics queue, and the
// validation layer's messages. Every other engine object borrows a VulkanContext.
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace arbor::vk {

// A Vulkan call failed, or the machine offers no usable device; callers exit with code 1.
class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void check(VkResult result, const char* what);

struct ContextOptions {
  bool validation = false;                    // Khronos validation layer; its errors are counted
  std::string device;                         // substring of the device name to prefer ("" = best)
  std::vector<const char*> instanceExtensions;  // e.g. what GLFW needs for a window
  std::vector<const char*> deviceExtensions;    // e.g. VK_KHR_swapchain
};

class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  VkCommandPool commandPool() const { return pool_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceFeatures& features() const { return enabled_; }

  // vkCmdDrawIndirectCount (VK_KHR_draw_indirect_count), or null where the device has not got it.
  PFN_vkCmdDrawIndirectCountKHR drawIndirectCount() const { return drawIndirectCount_; }

  // Mesa's lavapipe (llvmpipe): one draw must not emit more than 65535 tessellated vertices there.
  bool isLavapipe() const { return lavapipe_; }
  std::string deviceDescription() const;

  // Validation errors reported so far (each is also printed to stderr).
  std::uint32_t validationErrors() const { return validationErrors_.load(); }
  bool validationEnabled() const { return validation_; }

  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags properties) const;

  // Records commands into a one-shot command buffer, submits it and waits for it to finish.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT type,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceFeatures enabled_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  PFN_vkCmdDrawIndirectCountKHR drawIndirectCount_ = nullptr;
  bool lavapipe_ = false;
  bool validation_ = false;
  std::atomic<std::uint32_t> validationErrors_{0};
};

}  // namespace arbor::vk
