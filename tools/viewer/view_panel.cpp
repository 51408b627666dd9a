#include "view_panel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <imgui.h>

#include "cli_values.hpp"
#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "files/tree_file.hpp"

namespace arbor::viewer {

namespace {

// One parameter as a slider over its documented range (very wide ranges stop at 1e4); true when moved.
bool parameterSlider(TreeModel& model, std::size_t index, const ModelParameter& p) {
  const float hi = static_cast<float>(std::min(p.max, 1e4)), lo = static_cast<float>(p.min);
  ImGui::PushID(static_cast<int>(index));
  bool moved = false;
  if (p.integer) {
    int v = static_cast<int>(std::lround(model.value(index)));
    moved = ImGui::SliderInt(p.key.c_str(), &v, static_cast<int>(lo), static_cast<int>(hi));
    if (moved) model.setValue(index, v);
  } else {
    auto v = static_cast<float>(model.value(index));
    moved = ImGui::SliderFloat(p.key.c_str(), &v, lo, hi);
    if (moved) model.setValue(index, v);
  }
  ImGui::PopID();
  return moved;
}

}  // namespace

bool modelSliders(TreeModel& model) {
  const std::vector<ModelParameter> parameters = model.parameters();
  bool edited = false;
  std::size_t i = 0;
  while (i < parameters.size()) {
    // A run of parameters with one group: the tree's own in the open, each other group under its heading.
    const std::string& group = parameters[i].group;
    std::size_t end = i;
    while (end < parameters.size() && parameters[end].group == group) ++end;
    const bool open = group.empty() || ImGui::TreeNode(group.c_str());
    for (; open && i < end; ++i) edited |= parameterSlider(model, i, parameters[i]);
    if (open && !group.empty()) ImGui::TreePop();
    i = end;
  }
  return edited;
}

void fileButtons(std::string& path, std::string& status, const std::function<void(const std::string&)>& save,
                 const std::function<void(const std::string&)>& exportMesh) {
  char text[512];
  std::snprintf(text, sizeof text, "%s", path.c_str());
  if (ImGui::InputText("save to", text, sizeof text)) path = text;
  const auto attempt = [&](bool model) {
    try {
      cli::requireOutputFile(path, "file");
      if (model && !endsWith(path, ".json")) throw InputError(path, "file", "a model is saved as .json");
      if (!model && !isMeshFile(path)) throw InputError(path, "file", "a mesh is exported as .obj, .gltf or .glb");
      (model ? save : exportMesh)(path);
      status = "wrote " + path;
    } catch (const std::exception& e) {
      status = e.what();
    }
  };
  if (ImGui::Button("save model (.json)")) attempt(true);
  ImGui::SameLine();
  if (ImGui::Button("export mesh (.obj .gltf .glb)")) attempt(false);
  if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
}

void drawPanel(ViewState& state, const render::ForestFrame& frame, const render::FrameStats& stats, const std::string& device,
               ViewerScene& scene) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 640), ImGuiCond_FirstUseEver);
  ImGui::Begin("Arbor");
  ImGui::Text("%s", device.c_str());
  const float last = state.frameTimes[(state.frameIndex + state.frameTimes.size() - 1) % state.frameTimes.size()];
  ImGui::Text("frame %.2f ms (%.0f fps)", static_cast<double>(last), last > 0.0f ? 1000.0 / static_cast<double>(last) : 0.0);
  ImGui::PlotLines("ms", state.frameTimes.data(), static_cast<int>(state.frameTimes.size()), static_cast<int>(state.frameIndex), nullptr,
                   0.0f, FLT_MAX, ImVec2(0, 60));
  ImGui::Text("triangles %llu, %u trees drawn, %u culled", static_cast<unsigned long long>(stats.triangles), frame.visible, frame.culled);
  ImGui::Text("detail: %u full, %u one level faked, %u two (%u far)", frame.perDetail[0], frame.perDetail[1], frame.perDetail[2],
              frame.far);
  scene.panel(state);  // first: what the scene is about (the modeller's controls, the forest's models)
  if (ImGui::CollapsingHeader("rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
    render::RenderSettings& s = state.settings;
    if (ImGui::BeginCombo("mode", render::renderModeName(s.mode))) {
      for (const render::RenderModeInfo& m : render::renderModes()) {
        if (ImGui::Selectable(m.name, m.mode == s.mode)) s.mode = m.mode;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", m.summary);
      }
      ImGui::EndCombo();
    }
    bool adaptive = s.adaptivePixels > 0.0f;
    ImGui::Checkbox("adaptive", &adaptive);
    if (adaptive) {
      if (s.adaptivePixels <= 0.0f) s.adaptivePixels = 8.0f;
      ImGui::SliderFloat("edge pixels", &s.adaptivePixels, 1.0f, 64.0f);
    } else {
      s.adaptivePixels = 0.0f;
      ImGui::SliderFloat("factor", &s.tessLevel, 1.0f, 64.0f);
    }
    ImGui::SliderFloat("displacement", &s.displacement, 0.0f, 1.0f);
    ImGui::Checkbox("wireframe", &s.wireframe);
    ImGui::Checkbox("leaves", &s.leaves);
    ImGui::SliderFloat("leaf distance", &s.leafLodDistance, 0.0f, 200.0f);
    int shadow = static_cast<int>(s.shadowLeaves);
    ImGui::SliderInt("shadow leaves", &shadow, 0, 500);
    s.shadowLeaves = static_cast<std::uint32_t>(shadow);
    ImGui::SliderFloat("full mesh within (m)", &state.detail.full, 0.0f, 300.0f);
    ImGui::SliderFloat("one level faked within (m)", &state.detail.reduced, 0.0f, 600.0f);
    ImGui::SliderFloat("far beyond (m)", &state.detail.far, 0.0f, 1000.0f);
    // Wind (docs/wind.md): the control cage posed every frame, leaves and fake branches following.
    float wind[3] = {static_cast<float>(s.wind.strength), static_cast<float>(s.wind.azimuth), static_cast<float>(s.wind.gustFrequency)};
    ImGui::SliderFloat("wind", &wind[0], 0.0f, 3.0f);
    ImGui::SliderFloat("wind towards (deg)", &wind[1], -180.0f, 180.0f);
    ImGui::SliderFloat("gusts per second", &wind[2], 0.05f, 2.0f);
    s.wind.strength = wind[0];
    s.wind.azimuth = wind[1];
    s.wind.gustFrequency = std::max(0.05f, wind[2]);
    ImGui::SliderFloat("sun azimuth", &state.lightAzimuth, -180.0f, 180.0f);
    ImGui::SliderFloat("sun elevation", &state.lightElevation, -10.0f, 90.0f);
    s.lightDirection = render::sunDirection(state.lightAzimuth, state.lightElevation);
  }
  ImGui::Separator();
  ImGui::Text("WASD move, right mouse look, Shift fast, Q/E down/up");
  ImGui::Text("Tab orbit/walk, F11 fullscreen, F12 screenshot, F1 panel");
  ImGui::End();
}

}  // namespace arbor::viewer
