#include "forest_scene.hpp"

#include <cstdio>

#include <imgui.h>

#include "view_panel.hpp"

namespace arbor::viewer {

ForestScene::ForestScene(cli::ForestRequest request) : request_(std::move(request)) { updateEstimates(); }

void ForestScene::start(const vk::VulkanContext& context, render::TreeRenderer& renderer) {
  context_ = &context;
  forest_ = cli::growForest(context, request_, "arbor view");
  renderer.setTrees(forest_->gpuTrees());
}

std::string ForestScene::summary() const {
  return std::to_string(forest_->trees().size()) + " distinct trees, " + std::to_string(forest_->placements().size()) + " placed";
}

bool ForestScene::handle(const WindowEvent& event) {
  if (event.action != "regenerate") return false;
  regenerate_ = true;  // as the panel's button does
  return true;
}

void ForestScene::update(render::TreeRenderer& renderer) {
  if (!regenerate_) return;
  regenerate_ = false;
  updateEstimates();  // the panel's button is off past the limits; --events is not
  if (!refusal_.empty()) {
    std::fprintf(stderr, "arbor view: not regenerated, keeping the previous trees: %s\n", refusal_.c_str());
    return;
  }
  try {
    auto grown = cli::growForest(*context_, request_, "arbor view");
    renderer.setTrees(grown->gpuTrees());
    forest_ = std::move(grown);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arbor view: regenerating failed, keeping the previous trees: %s\n", e.what());
  }
}

void ForestScene::panel(ViewState&) {
  bool edited = false;
  for (std::size_t k = 0; k < request_.sources.size(); ++k) {
    if (!ImGui::CollapsingHeader(request_.labels[k].c_str())) continue;
    ImGui::PushID(static_cast<int>(k));
    const TreeEstimate& e = estimates_[k];
    ImGui::Text("about %.3g nodes, %.3g leaves, %.3g quads", e.nodes, e.leaves, e.quads);
    if (TreeModel* model = request_.sources[k].model()) edited |= modelSliders(*model);
    else ImGui::TextWrapped("a skeleton given whole: no parameters to edit");
    ImGui::PopID();
  }
  if (edited) updateEstimates();
  if (refusal_.empty()) {
    if (ImGui::Button("regenerate")) regenerate_ = true;
  } else {
    // Past a limit the trees are not regrown: the viewer would freeze for seconds and then refuse anyway.
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "not regenerated:");
    ImGui::TextWrapped("%s", refusal_.c_str());
  }
}

void ForestScene::updateEstimates() {
  estimates_.clear();
  refusal_.clear();
  for (std::size_t k = 0; k < request_.sources.size(); ++k) {
    estimates_.push_back(request_.sources[k].estimate());
    const std::string excess = estimates_.back().excess(TreeLimits{});
    if (!excess.empty() && refusal_.empty()) refusal_ = request_.labels[k] + ": " + excess;
  }
}

}  // namespace arbor::viewer
