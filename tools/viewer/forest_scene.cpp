#include "forest_scene.hpp"

#include <cstdio>

#include <imgui.h>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "tree/build_tree.hpp"
#include "files/tree_file.hpp"
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
  if (event.action == "save") save(event.text);
  else if (event.action == "export") exportMesh(event.text);
  else if (event.action == "regenerate") regenerate_ = true;  // as the panel's button does
  else return false;
  return true;
}

void ForestScene::save(const std::string& path) {
  const TreeModel* model = request_.sources.front().model();
  if (!model) throw InputError(path, "save", request_.labels.front() + " is a skeleton given whole: there is no model to save");
  writeFileAtomically(path, model->toJson());
  std::printf("wrote %s (%s, as edited)\n", path.c_str(), request_.labels.front().c_str());
  std::fflush(stdout);
}

void ForestScene::exportMesh(const std::string& path) {
  // The first tree as the forest grew it (its first seed), whole: every level meshed.
  GrowthOptions growth;
  growth.seed = request_.seed;
  const Skeleton skeleton = request_.sources.front().grow(growth);
  writeTreeFile(path, skeleton, request_.labels.front(), TreeFileOptions{});
  std::printf("wrote %s (%s, seed %llu)\n", path.c_str(), request_.labels.front().c_str(), static_cast<unsigned long long>(request_.seed));
  std::fflush(stdout);
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
  ImGui::Text("the first tree, %s:", request_.labels.front().c_str());
  fileButtons(outputPath_, fileStatus_, [&](const std::string& p) { save(p); }, [&](const std::string& p) { exportMesh(p); });
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
