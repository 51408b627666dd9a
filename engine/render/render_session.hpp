#pragma once
// Everything an offscreen render needs, kept together so that tests and benchmarks render many frames
// without rebuilding the context: target, renderer, the uploaded tree.
#include <memory>

#include "offscreen.hpp"
#include "renderer.hpp"
#include "vk/frame_ring.hpp"

namespace arbor::render {

struct FrameResult {
  FrameStats gpu;
  double cpuMilliseconds = 0.0;  // record + submit + wait, on the host
};

class RenderSession {
 public:
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;
  RenderSession(const vk::VulkanContext& context, std::uint32_t width, std::uint32_t height, VkSampleCountFlagBits samples,
                const TreeTextures& textures);

  // `wind`: what moves the tree in the wind (tree/wind.hpp); without it the tree stands still in any wind.
  void setTree(const QuadMesh& mesh, const PatchSet& patches, const std::vector<Leaf>& leaves = {},
               const std::vector<ImpostorSegment>& impostors = {}, const TreeWind* wind = nullptr);
  const GpuTree* tree() const { return tree_.get(); }
  // The session's own tree planted where it stands (empty without one): what render(camera, settings) draws.
  std::vector<TreeInstance> treeInstances() const;
  FrameResult render(const Camera& camera, const RenderSettings& settings);
  // The renderer's trees (set with renderer().setTrees) at these places: a forest.
  FrameResult render(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances);
  // `frames` frames of one view with TreeRenderer::kFramesInFlight of them in flight, as a viewer runs them
  // (the benchmark): per frame, the host's time from one frame's completion to the next's, in ms; `last`
  // gets the last frame's figures. The target's image is not read back.
  std::vector<double> renderInFlight(const Camera& camera, const RenderSettings& settings, const std::vector<TreeInstance>& instances,
                                     int frames, FrameResult& last);
  Image image() const { return target_.readback(); }
  TreeRenderer& renderer() { return renderer_; }
  VkExtent2D extent() const { return target_.extent(); }

 private:
  const vk::VulkanContext& context_;
  OffscreenTarget target_;
  TreeRenderer renderer_;
  // beginFrame, then the render pass over `target` with the renderer's draws.
  void recordFrame(VkCommandBuffer cmd, const OffscreenTarget& target, const Camera& camera, const RenderSettings& settings,
                   const std::vector<TreeInstance>& instances);

  std::unique_ptr<GpuTree> tree_;
  std::unique_ptr<vk::FrameRing> frames_;  // made by the first renderInFlight
  // Frames in flight each write an image of their own: slot 0 the target, the others these (made with the ring).
  std::vector<std::unique_ptr<OffscreenTarget>> inFlightTargets_;
};

// The project's textures from assets/textures (made by `arbor textures`).
TreeTextures loadTreeTextures(const std::string& assetDirectory);

}  // namespace arbor::render
