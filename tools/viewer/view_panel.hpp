#pragma once
// The viewer's Dear ImGui panel: what every scene shows (figures, render settings, keys) around the scene's own
// part, and the sliders of a growth model's parameters.
#include <string>

#include "growth/growth_model.hpp"
#include "viewer.hpp"

namespace arbor::viewer {

// Figures (device, frame-time graph, triangles, trees per detail), render settings, the scene's part, the keys.
// Between the overlay's newFrame and render.
void drawPanel(ViewState& state, const render::ForestFrame& frame, const render::FrameStats& stats, const std::string& device,
               ViewerScene& scene);

// Every numeric parameter of the model as a slider over its documented range, grouped as the model groups
// them; true when one moved.
bool modelSliders(TreeModel& model);

}  // namespace arbor::viewer
