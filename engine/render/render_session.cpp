#include "render_session.hpp"

#include <chrono>

namespace arbor::render {

RenderSession::RenderSession(const vk::VulkanContext& context, std::uint32_t width, std::uint32_t height,
                             VkSampleCountFlagBits samples, const TreeTextures& textures)
    : context_(context),
      target_(context, width, height, samples),
      renderer_(context, target_.renderPass(), samples, textures) {}

void RenderSession::setTree(const QuadMesh& mesh, const PatchSet& patches, const std::vector<Leaf>& leaves,
                            const std::vector<ImpostorSegment>& impostors) {
  renderer_.setTree(nullptr);
  tree_ = std::make_unique<GpuTree>(uploadTree(context_, mesh, patches, leaves, impostors));
  renderer_.setTree(tree_.get());
}

FrameResult RenderSession::render(const Camera& camera, const RenderSettings& settings) {
  return render(camera, settings, tree_ ? std::vector<TreeInstance>{{0, plantedModel(*tree_)}} : std::vector<TreeInstance>{});
}

FrameResult RenderSession::render(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances) {
  const auto start = std::chrono::steady_clock::now();
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    renderer_.beginFrame(cmd, camera, target_.extent(), settings, instances);
    std::array<VkClearValue, 3> clear{};
    clear[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    clear[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = target_.renderPass();
    begin.framebuffer = target_.framebuffer();
    begin.renderArea = {{0, 0}, target_.extent()};
    begin.clearValueCount = static_cast<std::uint32_t>(clear.size());
    begin.pClearValues = clear.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    renderer_.draw(cmd, target_.extent(), settings, instances);
    vkCmdEndRenderPass(cmd);
    target_.recordReadback(cmd);
  });
  FrameResult result;
  result.cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.gpu = renderer_.stats();
  return result;
}

TreeTextures loadTreeTextures(const std::string& assetDirectory) {
  const std::string dir = assetDirectory + "/textures/";
  return TreeTextures{readPng(dir + "bark_color.png"), readPng(dir + "bark_height.png"), readPng(dir + "leaf_atlas.png")};
}

}  // namespace arbor::render
