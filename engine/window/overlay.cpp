#include "overlay.hpp"

#include <algorithm>
#include <array>
#include <cfloat>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

namespace arbor::window {

namespace {

void checkImGuiResult(VkResult result) { vk::check(result, "ImGui Vulkan backend"); }

}  // namespace

Overlay::Overlay(const vk::VulkanContext& context, const Window& window, VkRenderPass renderPass, std::uint32_t imageCount)
    : context_(context), window_(window) {
  const std::array<VkDescriptorPoolSize, 1> sizes{{{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8}}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 8;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  vk::check(vkCreateDescriptorPool(context.device(), &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForVulkan(window.handle(), true);  // its callbacks: keys, text, clicks, the wheel
  cursors_[ImGuiMouseCursor_TextInput] = glfwCreateStandardCursor(GLFW_IBEAM_CURSOR);
  cursors_[ImGuiMouseCursor_ResizeNS] = glfwCreateStandardCursor(GLFW_VRESIZE_CURSOR);
  cursors_[ImGuiMouseCursor_ResizeEW] = glfwCreateStandardCursor(GLFW_HRESIZE_CURSOR);
  cursors_[ImGuiMouseCursor_Hand] = glfwCreateStandardCursor(GLFW_HAND_CURSOR);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physicalDevice();
  info.Device = context.device();
  info.QueueFamily = context.queueFamily();
  info.Queue = context.queue();
  info.DescriptorPool = pool_;
  info.MinImageCount = std::max(2u, imageCount);
  info.ImageCount = std::max(2u, imageCount);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImGuiResult;
  ImGui_ImplVulkan_Init(&info, renderPass);
  context.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Overlay::~Overlay() {
  vkDeviceWaitIdle(context_.device());
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  for (GLFWcursor* c : cursors_)
    if (c) glfwDestroyCursor(c);
  vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
}

void Overlay::newFrame() {
  ImGui_ImplVulkan_NewFrame();
  platformFrame();
  ImGui::NewFrame();
}

// What ImGui_ImplGlfw_NewFrame sets, from the window's events: that function asks X11 for the window's and the
// framebuffer's size, the focus and the cursor every frame, round trips that each wait until the server has taken
// in the picture sent last (on lavapipe a sixth of the frame).
void Overlay::platformFrame() {
  ImGuiIO& io = ImGui::GetIO();
  const VkExtent2D size = window_.windowSize(), framebuffer = window_.framebufferSize();
  io.DisplaySize = ImVec2(static_cast<float>(size.width), static_cast<float>(size.height));
  if (size.width > 0 && size.height > 0) {
    io.DisplayFramebufferScale = ImVec2(static_cast<float>(framebuffer.width) / static_cast<float>(size.width),
                                        static_cast<float>(framebuffer.height) / static_cast<float>(size.height));
  }
  const double now = glfwGetTime();
  io.DeltaTime = time_ > 0.0 ? std::max(static_cast<float>(now - time_), 1e-6f) : 1.0f / 60.0f;
  time_ = now;
  // A click shorter than a frame still counts as held for this one.
  for (int b = 0; b < IM_ARRAYSIZE(io.MouseDown); ++b) io.MouseDown[b] = window_.mouseButtonPressed(b) || window_.mouseButtonHeld(b);
  io.MousePos = window_.focused() || window_.cursorInside() ? ImVec2(static_cast<float>(window_.cursorX()), static_cast<float>(window_.cursorY()))
                                                            : ImVec2(-FLT_MAX, -FLT_MAX);
  const int shape = ImGui::GetMouseCursor();
  if (shape != cursor_) {
    glfwSetCursor(window_.handle(), shape >= 0 && shape < static_cast<int>(cursors_.size()) ? cursors_[static_cast<std::size_t>(shape)] : nullptr);
    cursor_ = shape;
  }
}

void Overlay::render(VkCommandBuffer cmd) {
  ImGui::Render();
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

void Overlay::discardFrame() { ImGui::EndFrame(); }

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace arbor::window
