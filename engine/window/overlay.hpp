#pragma once
// The Dear ImGui overlay drawn into the window's render pass (GLFW and Vulkan backends of ImGui 1.86).
#include <vulkan/vulkan.h>

#include "vk/context.hpp"

struct GLFWwindow;

namespace arbor::window {

class Overlay {
 public:
  Overlay(const vk::VulkanContext& context, GLFWwindow* window, VkRenderPass renderPass, std::uint32_t imageCount);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  void newFrame();                   // then ImGui:: calls
  void render(VkCommandBuffer cmd);  // inside the render pass
  void discardFrame();               // instead of render, when the frame is not drawn
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  const vk::VulkanContext& context_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

}  // namespace arbor::window
