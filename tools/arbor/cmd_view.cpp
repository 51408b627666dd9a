// arbor view: its options, and which scene the viewer (tools/viewer) shows: the walkthrough over a generated
// forest, or the modeller for one space-colonization model.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/input_error.hpp"
#include "forest_scene.hpp"
#include "growth/space_colonization/space_colonization_model.hpp"
#include "growth_scene.hpp"
#include "common/text_util.hpp"
#include "render_options.hpp"
#include "export_options.hpp"
#include "files/tree_file.hpp"
#include "view_script.hpp"
#include "viewer.hpp"
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
  float anisotropy = 0.0f;  // 0: by device
  float displace = 0.0f;
  bool noLeaves = false;
  float leafLod = 60.0f;
  int shadowLeaves = 0;
  WindSettings wind;
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

// "FULL,REDUCED[,FAR]" in metres; empty: none given (the device decides).
std::optional<render::DetailDistances> parseDetail(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::vector<float> v = parseNumbers(text, "--detail", 0.0f, 100000.0f);
  if (v.size() < 2 || v.size() > 3 || v[1] < v[0] || (v.size() == 3 && v[2] < v[1])) {
    throw InputError(text, "--detail", "expected FULL,REDUCED[,FAR] metres, each at least the one before, e.g. 40,150,400");
  }
  return render::DetailDistances{v[0], v[1], v.size() == 3 ? v[2] : render::DetailDistances{}.far};
}

// One space-colonization model alone opens the modeller; anything else is a forest to walk through.
bool opensModeller(const ViewOptions& o, const std::vector<TreeSource>& sources) {
  return sources.size() == 1 && o.forest == 1 && sources.front().model() && spaceColonizationOf(*sources.front().model());
}

int runView(const ViewOptions& o) {
  viewer::ViewState state;
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
  s.wind = o.wind;
  const glm::vec2 sun = parseSunAngles(o.light);
  state.lightAzimuth = sun.x;
  state.lightElevation = sun.y;
  s.lightDirection = render::sunDirection(sun.x, sun.y);

  // Everything the options say is read before anything is grown, so that bad input fails early.
  viewer::ViewerOptions v;
  parseSize(o.size, v.width, v.height);
  v.detail = parseDetail(o.detail);
  v.maxTessGiven = o.maxTess > 0.0f;
  if (o.anisotropy > 0.0f) v.anisotropy = o.anisotropy;
  v.events = viewer::parseEvents(o.events);
  std::vector<TreeSource> sources;
  for (const std::string& name : o.species) sources.push_back(loadTreeArgument(name, nullptr, o.angles));
  if (!o.cameraPath.empty()) v.path = viewer::readCameraPath(o.cameraPath);
  const bool modeller = opensModeller(o, sources);
  if (modeller) viewer::GrowthScene::checkEvents(*sources.front().model(), v.events);
  for (const viewer::WindowEvent& e : v.events) {
    // Saved and exported files are checked like --out: a folder that is there and writable, a fitting extension.
    if (e.action == "save" || e.action == "export") {
      requireOutputFile(e.text, "--events");
      if (e.action == "save" && !endsWith(e.text, ".json")) throw InputError(e.text, "--events", "save writes the model as .json");
      if (e.action == "export" && !isMeshFile(e.text)) throw InputError(e.text, "--events", "export writes the mesh as .obj, .gltf or .glb");
      if (!modeller && !sources.front().model() && e.action == "save")
        throw InputError(e.text, "--events", o.species.front() + " is a skeleton given whole: there is no model to save");
      continue;
    }
    if (!modeller && viewer::isSceneEvent(e) && e.action != "regenerate")
      throw InputError(std::to_string(e.frame) + ":" + e.action, "--events",
                       "the modeller's events need one space-colonization model and --forest 1 (e.g. arbor view sc-open-broadleaf)");
  }
  // Scripted: a camera path or a frame count; without a display the scene goes to PNG files instead.
  const bool scripted = !o.cameraPath.empty() || o.frames > 0;
  v.offscreen = o.offscreen;
  if (scripted || o.offscreen || !window::displayAvailable()) requireOutputFolder(o.out);
  v.frames = o.frames > 0 ? o.frames : (scripted ? 60 : 0);
  v.every = o.screenshotEvery > 0 ? o.screenshotEvery : std::max(1, v.frames);
  v.out = o.out;
  v.fullscreen = o.fullscreen;
  v.vsync = !o.noVsync;
  v.orbit = o.orbit;
  v.overlayInScript = o.overlayInScript;
  v.step = o.step;
  v.device = o.device;
  v.validation = o.validation;
  if (modeller) {
    viewer::GrowthScene scene(*sources.front().model(), o.seed);
    return viewer::runViewer(v, state, scene);
  }
  viewer::ForestScene scene(ForestRequest{o.species, sources, o.forest, o.seeds, o.seed});
  return viewer::runViewer(v, state, scene);
}

}  // namespace

void addViewCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Walk through a generated forest in a window (Vulkan), or grow one space-colonization model in the modeller; offscreen PNGs where no display is.");
  cmd->add_option("species", o->species, "Presets, or model, skeleton or graph files (default: black-tupelo)");
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--forest", o->forest, "Trees to place (1: one tree, orbit camera)")->check(Whole(1, 5000))->capture_default_str();
  cmd->add_option("--seeds", o->seeds, "Distinct seeds per species (each grown once, then instanced)")->check(Whole(1, 16))->capture_default_str();
  cmd->add_option("--seed", o->seed, "First seed; also places the trees")->check(Seed())->capture_default_str();
  cmd->add_option("--size", o->size, "Window (or picture) size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_flag("--no-vsync", o->noVsync, "Present without waiting for vertical blank (mailbox or immediate)");
  cmd->add_flag("--fullscreen", o->fullscreen, "Start fullscreen (F11 toggles)");
  cmd->add_flag("--orbit", o->orbit, "Start with the orbit camera (Tab toggles)");
  cmd->add_option("--mode", o->mode, modeHelp())->capture_default_str();
  cmd->add_option("--tess", o->tess, "Uniform tessellation factor (default: adaptive)")->check(Number(1.0, 64.0));
  cmd->add_option("--adaptive", o->adaptive, "Adaptive tessellation: target edge length in pixels")->check(Number(0.5, 1000.0))->capture_default_str();
  cmd->add_option("--max-tess", o->maxTess, "Largest adaptive factor (default 64; lavapipe: 16, it splits draws by the largest)")
      ->check(Number(1.0, 64.0));
  addAnisotropyOption(cmd, o->anisotropy, "8; lavapipe: 1, where 8 costs about a third of the frame");
  cmd->add_option("--displace", o->displace, "Displacement scale")->check(Number(-10.0, 10.0));
  cmd->add_flag("--no-leaves", o->noLeaves, "Leave the leaves out");
  cmd->add_option("--leaf-lod", o->leafLod, "All leaves up to this distance (m), then fewer and larger ones, keeping the leaf area (0: all)")->check(Number(0.0, 10000.0))->capture_default_str();
  cmd->add_option("--shadow-leaves", o->shadowLeaves, "Leaf self-shadowing against this many leaves")->check(Whole(0, 4096))->capture_default_str();
  cmd->add_option("--detail", o->detail, "FULL,REDUCED[,FAR] metres: whole mesh within FULL, deepest level faked within REDUCED, two beyond; beyond FAR trees drawn without the tessellator, their fake branches as a sketch (default 40,150,400; lavapipe 0,15,60)");
  addWindOptions(cmd, o->wind, "the trees sway; also on the panel");
  cmd->add_option("--light", o->light, "Sun direction AZIMUTH,ELEVATION in degrees")->capture_default_str();
  cmd->add_option("--camera-path", o->cameraPath, "Scripted: cameras ex,ey,ez,tx,ty,tz[,fov], one per line, visited over --frames");
  cmd->add_option("--frames", o->frames, "Scripted: render this many frames, then exit (default with a path: 60)")->check(Whole(1, 100000));
  cmd->add_option("--screenshot-every", o->screenshotEvery, "Scripted: write every K-th frame as PNG (default: the last)")->check(Whole(1, 100000));
  cmd->add_option("--out", o->out, "Folder for screenshots")->capture_default_str();
  cmd->add_option("--events", o->events,
                  "Scripted events FRAME:ACTION,...: the window's resize=WxH, minimise, restore, fullscreen; regenerate; and the modeller's "
                  "open=FILE, grow, pause, step=NODES, finish, rewind=AGE, reset, add-cloud=SHAPE/X/Y/Z/SX/SY/SZ[/POINTS/INFLUENCE/KILL], "
                  "move-cloud=I/X/Y/Z, resize-cloud=I/SX/SY/SZ, remove-cloud=I, add-obstacle=box|sphere/X/Y/Z/SX/SY/SZ, move-obstacle=I/X/Y/Z, "
                  "resize-obstacle=I/SX/SY/SZ, remove-obstacle=I (docs/viewer.md)");
  cmd->add_flag("--offscreen", o->offscreen, "Render offscreen even when a display is there");
  cmd->add_flag("--overlay", o->overlayInScript, "Draw the overlay in scripted runs too");
  cmd->add_option("--step", o->step, "Move the cameras this many seconds per frame, whatever the frame took (reproducible walks; 0: real time)")
      ->check(Number(0.0, 1.0));
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1); errors fail the run");
  cmd->callback([o, &action] { action = [o] { return runView(*o); }; });
}

}  // namespace arbor::cli
