// arbor view: the real-time walkthrough over a generated forest (GLFW window, Vulkan swapchain, ImGui
// overlay); scripted with a camera path for tests and demos; offscreen to PNG files where no display is.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <GLFW/glfw3.h>

#include "assets.hpp"
#include "grow_forest.hpp"
#include "bench_support.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "image/png_io.hpp"
#include "render/forest.hpp"
#include "render/render_session.hpp"
#include "render_options.hpp"
#include "view_camera.hpp"
#include "view_script.hpp"
#include "view_panel.hpp"
#include "window/overlay.hpp"
#include "window/swapchain.hpp"
#include "window/window.hpp"

namespace arbor::cli {

namespace {

namespace fs = std::filesystem;

struct ViewOptions {
  AngleChoice angles = AngleChoice::File;
  std::vector<std::string> species{"black-tupelo"};
  std::uint32_t forest = 1;
  std::uint32_t seeds = 2;
  std::uint64_t seed = 1;
  std::string size = "1280x720";
  bool noVsync = false;
  bool fullscreen = false;
  bool orbit = false;
  std::string mode = "acc";
  float tess = 0.0f;
  float adaptive = 8.0f;
  float maxTess = 0.0f;
  float displace = 0.0f;
  bool noLeaves = false;
  float leafLod = 60.0f;
  int shadowLeaves = 0;
  std::string detail;  // "FULL,REDUCED" metres; empty: by device
  std::string light = "25,40";
  std::string cameraPath;
  int frames = 0;
  int screenshotEvery = 0;
  std::string out = "out/view";
  std::string events;
  bool offscreen = false;
  bool overlayInScript = false;
  float step = 0.0f;  // seconds the cameras move per frame (0: the frame's own time)
  std::string device;
  bool validation = false;
};

// What the overlay changes while the viewer runs.
ForestRequest forestRequest(const ViewOptions& o, const std::vector<TreeSource>& sources) {
  return ForestRequest{o.species, sources, o.forest, o.seeds, o.seed};
}

std::string screenshotName(const std::string& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d.png", frame);
  return (fs::path(dir) / name).string();
}

std::string describe(const render::ForestFrame& f) {
  return std::to_string(f.visible) + " trees (detail " + std::to_string(f.perDetail[0]) + "/" + std::to_string(f.perDetail[1]) + "/" +
         std::to_string(f.perDetail[2]) + ", " + std::to_string(f.far) + " far, " + std::to_string(f.culled) + " culled)";
}

// "FULL,REDUCED[,FAR]" in metres; empty: none given (the device decides).
std::optional<render::DetailDistances> parseDetail(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::vector<float> v = parseNumbers(text, "--detail", 0.0f, 100000.0f);
  if (v.size() < 2 || v.size() > 3 || v[1] < v[0] || (v.size() == 3 && v[2] < v[1])) {
    throw InputError(text, "--detail", "expected FULL,REDUCED[,FAR] metres, each at least the one before, e.g. 40,150,400");
  }
  return render::DetailDistances{v[0], v[1], v.size() == 3 ? v[2] : render::DetailDistances{}.far};
}

// Everything the options say, read once before anything is grown, so that bad input fails early.
struct ViewPlan {
  std::uint32_t width = 0, height = 0;
  std::vector<TreeSource> sources;
  std::vector<render::Camera> path;  // empty: the forest's tour
  std::vector<WindowEvent> events;
  std::optional<render::DetailDistances> detail;
  int frames = 0, every = 1;  // scripted runs: frames (0: interactive), a screenshot every `every`
};

// What the options leave open, chosen for the device: lavapipe gets fewer meshed levels and a lower largest
// adaptive factor (it splits tessellated draws by the largest: 15 patches a draw at 64, 226 at 16).
// Lavapipe tessellates the whole mesh of a large tree in seconds, so there the nearest trees already fake their
// deepest level.
void applyDeviceDefaults(const ViewOptions& o, const ViewPlan& plan, const vk::VulkanContext& context, ViewState& state) {
  state.detail = plan.detail.value_or(context.isLavapipe() ? render::DetailDistances{0.0f, 15.0f, 60.0f} : render::DetailDistances{});
  if (o.maxTess <= 0.0f && context.isLavapipe()) state.settings.maxLevel = 16.0f;
}

// The ground fades into the horizon beyond the forest as seen from the eye.
float groundRadius(const render::Forest& forest, const render::Camera& camera) {
  return std::max(100.0f, 2.0f * (forest.radius() + glm::length(glm::vec2(camera.eye))));
}

void beginPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent) {
  std::array<VkClearValue, 2> clear{};
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = static_cast<std::uint32_t>(clear.size());
  begin.pClearValues = clear.data();
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
}

// No display (or --offscreen): the same scene through the offscreen target, every screenshot a PNG.
int runOffscreen(const ViewOptions& o, const ViewPlan& plan, ViewState& state) {
  const std::vector<render::Camera>& path = plan.path;
  const bool tour = plan.frames <= 0 && path.empty();
  int frames = std::max(plan.frames, 1);
  const int every = plan.frames > 0 ? plan.every : 1;
  const std::uint32_t width = plan.width, height = plan.height;
  vk::VulkanContext context(vulkanOptions(o.validation, o.device));
  applyDeviceDefaults(o, plan, context, state);
  render::RenderSession session(context, width, height, VK_SAMPLE_COUNT_1_BIT, render::loadTreeTextures(assetDirectory()));
  const std::unique_ptr<render::Forest> grown = growForest(context, forestRequest(o, plan.sources), "arbor view");
  const render::Forest& forest = *grown;
  session.renderer().setTrees(forest.gpuTrees());
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const std::vector<render::Camera> keys = path.empty() ? forest.tour(aspect) : path;
  if (path.empty() && frames <= 1) frames = static_cast<int>(keys.size());  // one picture per stop of the tour
  fs::create_directories(o.out);
  std::vector<std::string> written;
  for (int f = 0; f < frames; ++f) {
    const render::Camera camera = cameraOnPath(keys, f, frames);
    state.settings.groundRadius = groundRadius(forest, camera);
    const render::ForestFrame visible = forest.frame(camera, aspect, state.detail);
    const render::FrameResult r = session.render(camera, state.settings, visible.instances);
    std::fprintf(stderr, "arbor view: frame %d/%d: %s, %llu triangles, %.1f ms\n", f + 1, frames, describe(visible).c_str(),
                 static_cast<unsigned long long>(r.gpu.triangles), r.cpuMilliseconds);
    if (tour || (f + 1) % every == 0 || f + 1 == frames) {
      written.push_back(screenshotName(o.out, f + 1));
      writePng(written.back(), session.image());
    }
  }
  if (reportValidationErrors(context)) return kExitFailure;
  std::printf("arbor view: no window (%s); rendered %d frames of the same scene offscreen on %s\n",
              o.offscreen ? "--offscreen" : "no display", frames, context.deviceDescription().c_str());
  for (const std::string& w : written) std::printf("wrote %s\n", w.c_str());
  return 0;
}

int runWindow(const ViewOptions& o, ViewPlan& plan, ViewState& state) {
  const std::vector<render::Camera>& path = plan.path;
  std::vector<TreeSource>& sources = plan.sources;  // the panel edits their models
  const int frames = plan.frames, every = plan.every;
  window::Window win("Arbor", static_cast<int>(plan.width), static_cast<int>(plan.height));
  if (o.fullscreen) win.toggleFullscreen();
  vk::ContextOptions options = vulkanOptions(o.validation, o.device);
  options.instanceExtensions = window::requiredInstanceExtensions();
  options.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  vk::VulkanContext context(options);
  applyDeviceDefaults(o, plan, context, state);
  const VkSurfaceKHR surface = win.createSurface(context.instance());
  int status = 0;
  {
    window::Swapchain swapchain(context, surface, win.framebufferSize(), !o.noVsync);
    render::TreeRenderer renderer(context, swapchain.renderPass(), VK_SAMPLE_COUNT_1_BIT, render::loadTreeTextures(assetDirectory()));
    auto forest = growForest(context, forestRequest(o, sources), "arbor view");
    renderer.setTrees(forest->gpuTrees());
    window::Overlay overlay(context, win.handle(), swapchain.renderPass(), swapchain.imageCount());
    const bool scripted = frames > 0;
    state.showOverlay = !scripted || o.overlayInScript;
    const auto aspectOf = [](VkExtent2D e) { return static_cast<float>(e.width) / static_cast<float>(std::max(1u, e.height)); };
    ViewCamera view = ViewCamera::lookingAt(forest->overview(aspectOf(swapchain.extent())), o.orbit || o.forest <= 1);
    if (!view.orbit) view.position.z = std::max(view.position.z, 1.7f);
    if (scripted) fs::create_directories(o.out);
    render::FrameStats stats;
    render::ForestFrame visible;
    auto last = std::chrono::steady_clock::now();
    int screenshotCount = 0;
    std::printf("arbor view: %s on %s, %s; %zu distinct trees, %zu placed\n", scripted ? "scripted" : "interactive",
                context.deviceDescription().c_str(), o.noVsync ? "vsync off" : "vsync on", forest->trees().size(), forest->placements().size());
    std::fflush(stdout);  // scripts wait for this line
    const std::vector<WindowEvent>& events = plan.events;
    std::vector<double> frameMs;
    for (int f = 0; !win.shouldClose() && (!scripted || f < frames); ++f) {
      for (const WindowEvent& e : events) {
        if (e.frame != f + 1) continue;
        if (e.action == "resize") win.resize(e.width, e.height);
        if (e.action == "minimise") win.minimise();
        if (e.action == "restore") win.restore();
        if (e.action == "fullscreen") win.toggleFullscreen();
        if (e.action == "regenerate") state.regenerate = true;  // as the overlay's button does
      }
      win.pollEvents();
      if (!scripted) win.waitWhileMinimised();
      if (win.shouldClose()) break;
      const VkExtent2D size = win.framebufferSize();
      if (size.width == 0 || size.height == 0) continue;  // minimised in a script: nothing to draw into
      const auto now = std::chrono::steady_clock::now();
      const float elapsed = std::chrono::duration<float>(now - last).count();
      // A slow frame must not throw the walker far; --step makes walks independent of the frame time.
      const float seconds = o.step > 0.0f ? o.step : std::min(0.25f, elapsed);
      last = now;
      bool screenshot = scripted && ((f + 1) % every == 0 || f + 1 == frames);
      if (!scripted) {
        if (win.keyPressed(GLFW_KEY_ESCAPE)) break;
        if (win.keyPressed(GLFW_KEY_F1)) state.showOverlay = !state.showOverlay;
        if (win.keyPressed(GLFW_KEY_F11)) win.toggleFullscreen();
        if (win.keyPressed(GLFW_KEY_TAB)) {
          const render::Camera c = view.camera();
          view = ViewCamera::lookingAt(c, !view.orbit);
        }
        screenshot = win.keyPressed(GLFW_KEY_F12);
        WalkInput in;
        const bool keys = !overlay.wantsKeyboard();
        in.forward = keys ? static_cast<float>(win.keyHeld(GLFW_KEY_W)) - static_cast<float>(win.keyHeld(GLFW_KEY_S)) : 0.0f;
        in.right = keys ? static_cast<float>(win.keyHeld(GLFW_KEY_D)) - static_cast<float>(win.keyHeld(GLFW_KEY_A)) : 0.0f;
        in.up = keys ? static_cast<float>(win.keyHeld(GLFW_KEY_E)) - static_cast<float>(win.keyHeld(GLFW_KEY_Q)) : 0.0f;
        in.fast = win.keyHeld(GLFW_KEY_LEFT_SHIFT);
        double dx = 0.0, dy = 0.0;
        win.takeMouseDelta(dx, dy);
        if (win.mouseLookHeld() && !overlay.wantsMouse()) {
          in.lookX = static_cast<float>(dx);
          in.lookY = static_cast<float>(dy);
        }
        in.zoom = overlay.wantsMouse() ? 0.0f : static_cast<float>(win.takeScroll());
        view.update(in, seconds, forest->radius() + forest->trees().front().crownRadius);
      }
      if (size.width != swapchain.extent().width || size.height != swapchain.extent().height) swapchain.recreate(size);
      const render::Camera camera = scripted ? cameraOnPath(path.empty() ? forest->tour(aspectOf(swapchain.extent())) : path, f, frames)
                                             : view.camera();
      state.settings.groundRadius = groundRadius(*forest, camera);
      visible = forest->frame(camera, aspectOf(swapchain.extent()), state.detail);
      if (state.showOverlay) {
        overlay.newFrame();
        drawPanel(state, visible, stats, sources, o.species, context.deviceDescription());
      }
      VkCommandBuffer cmd = VK_NULL_HANDLE;
      if (!swapchain.beginFrame(cmd)) {
        swapchain.recreate(win.framebufferSize());
        if (state.showOverlay) overlay.discardFrame();
        continue;
      }
      renderer.beginFrame(cmd, camera, swapchain.extent(), state.settings);
      beginPass(cmd, swapchain.renderPass(), swapchain.framebuffer(), swapchain.extent());
      renderer.draw(cmd, swapchain.extent(), state.settings, visible.instances);
      if (state.showOverlay) overlay.render(cmd);
      vkCmdEndRenderPass(cmd);
      if (screenshot) swapchain.recordScreenshot(cmd);
      const bool current = swapchain.endFrame();
      stats = renderer.stats();
      const float ms = elapsed * 1000.0f;
      if (f > 0) frameMs.push_back(ms);
      state.frameTimes[state.frameIndex] = ms;
      state.frameIndex = (state.frameIndex + 1) % state.frameTimes.size();
      if (screenshot) {
        const std::string name = screenshotName(o.out, scripted ? f + 1 : ++screenshotCount);
        try {
          fs::create_directories(o.out);
          writePng(name, swapchain.screenshot());
          std::printf("wrote %s\n", name.c_str());
        } catch (const std::exception& e) {
          if (scripted) throw;
          std::fprintf(stderr, "arbor view: the screenshot was not written: %s\n", e.what());  // the walk goes on
        }
        std::fflush(stdout);
      }
      if (scripted) {
        std::fprintf(stderr, "arbor view: frame %d/%d: %s, %llu triangles\n", f + 1, frames, describe(visible).c_str(),
                     static_cast<unsigned long long>(stats.triangles));
      }
      if (!current) swapchain.recreate(win.framebufferSize());
      if (state.regenerate) {
        state.regenerate = false;
        updateEstimates(state, sources, o.species);  // the panel's button is off past the limits; --events is not
        if (!state.refusal.empty()) {
          std::fprintf(stderr, "arbor view: not regenerated, keeping the previous trees: %s\n", state.refusal.c_str());
          continue;
        }
        swapchain.waitIdle();
        try {
          auto grown = growForest(context, forestRequest(o, sources), "arbor view");
          renderer.setTrees(grown->gpuTrees());
          forest = std::move(grown);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "arbor view: regenerating failed, keeping the previous trees: %s\n", e.what());
        }
      }
    }
    swapchain.waitIdle();
    if (!frameMs.empty()) {
      std::sort(frameMs.begin(), frameMs.end());
      std::printf("arbor view: %zu frames at %ux%u, median %.1f ms (%.1f frames/s), slowest %.1f ms\n", frameMs.size() + 1,
                  swapchain.extent().width, swapchain.extent().height, frameMs[frameMs.size() / 2], 1000.0 / frameMs[frameMs.size() / 2],
                  frameMs.back());
    }
    if (reportValidationErrors(context)) status = kExitFailure;
  }
  vkDestroySurfaceKHR(context.instance(), surface, nullptr);
  return status;
}

int runView(const ViewOptions& o) {
  ViewState state;
  render::RenderSettings& s = state.settings;
  s.mode = parseMode(o.mode);
  s.tessLevel = o.tess > 0.0f ? o.tess : 8.0f;
  s.adaptivePixels = o.tess > 0.0f ? 0.0f : o.adaptive;
  if (o.maxTess > 0.0f) s.maxLevel = o.maxTess;
  s.displacement = o.displace;
  s.leaves = !o.noLeaves;
  s.impostors = true;  // only the reduced details have fake branches
  s.leafLodDistance = o.leafLod;
  s.shadowLeaves = static_cast<std::uint32_t>(o.shadowLeaves);
  const glm::vec2 sun = parseSunAngles(o.light);
  state.lightAzimuth = sun.x;
  state.lightElevation = sun.y;
  s.lightDirection = render::sunDirection(sun.x, sun.y);
  ViewPlan plan;
  parseSize(o.size, plan.width, plan.height);
  plan.detail = parseDetail(o.detail);
  plan.events = parseEvents(o.events);
  for (const std::string& name : o.species) plan.sources.push_back(loadTreeArgument(name, nullptr, o.angles));
  if (!o.cameraPath.empty()) plan.path = readCameraPath(o.cameraPath);
  // Scripted: a camera path or a frame count; without a display the scene goes to PNG files instead.
  const bool scripted = !o.cameraPath.empty() || o.frames > 0;
  const bool offscreen = o.offscreen || !window::displayAvailable();
  if (scripted || offscreen) requireOutputFolder(o.out);
  plan.frames = o.frames > 0 ? o.frames : (scripted ? 60 : 0);
  plan.every = o.screenshotEvery > 0 ? o.screenshotEvery : std::max(1, plan.frames);
  if (offscreen) return runOffscreen(o, plan, state);
  return runWindow(o, plan, state);
}

}  // namespace

void addViewCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Walk through a generated forest in a window (Vulkan); offscreen PNGs where no display is.");
  cmd->add_option("species", o->species, "Presets, or model, skeleton or graph files (default: black-tupelo)");
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--forest", o->forest, "Trees to place (1: one tree, orbit camera)")->check(Whole(1, 5000))->capture_default_str();
  cmd->add_option("--seeds", o->seeds, "Distinct seeds per species (each grown once, then instanced)")->check(Whole(1, 16))->capture_default_str();
  cmd->add_option("--seed", o->seed, "First seed; also places the trees")->check(Seed())->capture_default_str();
  cmd->add_option("--size", o->size, "Window (or picture) size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_flag("--no-vsync", o->noVsync, "Present without waiting for vertical blank (mailbox or immediate)");
  cmd->add_flag("--fullscreen", o->fullscreen, "Start fullscreen (F11 toggles)");
  cmd->add_flag("--orbit", o->orbit, "Start with the orbit camera (Tab toggles)");
  cmd->add_option("--mode", o->mode, "flat, pn, acc")->capture_default_str();
  cmd->add_option("--tess", o->tess, "Uniform tessellation factor (default: adaptive)")->check(Number(1.0, 64.0));
  cmd->add_option("--adaptive", o->adaptive, "Adaptive tessellation: target edge length in pixels")->check(Number(0.5, 1000.0))->capture_default_str();
  cmd->add_option("--max-tess", o->maxTess, "Largest adaptive factor (default 64; lavapipe: 16, it splits draws by the largest)")
      ->check(Number(1.0, 64.0));
  cmd->add_option("--displace", o->displace, "Displacement scale")->check(Number(-10.0, 10.0));
  cmd->add_flag("--no-leaves", o->noLeaves, "Leave the leaves out");
  cmd->add_option("--leaf-lod", o->leafLod, "All leaves up to this distance (m), then thinning (0: all)")->check(Number(0.0, 10000.0))->capture_default_str();
  cmd->add_option("--shadow-leaves", o->shadowLeaves, "Leaf self-shadowing against this many leaves")->check(Whole(0, 4096))->capture_default_str();
  cmd->add_option("--detail", o->detail, "FULL,REDUCED[,FAR] metres: whole mesh within FULL, deepest level faked within REDUCED, two beyond; beyond FAR trees drawn without the tessellator, their fake branches as a sketch (default 40,150,400; lavapipe 0,15,60)");
  cmd->add_option("--light", o->light, "Sun direction AZIMUTH,ELEVATION in degrees")->capture_default_str();
  cmd->add_option("--camera-path", o->cameraPath, "Scripted: cameras ex,ey,ez,tx,ty,tz[,fov], one per line, visited over --frames");
  cmd->add_option("--frames", o->frames, "Scripted: render this many frames, then exit (default with a path: 60)")->check(Whole(1, 100000));
  cmd->add_option("--screenshot-every", o->screenshotEvery, "Scripted: write every K-th frame as PNG (default: the last)")->check(Whole(1, 100000));
  cmd->add_option("--out", o->out, "Folder for screenshots")->capture_default_str();
  cmd->add_option("--events", o->events, "Scripted window events FRAME:ACTION,... with ACTION resize=WxH, minimise, restore, fullscreen, regenerate");
  cmd->add_flag("--offscreen", o->offscreen, "Render offscreen even when a display is there");
  cmd->add_flag("--overlay", o->overlayInScript, "Draw the overlay in scripted runs too");
  cmd->add_option("--step", o->step, "Move the cameras this many seconds per frame, whatever the frame took (reproducible walks; 0: real time)")
      ->check(Number(0.0, 1.0));
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1); errors fail the run");
  cmd->callback([o, &action] { action = [o] { return runView(*o); }; });
}

}  // namespace arbor::cli
