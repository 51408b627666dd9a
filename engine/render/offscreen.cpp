#include "offscreen.hpp"

#include <cstring>
#include <vector>

namespace arbor::render {

namespace {
constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // the shaders write gamma-encoded colour
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
}  // namespace

OffscreenTarget::OffscreenTarget(const vk::VulkanContext& context, std::uint32_t width, std::uint32_t height,
                                 VkSampleCountFlagBits samples)
    : context_(context), width_(width), height_(height), samples_(samples) {
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  color_ = vk::GpuImage(context, width, height, kColorFormat,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (msaa ? 0u : static_cast<VkImageUsageFlags>(VK_IMAGE_USAGE_TRANSFER_SRC_BIT)), samples);
  if (msaa) {
    resolve_ = vk::GpuImage(context, width, height, kColorFormat,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  }
  depth_ = vk::GpuImage(context, width, height, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, samples);
  readbackBuffer_ = vk::hostBuffer(context, static_cast<std::size_t>(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

  std::vector<VkAttachmentDescription> attachments(msaa ? 3 : 2);
  attachments[0] = {0, kColorFormat, samples, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                    VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                    msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  attachments[1] = {0, kDepthFormat, samples, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE,
                    VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  if (msaa) {
    attachments[2] = {0, kColorFormat, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE,
                      VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  }
  const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference resolveRef{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pDepthStencilAttachment = &depthRef;
  if (msaa) subpass.pResolveAttachments = &resolveRef;
  // The copy after the pass waits for the colour writes.
  const VkSubpassDependency after{0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                  VK_ACCESS_TRANSFER_READ_BIT, 0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  vk::check(vkCreateRenderPass(context.device(), &info, nullptr, &renderPass_), "vkCreateRenderPass");

  std::vector<VkImageView> views{color_.view(), depth_.view()};
  if (msaa) views.push_back(resolve_.view());
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = renderPass_;
  fb.attachmentCount = static_cast<std::uint32_t>(views.size());
  fb.pAttachments = views.data();
  fb.width = width;
  fb.height = height;
  fb.layers = 1;
  vk::check(vkCreateFramebuffer(context.device(), &fb, nullptr, &framebuffer_), "vkCreateFramebuffer");
}

OffscreenTarget::~OffscreenTarget() {
  vkDestroyFramebuffer(context_.device(), framebuffer_, nullptr);
  vkDestroyRenderPass(context_.device(), renderPass_, nullptr);
}

void OffscreenTarget::recordReadback(VkCommandBuffer cmd) const {
  const vk::GpuImage& source = samples_ != VK_SAMPLE_COUNT_1_BIT ? resolve_ : color_;
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width_, height_, 1};
  vkCmdCopyImageToBuffer(cmd, source.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readbackBuffer_.handle(), 1, &region);
  VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = readbackBuffer_.handle();
  barrier.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &barrier, 0, nullptr);
}

Image OffscreenTarget::readback() const {
  Image image;
  image.width = static_cast<int>(width_);
  image.height = static_cast<int>(height_);
  image.rgba.resize(static_cast<std::size_t>(width_) * height_ * 4);
  std::memcpy(image.rgba.data(), readbackBuffer_.mapped(), image.rgba.size());
  return image;
}

}  // namespace arbor::render
