#pragma once
// The viewer: one frame loop for the window and the offscreen path (frame_target.hpp), the cameras, the panel
// and the scripted events, around a scene that says what is shown: a forest to walk through (forest_scene) or a
// tree growing under the artist's hands (growth_scene).
#include <optional>
#include <string>
#include <vector>

#include "render/forest.hpp"
#include "render/renderer.hpp"
#include "view_script.hpp"

namespace arbor::viewer {

// What the panel changes while the viewer runs, whatever the scene.
struct ViewState {
  render::RenderSettings settings;
  render::DetailDistances detail;
  float lightAzimuth = 25.0f, lightElevation = 40.0f;
  bool showOverlay = true;
  std::vector<float> frameTimes = std::vector<float>(120, 0.0f);
  std::size_t frameIndex = 0;
};

class ViewerScene {
 public:
  virtual ~ViewerScene() = default;
  // Once the device is there: grow what the scene shows and give it to the renderer (progress on stderr).
  virtual void start(const vk::VulkanContext& context, render::TreeRenderer& renderer) = 0;
  // Before the device goes: free everything the scene holds on it.
  virtual void stop() = 0;
  virtual std::string summary() const = 0;  // printed once the scene is up: "3 distinct trees, 40 placed"
  virtual const render::Forest& forest() const = 0;
  // A camera that sees the whole scene, and the stops of a short tour starting there.
  virtual render::Camera overview(float aspect) const = 0;
  virtual std::vector<render::Camera> tour(float aspect) const = 0;
  // Scene events of --events (validated before the device starts); false: not one this scene knows.
  virtual bool handle(const WindowEvent& event) = 0;
  // Between frames: apply what the panel or the events asked for, regrow, upload. The device is idle when
  // replacesGpuData() said so just before (frames run two in flight otherwise).
  virtual bool replacesGpuData() const = 0;
  virtual void update(render::TreeRenderer& renderer) = 0;
  // Inside the panel's window, after the render settings.
  virtual void panel(ViewState& state) = 0;
  // Inside the render pass, after the trees: the scene's own lines.
  virtual void drawLines(VkCommandBuffer cmd, render::TreeRenderer& renderer) = 0;
  // Appended to each scripted frame's log line ("" for none).
  virtual std::string status() const = 0;
};

struct ViewerOptions {
  std::uint32_t width = 1280, height = 720;
  bool offscreen = false;  // even where a display is
  bool fullscreen = false, vsync = true, orbit = false;
  std::vector<render::Camera> path;  // scripted cameras visited over the frames; empty: the scene's tour
  int frames = 0;                    // scripted: this many frames, then exit; 0: interactive (offscreen: the tour)
  int every = 1;                     // scripted: a screenshot every `every` frames and of the last
  std::string out = "out/view";
  std::vector<WindowEvent> events;
  bool overlayInScript = false;
  float step = 0.0f;  // seconds the cameras move per frame (0: the frame's own time)
  std::string device;
  bool validation = false;
  std::optional<render::DetailDistances> detail;  // none: chosen for the device
  bool maxTessGiven = false;                       // else lavapipe's largest factor is lowered
  std::optional<float> anisotropy;                 // the bark's texture filtering; none: chosen for the device
};

// Runs until the window closes (Esc) or the script ends; 0, or kExitFailure on validation errors.
int runViewer(const ViewerOptions& options, ViewState& state, ViewerScene& scene);

}  // namespace arbor::viewer
