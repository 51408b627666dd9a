#include "swapchain.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

namespace arbor::window {

namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace

Swapchain::Swapchain(const vk::VulkanContext& context, VkSurfaceKHR surface, VkExtent2D size, bool vsync)
    : context_(context), surface_(surface), vsync_(vsync), acquireAhead_(context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
  VkBool32 presentable = VK_FALSE;
  vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice(), context.queueFamily(), surface, &presentable);
  if (!presentable) throw vk::VulkanError("the Vulkan device's graphics queue cannot present to this window");
  std::uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), surface, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), surface, &count, formats.data());
  if (formats.empty()) throw vk::VulkanError("the window surface offers no formats");
  // UNORM: the shaders write gamma-encoded colour themselves, as into the offscreen target.
  format_ = formats.front();
  for (const VkSurfaceFormatKHR& f : formats) {
    if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) {
      format_ = f;
      break;
    }
  }
  swizzle_ = format_.format == VK_FORMAT_B8G8R8A8_UNORM;
  vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice(), surface, &count, nullptr);
  std::vector<VkPresentModeKHR> modes(count);
  vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice(), surface, &count, modes.data());
  if (!vsync) {
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
      if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) {
        presentMode_ = wanted;
        break;
      }
    }
  }

  const std::array<VkAttachmentDescription, 2> attachments{{
      {0, format_.format, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
       VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR},
      {0, kDepthFormat, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE,
       VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL},
  }};
  const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pDepthStencilAttachment = &depthRef;
  // The acquired image is written only after the presentation engine let go of it; the depth buffer is
  // cleared only after the previous frame's tests.
  const std::array<VkSubpassDependency, 2> dependencies{{
      {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,  // the frame before, still in flight, wrote the shared depth image
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, 0},
      {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, 0},
  }};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  vk::check(vkCreateRenderPass(context.device(), &info, nullptr, &renderPass_), "vkCreateRenderPass");

  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = context.commandPool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = kFramesInFlight;
  vk::check(vkAllocateCommandBuffers(context.device(), &alloc, cmd_.data()), "vkAllocateCommandBuffers");
  const VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // nothing to wait for before the first frames
  for (std::uint32_t f = 0; f < kFramesInFlight; ++f) {
    vk::check(vkCreateSemaphore(context.device(), &semaphore, nullptr, &imageAvailable_[f]), "vkCreateSemaphore");
    vk::check(vkCreateSemaphore(context.device(), &semaphore, nullptr, &renderFinished_[f]), "vkCreateSemaphore");
    vk::check(vkCreateFence(context.device(), &fence, nullptr, &inFlight_[f]), "vkCreateFence");
  }
  build(size);
}

Swapchain::~Swapchain() {
  const VkDevice device = context_.device();
  dropAcquiredAhead();
  vkDeviceWaitIdle(device);
  destroyImages();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  for (std::uint32_t f = 0; f < kFramesInFlight; ++f) {
    vkDestroyFence(device, inFlight_[f], nullptr);
    vkDestroySemaphore(device, imageAvailable_[f], nullptr);
    vkDestroySemaphore(device, renderFinished_[f], nullptr);
  }
  vkFreeCommandBuffers(device, context_.commandPool(), kFramesInFlight, cmd_.data());
  vkDestroyRenderPass(device, renderPass_, nullptr);
}

void Swapchain::destroyImages() {
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(context_.device(), f, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(context_.device(), v, nullptr);
  framebuffers_.clear();
  views_.clear();
  images_.clear();
}

void Swapchain::recreate(VkExtent2D size) {
  dropAcquiredAhead();
  vkDeviceWaitIdle(context_.device());
  build(size);
}

void Swapchain::build(VkExtent2D size) {
  const VkDevice device = context_.device();
  VkSurfaceCapabilitiesKHR caps{};
  vk::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), surface_, &caps), "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  extent_ = caps.currentExtent.width != std::numeric_limits<std::uint32_t>::max()
                ? caps.currentExtent
                : VkExtent2D{std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                             std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  std::uint32_t images = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = images;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  vk::check(vkCreateSwapchainKHR(device, &info, nullptr, &created), "vkCreateSwapchainKHR");
  destroyImages();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = created;

  std::uint32_t count = 0;
  vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data());
  depth_ = vk::GpuImage(context_, extent_.width, extent_.height, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView v = VK_NULL_HANDLE;
    vk::check(vkCreateImageView(device, &view, nullptr, &v), "vkCreateImageView");
    views_.push_back(v);
    const std::array<VkImageView, 2> attachments{v, depth_.view()};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = renderPass_;
    fb.attachmentCount = static_cast<std::uint32_t>(attachments.size());
    fb.pAttachments = attachments.data();
    fb.width = extent_.width;
    fb.height = extent_.height;
    fb.layers = 1;
    VkFramebuffer f = VK_NULL_HANDLE;
    vk::check(vkCreateFramebuffer(device, &fb, nullptr, &f), "vkCreateFramebuffer");
    framebuffers_.push_back(f);
  }
  readback_ = vk::hostBuffer(context_, static_cast<std::size_t>(extent_.width) * extent_.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

bool Swapchain::beginFrame(VkCommandBuffer& cmd) {
  const VkDevice device = context_.device();
  // The frame that last used this slot's command buffer, semaphores and the renderer's per-frame resources.
  vk::check(vkWaitForFences(device, 1, &inFlight_[frame_], VK_TRUE, UINT64_MAX), "vkWaitForFences");
  VkResult acquired = VK_SUCCESS;
  if (ahead_) {
    current_ = aheadImage_;
    ahead_ = false;
  } else {
    acquired = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, imageAvailable_[frame_], VK_NULL_HANDLE, &current_);
  }
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (acquired != VK_SUBOPTIMAL_KHR) vk::check(acquired, "vkAcquireNextImageKHR");
  vk::check(vkResetFences(device, 1, &inFlight_[frame_]), "vkResetFences");
  vk::check(vkResetCommandBuffer(cmd_[frame_], 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk::check(vkBeginCommandBuffer(cmd_[frame_], &begin), "vkBeginCommandBuffer");
  cmd = cmd_[frame_];
  return true;
}

void Swapchain::recordScreenshot(VkCommandBuffer cmd) {
  const VkImage image = images_[current_];
  vk::transitionImage(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(), 1, &region);
  vk::transitionImage(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
}

bool Swapchain::endFrame(bool wait) {
  const std::uint32_t frame = frame_;
  frame_ = (frame_ + 1) % kFramesInFlight;
  vk::check(vkEndCommandBuffer(cmd_[frame]), "vkEndCommandBuffer");
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &imageAvailable_[frame];
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_[frame];
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &renderFinished_[frame];
  vk::check(vkQueueSubmit(context_.queue(), 1, &submit, inFlight_[frame]), "vkQueueSubmit");
  if (acquireAhead_) acquireNext();
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &renderFinished_[frame];
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain_;
  present.pImageIndices = &current_;
  const VkResult presented = vkQueuePresentKHR(context_.queue(), &present);
  if (wait) vk::check(vkWaitForFences(context_.device(), 1, &inFlight_[frame], VK_TRUE, UINT64_MAX), "vkWaitForFences");
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) return false;
  vk::check(presented, "vkQueuePresentKHR");
  return true;
}

void Swapchain::acquireNext() {
  const VkDevice device = context_.device();
  // The semaphore's last wait belongs to the frame that used this slot before; it has run once its fence is set.
  vk::check(vkWaitForFences(device, 1, &inFlight_[frame_], VK_TRUE, UINT64_MAX), "vkWaitForFences");
  // Without waiting: where no image is free now (or the window changed), beginFrame acquires as usual.
  const VkResult acquired = vkAcquireNextImageKHR(device, swapchain_, 0, imageAvailable_[frame_], VK_NULL_HANDLE, &aheadImage_);
  ahead_ = acquired == VK_SUCCESS || acquired == VK_SUBOPTIMAL_KHR;
}

void Swapchain::dropAcquiredAhead() noexcept {
  if (!ahead_) return;
  ahead_ = false;
  // A batch that waits on the acquire's semaphore leaves it unsignalled for the next acquire. Not checked: the
  // destructor calls this too, and a lost device shows in the calls that follow a recreate.
  const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &imageAvailable_[frame_];
  submit.pWaitDstStageMask = &stage;
  if (vkQueueSubmit(context_.queue(), 1, &submit, VK_NULL_HANDLE) == VK_SUCCESS) vkQueueWaitIdle(context_.queue());
}

void Swapchain::waitIdle() const { vkDeviceWaitIdle(context_.device()); }

Image Swapchain::screenshot() const {
  Image image;
  image.width = static_cast<int>(extent_.width);
  image.height = static_cast<int>(extent_.height);
  image.rgba.resize(static_cast<std::size_t>(extent_.width) * extent_.height * 4);
  std::memcpy(image.rgba.data(), readback_.mapped(), image.rgba.size());
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    if (swizzle_) std::swap(image.rgba[i], image.rgba[i + 2]);
    image.rgba[i + 3] = 255;
  }
  return image;
}

}  // namespace arbor::window
