#pragma once
// The modeller (Patrick, Rege & Bailey's interactive tool, in the viewer): one space-colonization tree that grows,
// pauses, steps and rewinds, with its attraction clouds and obstacles drawn as wireframes and edited from the
// panel or from --events; the mesh is rebuilt after every change.
#include <memory>
#include <string>
#include <vector>

#include "growth/space_colonization/space_colonization_model.hpp"
#include "viewer.hpp"
#include "vk/buffer.hpp"

namespace arbor::viewer {

// The model after one editing event (add-, move-, resize-, remove-cloud or -obstacle), checked as the model file
// reader checks a file; InputError naming --events and the event otherwise. Other events leave it as it is.
sc::SpaceColonization editedModel(const sc::SpaceColonization& model, const WindowEvent& event);

// Whether a scene event is one the modeller understands (its growth and editing events).
bool isModellerEvent(const WindowEvent& event);

class GrowthScene final : public ViewerScene {
 public:
  // `model` must be a space-colonization model (spaceColonizationOf); it starts grown to the end.
  GrowthScene(const TreeModel& model, std::uint64_t seed);

  // The script's scene events, in frame order, tried on the model before anything starts, so that a bad index,
  // cloud or file fails with exit 2 before a window opens.
  static void checkEvents(const TreeModel& model, const std::vector<WindowEvent>& events);

  void start(const vk::VulkanContext& context, render::TreeRenderer& renderer) override;
  std::string summary() const override;
  void stop() override;
  const render::Forest& forest() const override { return *forest_; }
  // Framing the working volume (clouds, obstacles and tree), fixed while the tree grows into it.
  render::Camera overview(float aspect) const override;
  std::vector<render::Camera> tour(float aspect) const override;
  bool handle(const WindowEvent& event) override;
  bool replacesGpuData() const override { return true; }  // growing rebuilds the mesh and the wireframes
  void update(render::TreeRenderer& renderer) override;
  void panel(ViewState& state) override;
  void drawLines(VkCommandBuffer cmd, render::TreeRenderer& renderer) override;
  std::string status() const override;

 private:
  void open(const TreeModel& model);
  void restart();                     // age 0 with every cloud and obstacle of the model as it stands now
  void goToAge(std::uint32_t age);    // back by rewinding, forward by growing
  void apply(const sc::SpaceColonization& edited, const WindowEvent& event);  // the colonizer follows the edit
  bool tryEdit(const WindowEvent& event);  // the panel's edits: false (and a message) when the model refuses
  bool replaceCloud(std::size_t index, const sc::AttractionCloud& cloud);  // likewise, for shape, points and radii
  void save(const std::string& path);        // the edited model as a model file
  void exportMesh(const std::string& path);  // the mesh of the state shown (.obj, .gltf, .glb)
  void rebuildTree(render::TreeRenderer& renderer);
  void rebuildLines();
  render::Bounds workingBounds() const;  // world space, as the tree stands

  sc::SpaceColonization model_;
  std::uint64_t seed_ = 1;
  std::unique_ptr<sc::Colonizer> colonizer_;
  bool growing_ = false;
  int stepSize_ = 200;              // Patrick et al.'s step size: nodes processed per frame while growing
  std::uint32_t highestAge_ = 0;    // the age slider's end: the oldest state reached since the last restart
  bool treeChanged_ = true, linesChanged_ = true;
  bool showPoints_ = true, showWireframes_ = true;
  std::string message_;             // the last refused edit
  std::string pathInput_;           // the panel's file field
  std::string outputPath_ = "out/model.json";  // the panel's save / export field
  std::string fileStatus_;                     // what the last save or export did
  std::vector<std::string> presets_;  // space-colonization presets, for the panel's list

  const vk::VulkanContext* context_ = nullptr;
  std::unique_ptr<render::Forest> forest_;
  vk::Buffer lines_;
  std::uint32_t lineCount_ = 0;
};

}  // namespace arbor::viewer
