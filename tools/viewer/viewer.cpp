#include "viewer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <GLFW/glfw3.h>

#include "assets.hpp"
#include "commands.hpp"
#include "frame_target.hpp"
#include "render/render_session.hpp"
#include "render_options.hpp"
#include "view_camera.hpp"
#include "view_panel.hpp"
#include "window/overlay.hpp"
#include "window/window.hpp"

namespace arbor::viewer {

namespace {

namespace fs = std::filesystem;

std::string screenshotName(const std::string& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d.png", frame);
  return (fs::path(dir) / name).string();
}

std::string describe(const render::ForestFrame& f) {
  return std::to_string(f.visible) + " trees (detail " + std::to_string(f.perDetail[0]) + "/" + std::to_string(f.perDetail[1]) + "/" +
         std::to_string(f.perDetail[2]) + ", " + std::to_string(f.far) + " far, " + std::to_string(f.culled) + " culled)";
}

// What the options leave open, chosen for the device: lavapipe gets fewer meshed levels and a lower largest
// adaptive factor (it splits tessellated draws by the largest: 15 patches a draw at 64, 226 at 16).
// Lavapipe tessellates the whole mesh of a large tree in seconds, so there the nearest trees already fake their
// deepest level; and it samples anisotropically in software, a third of a single tree's frame at 8.
void applyDeviceDefaults(const ViewerOptions& o, const vk::VulkanContext& context, ViewState& state) {
  state.detail = o.detail.value_or(context.isLavapipe() ? render::DetailDistances{0.0f, 15.0f, 60.0f} : render::DetailDistances{});
  if (!o.maxTessGiven && context.isLavapipe()) state.settings.maxLevel = 16.0f;
}

// The ground fades into the horizon beyond the forest as seen from the eye.
float groundRadius(const render::Forest& forest, const render::Camera& camera) {
  return std::max(100.0f, 2.0f * (forest.radius() + glm::length(glm::vec2(camera.eye))));
}

float aspectOf(VkExtent2D e) { return static_cast<float>(e.width) / static_cast<float>(std::max(1u, e.height)); }

// The walker's input from the keys and the mouse, unless the panel has them.
WalkInput walkInput(window::Window& win, const window::Overlay& overlay) {
  WalkInput in;
  const bool keys = !overlay.wantsKeyboard();
  const auto axis = [&](int plus, int minus) { return keys ? static_cast<float>(win.keyHeld(plus)) - static_cast<float>(win.keyHeld(minus)) : 0.0f; };
  in.forward = axis(GLFW_KEY_W, GLFW_KEY_S);
  in.right = axis(GLFW_KEY_D, GLFW_KEY_A);
  in.up = axis(GLFW_KEY_E, GLFW_KEY_Q);
  in.fast = win.keyHeld(GLFW_KEY_LEFT_SHIFT);
  double dx = 0.0, dy = 0.0;
  win.takeMouseDelta(dx, dy);
  if (win.mouseLookHeld() && !overlay.wantsMouse()) {
    in.lookX = static_cast<float>(dx);
    in.lookY = static_cast<float>(dy);
  }
  in.zoom = overlay.wantsMouse() ? 0.0f : static_cast<float>(win.takeScroll());
  return in;
}

// The window's own events; a script resizes the offscreen picture too.
void applyWindowEvent(const WindowEvent& e, window::Window* win, FrameTarget& target) {
  if (!win) {
    if (e.action == "resize") target.resize({static_cast<std::uint32_t>(e.width), static_cast<std::uint32_t>(e.height)});
    return;  // no window to minimise or make fullscreen
  }
  if (e.action == "resize") win->resize(e.width, e.height);
  if (e.action == "minimise") win->minimise();
  if (e.action == "restore") win->restore();
  if (e.action == "fullscreen") win->toggleFullscreen();
}

}  // namespace

int runViewer(const ViewerOptions& o, ViewState& state, ViewerScene& scene) {
  const bool offscreen = o.offscreen || !window::displayAvailable();
  std::unique_ptr<window::Window> win;
  if (!offscreen) {
    win = std::make_unique<window::Window>("Arbor", static_cast<int>(o.width), static_cast<int>(o.height));
    if (o.fullscreen) win->toggleFullscreen();
  }
  vk::ContextOptions options = cli::vulkanOptions(o.validation, o.device);
  if (win) {
    options.instanceExtensions = window::requiredInstanceExtensions();
    options.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  }
  vk::VulkanContext context(options);
  applyDeviceDefaults(o, context, state);
  const VkSurfaceKHR surface = win ? win->createSurface(context.instance()) : VK_NULL_HANDLE;
  int status = 0;
  {
    const std::unique_ptr<FrameTarget> target = win ? windowTarget(context, *win, surface, o.vsync) : offscreenTarget(context, {o.width, o.height});
    render::TreeRenderer renderer(context, target->renderPass(), VK_SAMPLE_COUNT_1_BIT, cli::treeTextures(o.anisotropy.value_or(0.0f), context));
    // However the loop ends, the scene's buffers go before the device does.
    const std::unique_ptr<ViewerScene, void (*)(ViewerScene*)> stopScene(&scene, [](ViewerScene* sc) { sc->stop(); });
    scene.start(context, renderer);
    std::unique_ptr<window::Overlay> overlay;
    if (win) overlay = std::make_unique<window::Overlay>(context, *win, target->renderPass(), target->imageCount());
    // Offscreen without a script: one picture per stop of the scene's tour.
    const bool tour = offscreen && o.frames <= 0 && o.path.empty();
    const std::vector<render::Camera> tourStops = scene.tour(aspectOf(target->extent()));
    const bool scripted = o.frames > 0 || offscreen;
    const int frames = tour ? static_cast<int>(tourStops.size()) : o.frames;
    const int every = tour ? 1 : o.every;
    state.showOverlay = win && (!scripted || o.overlayInScript);
    ViewCamera view = ViewCamera::lookingAt(scene.overview(aspectOf(target->extent())), o.orbit || scene.forest().placements().size() <= 1);
    if (!view.orbit) view.position.z = std::max(view.position.z, 1.7f);
    if (scripted) fs::create_directories(o.out);
    render::FrameStats stats;
    auto last = std::chrono::steady_clock::now();
    int screenshotCount = 0;
    bool screenshotWanted = false;  // F12 seen, picture not yet taken
    if (offscreen) {
      std::printf("arbor view: no window (%s); rendering %d frames offscreen on %s; %s\n", o.offscreen ? "--offscreen" : "no display", frames,
                  context.deviceDescription().c_str(), scene.summary().c_str());
    } else {
      std::printf("arbor view: %s on %s, %s; %s\n", scripted ? "scripted" : "interactive", context.deviceDescription().c_str(),
                  o.vsync ? "vsync on" : "vsync off", scene.summary().c_str());
    }
    std::fflush(stdout);  // scripts wait for this line
    std::vector<double> frameMs, gpuMs;
    for (int f = 0; !(win && win->shouldClose()) && (!scripted || f < frames); ++f) {
      for (const WindowEvent& e : o.events) {
        if (e.frame != f + 1) continue;
        if (isSceneEvent(e)) scene.handle(e);
        else applyWindowEvent(e, win.get(), *target);
      }
      if (scene.replacesGpuData()) target->waitIdle();  // frames in flight may still draw from what it replaces
      scene.update(renderer);
      if (win) {
        win->pollEvents();
        if (!scripted) win->waitWhileMinimised();
        if (win->shouldClose()) break;
      }
      const VkExtent2D size = win ? win->framebufferSize() : target->extent();
      if (size.width == 0 || size.height == 0) continue;  // minimised in a script: nothing to draw into
      const auto now = std::chrono::steady_clock::now();
      const float elapsed = std::chrono::duration<float>(now - last).count();
      // A slow frame must not throw the walker far; --step makes walks independent of the frame time.
      const float seconds = o.step > 0.0f ? o.step : std::min(0.25f, elapsed);
      last = now;
      // The wind's clock: the frame time, or a 30th of a second per frame in scripts (repeatable pictures).
      state.settings.windSeconds += scripted && o.step <= 0.0f ? 1.0 / 30.0 : static_cast<double>(seconds);
      bool screenshot = scripted && ((f + 1) % every == 0 || f + 1 == frames);
      const render::Forest& forest = scene.forest();
      if (!scripted) {
        if (win->keyPressed(GLFW_KEY_ESCAPE)) break;
        if (win->keyPressed(GLFW_KEY_F1)) state.showOverlay = !state.showOverlay;
        if (win->keyPressed(GLFW_KEY_F11)) win->toggleFullscreen();
        if (win->keyPressed(GLFW_KEY_TAB)) view = ViewCamera::lookingAt(view.camera(), !view.orbit);
        // A click shorter than a frame reaches the panel as a press now and a release next frame (window/overlay.cpp):
        // F12 with it waits for the frame that shows what the click did.
        if (win->keyPressed(GLFW_KEY_F12)) screenshotWanted = true;
        screenshot = screenshotWanted && !(state.showOverlay && win->clickedWithinFrame());
        view.update(walkInput(*win, *overlay), seconds, forest.radius() + forest.trees().front().crownRadius);
      }
      if (size.width != target->extent().width || size.height != target->extent().height) target->resize(size);
      const float aspect = aspectOf(target->extent());
      const render::Camera camera = tour ? tourStops[static_cast<std::size_t>(f)]
                                    : scripted ? cameraOnPath(o.path.empty() ? scene.tour(aspect) : o.path, f, frames)
                                               : view.camera();
      state.settings.groundRadius = groundRadius(forest, camera);
      const render::ForestFrame visible = forest.frame(camera, aspect, state.detail);
      if (state.showOverlay) {
        overlay->newFrame();
        drawPanel(state, visible, stats, context.deviceDescription(), scene);
      }
      const bool shown = target->draw([&](VkCommandBuffer cmd) { renderer.beginFrame(cmd, camera, target->extent(), state.settings, visible.instances); },
                                      [&](VkCommandBuffer cmd) {
                                        renderer.draw(cmd, target->extent(), state.settings, visible.instances);
                                        scene.drawLines(cmd, renderer);
                                        if (state.showOverlay) overlay->render(cmd);
                                      },
                                      screenshot);
      if (!shown) {
        if (state.showOverlay) overlay->discardFrame();
        continue;
      }
      stats = target->lastFrameCompleted() ? renderer.stats() : renderer.completedStats();
      const float ms = elapsed * 1000.0f;
      if (f > 0) frameMs.push_back(ms);
      if (f > 0 && stats.hasTime) gpuMs.push_back(stats.gpuMilliseconds);
      state.frameTimes[state.frameIndex] = ms;
      state.frameIndex = (state.frameIndex + 1) % state.frameTimes.size();
      if (screenshot) {
        screenshotWanted = false;
        const std::string name = screenshotName(o.out, scripted ? f + 1 : ++screenshotCount);
        try {
          fs::create_directories(o.out);
          writePng(name, target->screenshot());
          std::printf("wrote %s\n", name.c_str());
        } catch (const std::exception& e) {
          if (scripted) throw;
          std::fprintf(stderr, "arbor view: the screenshot was not written: %s\n", e.what());  // the walk goes on
        }
        std::fflush(stdout);
      }
      if (scripted) {
        const std::string more = scene.status();
        std::fprintf(stderr, "arbor view: frame %d/%d: %s, %llu triangles%s%s\n", f + 1, frames, describe(visible).c_str(),
                     static_cast<unsigned long long>(stats.triangles), more.empty() ? "" : "; ", more.c_str());
      }
    }
    target->waitIdle();
    if (!frameMs.empty()) {
      // The pace with two frames in flight (window or offscreen): the slower of recording and drawing.
      std::sort(frameMs.begin(), frameMs.end());
      char gpu[64] = "";
      if (!gpuMs.empty()) {
        std::sort(gpuMs.begin(), gpuMs.end());
        std::snprintf(gpu, sizeof gpu, ", the trees' GPU time median %.2f ms", gpuMs[gpuMs.size() / 2]);
      }
      std::printf("arbor view: %zu frames at %ux%u, median %.1f ms (%.1f frames/s), slowest %.1f ms%s\n", frameMs.size() + 1,
                  target->extent().width, target->extent().height, frameMs[frameMs.size() / 2], 1000.0 / frameMs[frameMs.size() / 2],
                  frameMs.back(), gpu);
    }
  }
  if (cli::reportValidationErrors(context)) status = cli::kExitFailure;
  if (surface) vkDestroySurfaceKHR(context.instance(), surface, nullptr);
  return status;
}

}  // namespace arbor::viewer
