#pragma once
// The viewer's Dear ImGui panel: what every scene shows (figures, render settings, keys) around the scene's own
// part, and the sliders of a growth model's parameters.
#include <functional>
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

// A file field with "save model" (.json) and "export mesh" (.obj, .gltf, .glb) buttons; each checks the path
// first (its folder exists and is writable, the extension fits) and leaves what happened in `status`.
void fileButtons(std::string& path, std::string& status, const std::function<void(const std::string&)>& save,
                 const std::function<void(const std::string&)>& exportMesh);

}  // namespace arbor::viewer
