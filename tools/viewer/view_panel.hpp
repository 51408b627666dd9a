#pragma once
// The viewer's Dear ImGui panel and the state it edits while the viewer runs.
#include <string>
#include <vector>

#include "growth/growth_model.hpp"
#include "tree/tree_source.hpp"
#include "render/forest.hpp"
#include "render/renderer.hpp"

namespace arbor::cli {

// What the panel changes while the viewer runs.
struct ViewState {
  render::RenderSettings settings;
  render::DetailDistances detail;
  float lightAzimuth = 25.0f, lightElevation = 40.0f;
  bool showOverlay = true;
  bool regenerate = false;
  std::vector<float> frameTimes = std::vector<float>(120, 0.0f);
  std::size_t frameIndex = 0;
  std::vector<TreeEstimate> estimates;  // per tree source, redone whenever a slider moves
  std::string refusal;                  // why the trees as set would not be grown ("" when they would)
};

// The estimate of every source and, when one passes the limits, the refusal that stops regeneration.
void updateEstimates(ViewState& state, const std::vector<TreeSource>& sources, const std::vector<std::string>& names);

// Figures (device, frame-time graph, triangles, trees per detail), render settings, and every numeric
// parameter of each tree's growth model (grouped as the model groups them; a skeleton given whole has none)
// with a regenerate button. Between the
// overlay's newFrame and render.
void drawPanel(ViewState& state, const render::ForestFrame& frame, const render::FrameStats& stats, std::vector<TreeSource>& sources,
               const std::vector<std::string>& names, const std::string& device);

}  // namespace arbor::cli
