#pragma once
// The walkthrough's scene: a forest of the given presets, model, skeleton or graph files, each grown at a few
// seeds and instanced; the panel edits every growth model's parameters and regrows on request.
#include <memory>
#include <string>
#include <vector>

#include "grow_forest.hpp"
#include "viewer.hpp"

namespace arbor::viewer {

class ForestScene final : public ViewerScene {
 public:
  explicit ForestScene(cli::ForestRequest request);

  void start(const vk::VulkanContext& context, render::TreeRenderer& renderer) override;
  std::string summary() const override;
  void stop() override { forest_.reset(); }
  const render::Forest& forest() const override { return *forest_; }
  render::Camera overview(float aspect) const override { return forest_->overview(aspect); }
  std::vector<render::Camera> tour(float aspect) const override { return forest_->tour(aspect); }
  bool handle(const WindowEvent& event) override;
  bool replacesGpuData() const override { return regenerate_; }
  void update(render::TreeRenderer& renderer) override;
  void panel(ViewState& state) override;
  void drawLines(VkCommandBuffer, render::TreeRenderer&) override {}
  std::string status() const override { return ""; }

 private:
  void updateEstimates();
  void save(const std::string& path);        // the first source's model, as edited, as JSON
  void exportMesh(const std::string& path);  // the first tree's whole mesh (.obj, .gltf, .glb)

  cli::ForestRequest request_;  // the panel edits its sources' models
  const vk::VulkanContext* context_ = nullptr;
  std::unique_ptr<render::Forest> forest_;
  std::vector<TreeEstimate> estimates_;  // per source, redone whenever a slider moves
  std::string refusal_;                  // why the trees as set would not be grown ("" when they would)
  bool regenerate_ = false;
  std::string outputPath_ = "out/tree.json";  // the panel's save / export field
  std::string fileStatus_;                     // what the last save or export did
};

}  // namespace arbor::viewer
