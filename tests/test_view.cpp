// The walkthrough viewer as users run it: in a window under Xvfb on lavapipe with a scripted camera path,
// and offscreen where no display is. Validation is on in every run; any error fails the run (exit 1).
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

#include "common/atomic_file.hpp"
#include "image/image_compare.hpp"
#include "image/png_io.hpp"
#include "render_support.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace arbor;

namespace {

using test::runCommand;
using Result = test::CommandResult;

// `prefix` runs the viewer under Xvfb or without a display.
Result run(const std::string& prefix, const std::string& arguments) {
  return runCommand(prefix + " " + ARBOR_BINARY + " view --validation " + arguments + " 2>&1");
}

// A stuck window (no display answering, a script waiting for it) ends in a failure, not a hung suite.
const std::string kXvfb = "timeout 180 xvfb-run -a -s '-screen 0 800x600x24'";
const std::string kNoDisplay = "timeout 180 env -u DISPLAY -u WAYLAND_DISPLAY";

// Walks past the palm: it stands in the middle of every frame.
std::string palmPath() {
  const std::string path = test::tempPath("palm-path.txt");
  std::ofstream(path) << "# eye x,y,z, target x,y,z, field of view\n-8,-20,2,0,0,5,50\n\n8,-20,3,0,0,5,50\n";
  return path;
}

std::string freshDir(const std::string& name) {
  const std::string dir = test::tempPath(name);
  fs::remove_all(dir);
  return dir;
}

// Share of pixels in the column band around the middle that are not sky or ground (a tree is there).
double treeShareInMiddle(const Image& image) {
  std::size_t tree = 0, total = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = image.width * 2 / 5; x < image.width * 3 / 5; ++x) {
      const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x));
      const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
      // Sky is blue-white; the ground a dull, even green-grey; bark brown, leaves saturated green.
      const bool sky = b > r && b >= g;
      const bool ground = std::abs(r - g) < 20 && std::abs(g - b) < 40 && g < 170 && y > image.height / 2;
      tree += !sky && !ground ? 1 : 0;
      ++total;
    }
  }
  return static_cast<double>(tree) / static_cast<double>(total);
}

// Saturated green to the right of the panel (the first 450 columns): the palm's fronds.
std::size_t leafPixelsBesidePanel(const Image& image) {
  std::size_t leaves = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 450; x < image.width; ++x) {
      const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x));
      const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
      leaves += g > r + 25 && g > b + 25 ? 1 : 0;
    }
  }
  return leaves;
}

// The viewer in a window under Xvfb driven by xdotool, as a user would: `steps` (shell lines that may use $win
// and waitfor) run once the viewer has started, its window has focus and F12 has written frame-0001.png; then Esc.
// Every step waits for the viewer to show it was taken (its start line, each screenshot's "wrote" line, its exit),
// never for a fixed time: a loaded machine only makes it slower. Returns the run with the viewer's log appended.
Result runInWindow(const std::string& name, const std::string& viewerArguments, const std::string& steps) {
  const std::string log = test::tempPath(name + ".log"), script = test::tempPath(name + ".sh");
  std::ofstream(script) << "log=" << log << "\n"
                        << "waitfor() { i=0; until grep -q \"$1\" $log; do i=$((i+1)); [ $i -gt 1200 ] && { echo \"timed out waiting for $1\"; return 1; }; sleep 0.05; done; }\n"
                        << ARBOR_BINARY << " view --validation " << viewerArguments << " > $log 2>&1 &\n"
                        << "pid=$!\n"
                        << "waitfor 'interactive on' || { kill $pid; exit 1; }\n"
                        << "win=$(timeout 60 xdotool search --sync --name '^Arbor$' | head -1)\n"
                        << "xdotool windowfocus --sync \"$win\"\n"
                        << "xdotool key F12\n"
                        << "waitfor 'frame-0001.png' || { kill $pid; exit 1; }\n"
                        << steps << "\n"
                        << "xdotool key Escape\n"
                        << "(sleep 120; kill $pid) > /dev/null 2>&1 &\n"  // Esc not heard: end it, and fail
                        << "watchdog=$!\n"
                        << "wait $pid; status=$?\n"
                        << "kill $watchdog 2>/dev/null\n"
                        << "exit $status\n";
  Result r = runCommand(kXvfb + " sh " + script + " 2>&1");
  std::ifstream in(log);
  r.output += std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return r;
}

}  // namespace

TEST_CASE("the viewer in a window shows the scripted frames, the same as offscreen, without validation errors", "[view]") {
  const std::string path = palmPath();
  const std::string windowDir = freshDir("view-window"), offscreenDir = freshDir("view-offscreen");
  const std::string common = "palm --size 240x180 --camera-path " + path + " --frames 4 --screenshot-every 2 --out ";
  const Result window = run(kXvfb, common + windowDir);
  INFO(window.output);
  REQUIRE(window.exitCode == 0);
  CHECK_THAT(window.output, Catch::Contains("scripted on"));
  CHECK_THAT(window.output, Catch::Contains("median"));
  const Result offscreen = run(kNoDisplay, common + offscreenDir);
  INFO(offscreen.output);
  REQUIRE(offscreen.exitCode == 0);
  CHECK_THAT(offscreen.output, Catch::Contains("no display"));
  for (const char* frame : {"frame-0002.png", "frame-0004.png"}) {
    INFO(frame);
    REQUIRE(fs::exists(fs::path(windowDir) / frame));
    REQUIRE(fs::exists(fs::path(offscreenDir) / frame));
    const Image shown = readPng((fs::path(windowDir) / frame).string());
    const Image rendered = readPng((fs::path(offscreenDir) / frame).string());
    CHECK(shown.width == 240);
    CHECK(shown.height == 180);
    CHECK(treeShareInMiddle(shown) > 0.03);  // the palm is where the path looks
    const ImageDifference d = compareImages(rendered, shown, 16);
    CHECK(d.pixelsOverThreshold == 0);  // the swapchain shows what the offscreen target renders
  }
  CHECK_FALSE(fs::exists(fs::path(windowDir) / "frame-0001.png"));  // only every second frame
}

TEST_CASE("the viewer survives resize, minimise, fullscreen and regeneration, overlay on", "[view]") {
  const std::string dir = freshDir("view-events");
  const Result r = run(kXvfb, "palm --size 240x180 --frames 8 --screenshot-every 1 --overlay --out " + dir +
                                  " --events 2:resize=200x150,3:minimise,4:restore,5:fullscreen,6:fullscreen,6:regenerate,7:resize=240x180");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(readPng((fs::path(dir) / "frame-0002.png").string()).width == 200);
  CHECK(readPng((fs::path(dir) / "frame-0005.png").string()).width == 800);  // the Xvfb screen
  const Image last = readPng((fs::path(dir) / "frame-0008.png").string());
  CHECK(last.width == 240);
  // The overlay's frame-time graph, dark blue, stands at the top left.
  const std::size_t corner = 4 * (100 * static_cast<std::size_t>(last.width) + 100);
  CHECK(last.rgba[corner] + last.rgba[corner + 1] + last.rgba[corner + 2] < 250);
  CHECK_THAT(r.output, Catch::Contains("growing palm #1 (1/1)"));
}

TEST_CASE("the viewer answers keys: F12 takes a screenshot, W moves the camera, Esc leaves", "[view]") {
  const std::string dir = freshDir("view-keys");
  // --step 0.25 moves the camera by a quarter second's walk in every frame, however long the frame took. W is held
  // while three more screenshots are taken: at least those frames walk.
  const Result r = runInWindow("view-keys", "palm --size 240x180 --step 0.25 --out " + dir,
                               "xdotool keydown w\n"
                               "for n in 2 3 4; do xdotool key F12; waitfor \"frame-000$n.png\" || { kill $pid; exit 1; }; done\n"
                               "xdotool keyup w");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);  // Esc left the viewer, without a validation error
  REQUIRE(fs::exists(fs::path(dir) / "frame-0001.png"));
  REQUIRE(fs::exists(fs::path(dir) / "frame-0004.png"));
  const ImageDifference moved = compareImages(readPng((fs::path(dir) / "frame-0001.png").string()),
                                              readPng((fs::path(dir) / "frame-0004.png").string()), 16);
  CHECK(moved.pixelsOverThreshold > 1000);  // W brought the orbit camera closer
}

TEST_CASE("the viewer's panel answers the mouse: a click on 'leaves' hides them", "[view]") {
  // The panel follows the pointer from its events (window/overlay.cpp), not from questions to X11: xdotool moves
  // the pointer onto the checkbox, then clicks and presses F12 while the viewer is stopped, so that press, release
  // and F12 come in one frame's events (a slow frame's case): the screenshot must wait for the click's effect.
  const std::string dir = freshDir("view-click");
  const Result r = runInWindow("view-click", "palm --size 800x600 --out " + dir,
                               "xdotool mousemove --window \"$win\" --sync 27 426\n"  // the 'leaves' checkbox
                               "kill -STOP $pid; xdotool click 1 key F12; kill -CONT $pid\n"
                               "waitfor 'frame-0002.png' || { kill $pid; exit 1; }");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::size_t before = leafPixelsBesidePanel(readPng((fs::path(dir) / "frame-0001.png").string()));
  const std::size_t after = leafPixelsBesidePanel(readPng((fs::path(dir) / "frame-0002.png").string()));
  INFO("leaf pixels before " << before << ", after " << after);
  CHECK(before > 500);
  CHECK(after * 20 < before);
}

TEST_CASE("the viewer turns the camera while the right button drags the mouse", "[view]") {
  // The pointer comes from GLFW's events (window/window.cpp). It starts over the panel, which then has the mouse:
  // moved right of it and shown in a screenshot (so a frame has seen it there), then the right button held and the
  // pointer moved turn the camera, and the next screenshot shows another view.
  const std::string dir = freshDir("view-mouse-look");
  const Result r = runInWindow("view-mouse-look", "palm --size 800x600 --out " + dir,
                               "xdotool mousemove --window \"$win\" --sync 700 300 key F12\n"
                               "waitfor 'frame-0002.png' || { kill $pid; exit 1; }\n"
                               "xdotool mousedown 3 mousemove_relative --sync 80 0 key F12\n"
                               "waitfor 'frame-0003.png' || { kill $pid; exit 1; }\n"
                               "xdotool mouseup 3");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const ImageDifference turned = compareImages(readPng((fs::path(dir) / "frame-0002.png").string()),
                                               readPng((fs::path(dir) / "frame-0003.png").string()), 16);
  CHECK(turned.pixelsOverThreshold > 1000);
}

TEST_CASE("the viewer follows a resize made by the window system, not by its script", "[view]") {
  // The window keeps its size from GLFW's events (window/window.cpp): xdotool resizes it from outside, and the
  // next screenshot has the new size.
  const std::string dir = freshDir("view-outside-resize");
  const Result r = runInWindow("view-outside-resize", "palm --size 320x240 --out " + dir,
                               "xdotool windowsize --sync \"$win\" 400 300 key F12\n"
                               "waitfor 'frame-0002.png' || { kill $pid; exit 1; }");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(readPng((fs::path(dir) / "frame-0001.png").string()).width == 320);
  const Image resized = readPng((fs::path(dir) / "frame-0002.png").string());
  CHECK(resized.width == 400);
  CHECK(resized.height == 300);
}

TEST_CASE("the viewer's trees sway in the wind, still air draws them as without wind", "[view][wind]") {
  const std::string path = palmPath();
  const std::string common = "palm --size 160x120 --camera-path " + path + " --frames 2 --screenshot-every 2 --out ";
  std::vector<Image> frames;
  for (const char* wind : {"", " --wind 0", " --wind 3 --wind-azimuth 90"}) {
    const std::string dir = freshDir(std::string("view-wind") + std::to_string(frames.size()));
    const Result r = run(kNoDisplay, common + dir + wind);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    frames.push_back(readPng((fs::path(dir) / "frame-0002.png").string()));
  }
  CHECK(compareImages(frames[0], frames[1], 0).pixelsOverThreshold == 0);
  CHECK(compareImages(frames[0], frames[2], 16).pixelsOverThreshold > 20);
}

TEST_CASE("the viewer filters bark anisotropically as asked, trilinearly by default on lavapipe", "[view]") {
  // Looking up the palm's trunk from its foot: the bark recedes at a grazing angle, where anisotropy keeps detail.
  const std::string path = test::tempPath("graze-path.txt");
  std::ofstream(path) << "0.3,-0.3,0.5,0,0,6,40\n0.3,-0.3,0.5,0,0,6,40\n";
  std::vector<Image> frames;
  for (const char* filtering : {"", " --anisotropy 1", " --anisotropy 16"}) {
    const std::string dir = freshDir(std::string("view-anisotropy") + std::to_string(frames.size()));
    const Result r = run(kNoDisplay, "palm --no-leaves --size 160x120 --camera-path " + path + " --frames 2 --screenshot-every 2 --out " + dir + filtering);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    frames.push_back(readPng((fs::path(dir) / "frame-0002.png").string()));
  }
  CHECK(compareImages(frames[0], frames[1], 0).pixelsOverThreshold == 0);
  CHECK(compareImages(frames[1], frames[2], 16).pixelsOverThreshold > 100);  // 396 on 2026-12-05
}

TEST_CASE("without a display the viewer renders a forest offscreen and says where", "[view]") {
  const std::string dir = freshDir("view-forest");
  const Result r = run(kNoDisplay, "palm quaking-aspen --forest 12 --seeds 1 --size 200x120 --levels-note --out " + dir);
  CHECK(r.exitCode == 2);  // an unknown option is refused
  const Result forest = run(kNoDisplay, "palm quaking-aspen --forest 12 --seeds 1 --size 200x120 --out " + dir);
  INFO(forest.output);
  REQUIRE(forest.exitCode == 0);
  CHECK_THAT(forest.output, Catch::Contains("12 trees"));
  CHECK_THAT(forest.output, Catch::Contains("wrote " + (fs::path(dir) / "frame-0001.png").string()));
  CHECK(readPng((fs::path(dir) / "frame-0001.png").string()).width == 200);
}

TEST_CASE("the viewer refuses bad scripts with 2, naming the file, line or option", "[view]") {
  const std::string bad = test::tempPath("bad-path.txt");
  std::ofstream(bad) << "0,-10,2,0,0,2\n0,0,1,0,0,1\n";
  const Result line = run(kNoDisplay, "palm --camera-path " + bad + " --frames 2 --out " + freshDir("view-bad"));
  CHECK(line.exitCode == 2);
  CHECK_THAT(line.output, Catch::Contains(bad));
  CHECK_THAT(line.output, Catch::Contains("line 2"));
  const Result missing = run(kNoDisplay, "palm --camera-path " + test::tempPath("no-such-path.txt") + " --out " + freshDir("view-bad"));
  CHECK(missing.exitCode == 2);
  CHECK_THAT(missing.output, Catch::Contains("no-such-path.txt"));
  const Result species = run(kNoDisplay, "palm no-such-tree --out " + freshDir("view-bad"));
  CHECK(species.exitCode == 2);
  CHECK_THAT(species.output, Catch::Contains("no-such-tree"));
  const Result detail = run(kNoDisplay, "palm --detail 50,10 --out " + freshDir("view-bad"));
  CHECK(detail.exitCode == 2);
  CHECK_THAT(detail.output, Catch::Contains("--detail"));
  const Result events = run(kNoDisplay, "palm --events 3:explode --out " + freshDir("view-bad"));
  CHECK(events.exitCode == 2);
  CHECK_THAT(events.output, Catch::Contains("--events"));
  CHECK_FALSE(fs::exists(test::tempPath("view-bad")));  // nothing written
}

namespace {

// What the modeller logs per scripted frame: "...; age A, N nodes (E enabled), P live points, C clouds, O obstacles, STATE".
struct ModellerFrame {
  unsigned age = 0;
  std::size_t nodes = 0, enabled = 0, live = 0, clouds = 0, obstacles = 0;
  std::string state;
};

std::vector<ModellerFrame> modellerFrames(const std::string& output) {
  std::vector<ModellerFrame> frames;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find("; age ");
    if (line.rfind("arbor view: frame ", 0) != 0 || at == std::string::npos) continue;
    ModellerFrame f;
    char state[32] = {};
    if (std::sscanf(line.c_str() + at, "; age %u, %zu nodes (%zu enabled), %zu live points, %zu clouds, %zu obstacles, %31s", &f.age, &f.nodes,
                    &f.enabled, &f.live, &f.clouds, &f.obstacles, state) == 7) {
      f.state = state;
      frames.push_back(f);
    }
  }
  return frames;
}

// The node count the modeller starts with: the model grown to the end ("modeller: NAME, N nodes").
std::size_t startingNodes(const std::string& output) {
  const std::size_t at = output.find(" nodes\n");
  REQUIRE(at != std::string::npos);
  const std::size_t from = output.rfind(", ", at);
  return std::stoul(output.substr(from + 2, at - from - 2));
}

}  // namespace

TEST_CASE("the modeller grows, pauses, rewinds, regrows and takes clouds and obstacles from a script", "[view][sc]") {
  const std::string dir = freshDir("view-modeller");
  const Result r = run(kNoDisplay, "sc-open-broadleaf --size 200x150 --frames 9 --out " + dir +
                                       " --events 1:rewind=0,2:step=300,3:rewind=10,4:finish,5:add-cloud=sphere/3.8/0/4.6/1/1/1/400/1.5/0.3,6:finish,"
                                       "7:add-obstacle=box/0/0/6/3/3/1,8:remove-obstacle=0,9:remove-cloud=1");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::vector<ModellerFrame> f = modellerFrames(r.output);
  REQUIRE(f.size() == 9);
  const std::size_t grown = startingNodes(r.output);
  CHECK(f[0].age == 0);
  CHECK(f[0].nodes == 13);  // the trunk's twelve segments
  CHECK(f[1].nodes > f[0].nodes);
  CHECK(f[1].nodes <= f[0].nodes + 300);  // at most one node per node processed
  CHECK(f[2].age == 10);
  CHECK(f[3].nodes == grown);  // regrown from a rewind: the same tree
  CHECK(f[3].state == "finished");
  CHECK(f[4].clouds == 2);
  CHECK(f[4].live > f[3].live);  // beside the crown: some of its 400 points die at once, the rest attract
  CHECK(f[4].live <= f[3].live + 400);
  CHECK(f[5].nodes > f[4].nodes);      // grown out toward the new cloud
  CHECK(f[5].live < f[4].live);
  CHECK(f[6].obstacles == 1);
  CHECK(f[6].enabled < f[6].nodes);   // the slab cut through the crown
  CHECK(f[6].nodes == f[5].nodes);    // disabled, not deleted
  CHECK(f[7].enabled == f[7].nodes);  // removed: every branch back
  CHECK(f[8].clouds == 1);
  CHECK(f[8].nodes == f[7].nodes);    // nodes never go with a cloud
  CHECK(fs::exists(fs::path(dir) / "frame-0009.png"));
}

TEST_CASE("the viewer saves the edited model and exports the mesh shown, from a script", "[view][sc]") {
  const std::string dir = freshDir("view-save");
  fs::create_directories(dir);
  const std::string model = dir + "/edited.json", glb = dir + "/age20.glb", obj = dir + "/age20.obj";
  const Result r = run(kNoDisplay, "sc-open-broadleaf --size 160x120 --frames 2 --out " + dir + "/shots --events 1:rewind=20,"
                                       "1:add-cloud=sphere/3.8/0/4.6/1/1/1/400/1.5/0.3,2:save=" + model + ",2:export=" + glb + ",2:export=" + obj);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("wrote " + model));
  const std::string saved = readFile(model);
  std::size_t clouds = 0;
  for (std::size_t at = saved.find("\"influence\""); at != std::string::npos; at = saved.find("\"influence\"", at + 1)) ++clouds;
  CHECK(clouds == 2);  // the added cloud is in the file
  CHECK(fs::file_size(glb) > 1000);
  // The exported mesh reads back and holds no intersecting pair; the saved model grows again.
  CHECK(test::runCommand(std::string(ARBOR_BINARY) + " check " + obj + " 2>&1").exitCode == 0);
  CHECK(test::runCommand(std::string(ARBOR_BINARY) + " generate " + model + " --quiet --out " + dir + "/regrown.obj 2>&1").exitCode == 0);

  const Result forest = run(kNoDisplay, "palm --size 160x120 --frames 1 --out " + dir + "/palm-shots --events 1:save=" + dir +
                                            "/palm.json,1:export=" + dir + "/palm.obj");
  INFO(forest.output);
  REQUIRE(forest.exitCode == 0);
  CHECK(readFile(dir + "/palm.json") == test::runCommand(std::string(ARBOR_BINARY) + " species palm").output);
  const Result bad = run(kNoDisplay, "palm --frames 1 --out " + dir + "/bad --events 1:export=" + dir + "/palm.stl");
  CHECK(bad.exitCode == 2);
  CHECK_THAT(bad.output, Catch::Contains(".obj, .gltf or .glb"));
}

TEST_CASE("the modeller's picture: tree, cloud and obstacle wireframes, live points (golden)", "[view][sc][golden]") {
  const std::string dir = freshDir("view-modeller-golden");
  const Result r = run(kNoDisplay, "sc-around-sphere --size 320x240 --frames 1 --out " + dir + " --events 1:rewind=25");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const test::GoldenCheck golden = test::checkGolden("modeller-around-sphere", readPng((fs::path(dir) / "frame-0001.png").string()));
  INFO(golden.report);
  CHECK(golden.ok);
}

TEST_CASE("the modeller in a window: growing frame by frame with the panel on", "[view][sc]") {
  const std::string dir = freshDir("view-modeller-window");
  const Result r = run(kXvfb, "sc-between-walls --size 320x240 --frames 6 --overlay --out " + dir + " --events 1:rewind=0,2:grow,5:pause");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("scripted on"));
  const std::vector<ModellerFrame> f = modellerFrames(r.output);
  REQUIRE(f.size() == 6);
  CHECK(f[0].age == 0);
  for (std::size_t k = 1; k < 4; ++k) {
    CHECK(f[k].state == "growing");
    CHECK(f[k].nodes > f[k - 1].nodes);
  }
  CHECK(f[4].state == "paused");
  CHECK(f[5].nodes == f[4].nodes);
}

TEST_CASE("the modeller refuses bad scripts with 2 before anything is drawn", "[view][sc]") {
  const std::string dir = freshDir("view-modeller-bad");
  const std::pair<const char*, const char*> cases[] = {
      {"sc-open-broadleaf --events 2:remove-cloud=3", "no cloud 3"},
      {"sc-open-broadleaf --events 2:add-obstacle=box/0/0/0.5/1/1/1", "trunk"},
      {"sc-open-broadleaf --events 2:add-cloud=sphere/0/0/5/1/1/1/100/0.2/0.5", "kill"},
      {"sc-open-broadleaf --events 2:open=palm", "space-colonization"},
      {"palm --events 2:grow", "modeller"},
  };
  for (const auto& [arguments, says] : cases) {
    const Result r = run(kNoDisplay, std::string(arguments) + " --frames 3 --out " + dir);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Catch::Contains("--events"));
    CHECK_THAT(r.output, Catch::Contains(says));
    CHECK_FALSE(fs::exists(dir));
  }
}
