#include "view_panel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <imgui.h>

#include "species/species_fields.hpp"

namespace arbor::cli {

void drawPanel(ViewState& state, const render::ForestFrame& frame, const render::FrameStats& stats, std::vector<SpeciesParams>& params,
               const std::vector<std::string>& names, const std::string& device) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 540), ImGuiCond_FirstUseEver);
  ImGui::Begin("Arbor");
  ImGui::Text("%s", device.c_str());
  const float last = state.frameTimes[(state.frameIndex + state.frameTimes.size() - 1) % state.frameTimes.size()];
  ImGui::Text("frame %.2f ms (%.0f fps)", static_cast<double>(last), last > 0.0f ? 1000.0 / static_cast<double>(last) : 0.0);
  ImGui::PlotLines("ms", state.frameTimes.data(), static_cast<int>(state.frameTimes.size()), static_cast<int>(state.frameIndex), nullptr,
                   0.0f, FLT_MAX, ImVec2(0, 60));
  ImGui::Text("triangles %llu, %u trees drawn, %u culled", static_cast<unsigned long long>(stats.triangles), frame.visible, frame.culled);
  ImGui::Text("detail: %u full, %u one level faked, %u two (%u far)", frame.perDetail[0], frame.perDetail[1], frame.perDetail[2],
              frame.far);
  render::RenderSettings& s = state.settings;
  int mode = static_cast<int>(s.mode);
  ImGui::Combo("mode", &mode, "flat\0pn\0acc\0");
  s.mode = static_cast<render::RenderMode>(mode);
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
  ImGui::SliderFloat("sun azimuth", &state.lightAzimuth, -180.0f, 180.0f);
  ImGui::SliderFloat("sun elevation", &state.lightElevation, -10.0f, 90.0f);
  s.lightDirection = render::sunDirection(state.lightAzimuth, state.lightElevation);
  if (state.estimates.size() != params.size()) updateEstimates(state, params, names);
  bool edited = false;
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (!ImGui::CollapsingHeader(names[k].c_str())) continue;
    ImGui::PushID(static_cast<int>(k));
    const TreeEstimate& e = state.estimates[k];
    ImGui::Text("about %.3g nodes, %.3g leaves, %.3g quads", e.nodes, e.leaves, e.quads);
    for (const TreeField& f : treeFields()) {
      if (f.real) {
        auto v = static_cast<float>(params[k].*f.real);
        if (ImGui::SliderFloat(f.key, &v, static_cast<float>(f.min), static_cast<float>(std::min(f.max, 1e4)))) {
          params[k].*f.real = v;
          edited = true;
        }
      } else if (f.integer && f.type == FieldType::Integer) {
        int v = params[k].*f.integer;
        if (ImGui::SliderInt(f.key, &v, static_cast<int>(f.min), static_cast<int>(std::min(f.max, 1e4)))) {
          params[k].*f.integer = v;
          edited = true;
        }
      }
    }
    // Levels beyond those given reuse the deepest entry; Levels may grow up to the entries there are.
    params[k].levels = std::min(params[k].levels, static_cast<int>(params[k].stemLevels.size()));
    for (std::size_t l = 0; l < params[k].stemLevels.size(); ++l) {
      if (!ImGui::TreeNode(reinterpret_cast<void*>(l + 1), "level %zu", l)) continue;
      StemLevelParams& lp = params[k].stemLevels[l];
      for (const LevelField& f : levelFields()) {
        if (f.real) {
          auto v = static_cast<float>(lp.*f.real);
          const float lo = l == 0 && f.real == &StemLevelParams::branches ? 1.0f : static_cast<float>(f.min);
          const float hi = l == 0 && f.real == &StemLevelParams::branches ? 64.0f : static_cast<float>(f.max);
          if (ImGui::SliderFloat(f.key, &v, lo, hi)) {
            lp.*f.real = l == 0 && f.real == &StemLevelParams::branches ? std::round(v) : v;
            edited = true;
          }
        } else if (f.integer) {
          int v = lp.*f.integer;
          if (ImGui::SliderInt(f.key, &v, static_cast<int>(f.min), static_cast<int>(f.max))) {
            lp.*f.integer = v;
            edited = true;
          }
        }
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (edited) updateEstimates(state, params, names);
  if (state.refusal.empty()) {
    if (ImGui::Button("regenerate")) state.regenerate = true;
  } else {
    // Past a limit the trees are not regrown: the viewer would freeze for seconds and then refuse anyway.
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "not regenerated:");
    ImGui::TextWrapped("%s", state.refusal.c_str());
  }
  ImGui::Text("WASD move, right mouse look, Shift fast, Q/E down/up");
  ImGui::Text("Tab orbit/walk, F11 fullscreen, F12 screenshot, F1 panel");
  ImGui::End();
}

void updateEstimates(ViewState& state, const std::vector<SpeciesParams>& params, const std::vector<std::string>& names) {
  state.estimates.clear();
  state.refusal.clear();
  for (std::size_t k = 0; k < params.size(); ++k) {
    state.estimates.push_back(estimateTree(params[k]));
    const std::string excess = state.estimates.back().excess(TreeLimits{});
    if (!excess.empty() && state.refusal.empty()) state.refusal = names[k] + ": " + excess;
  }
}

}  // namespace arbor::cli
