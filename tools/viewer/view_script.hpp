#pragma once
// The viewer's scripts as text: camera paths (one camera per line) and window events (--events). Parsing is
// apart from reading so that the fuzz targets and the tests feed them text directly.
#include <string>
#include <vector>

#include "render/camera.hpp"

namespace arbor::viewer {

// Camera path files are small text files; larger ones are refused before they are read.
constexpr std::size_t kMaxCameraPathBytes = 16u * 1024 * 1024;

// Each non-empty line not starting with '#' is "ex,ey,ez,tx,ty,tz[,fov]"; errors name the file and line (InputError).
// At least one camera.
std::vector<render::Camera> parseCameraPath(const std::string& text, const std::string& file);
std::vector<render::Camera> readCameraPath(const std::string& path);

struct WindowEvent {
  int frame = 0;
  std::string action;           // one of eventActions() (the window's, the forest's, the modeller's)
  int width = 0, height = 0;    // resize
  std::string text;             // open, save, export: the file; add-cloud, add-obstacle: the shape
  std::vector<double> numbers;  // the action's numbers in order (an index first where it names one)
};

// "FRAME:ACTION[=ARGUMENTS],..." (frames from 1); the actions and their arguments as `arbor view --help` lists
// them: resize=WxH, minimise, restore, fullscreen, regenerate, save=FILE, export=FILE, open=FILE, grow, pause, step=NODES, finish,
// rewind=AGE, reset, add-cloud=SHAPE/X/Y/Z/SX/SY/SZ[/POINTS/INFLUENCE/KILL], move-cloud=I/X/Y/Z,
// resize-cloud=I/SX/SY/SZ, remove-cloud=I, add-obstacle=box|sphere/X/Y/Z/SX/SY/SZ, move-obstacle=I/X/Y/Z,
// resize-obstacle=I/SX/SY/SZ, remove-obstacle=I. InputError naming --events and the item otherwise.
std::vector<WindowEvent> parseEvents(const std::string& text);

// The actions that change a scene rather than the window (the viewer checks them against its scene).
bool isSceneEvent(const WindowEvent& event);

}  // namespace arbor::viewer
