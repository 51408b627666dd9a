#pragma once
// The Dear ImGui overlay drawn into the window's render pass (GLFW and Vulkan backends of ImGui 1.86).
#include <vulkan/vulkan.h>

#include <array>

#include "vk/context.hpp"
#include "window.hpp"

struct GLFWcursor;

namespace arbor::window {

class Overlay {
 public:
  Overlay(const vk::VulkanContext& context, const Window& window, VkRenderPass renderPass, std::uint32_t imageCount);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  void newFrame();                   // then ImGui:: calls
  void render(VkCommandBuffer cmd);  // inside the render pass
  void discardFrame();               // instead of render, when the frame is not drawn
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  void platformFrame();

  const vk::VulkanContext& context_;
  const Window& window_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  double time_ = 0.0;                        // of the last frame, for ImGui's frame time
  std::array<GLFWcursor*, 9> cursors_{};    // by ImGuiMouseCursor (null: the arrow)
  int cursor_ = -2;                          // the shape set last
};

}  // namespace arbor::window
