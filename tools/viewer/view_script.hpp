#pragma once
// The viewer's scripts as text: camera paths (one camera per line) and window events (--events). Parsing is
// apart from reading so that the fuzz targets and the tests feed them text directly.
#include <string>
#include <vector>

#include "render/camera.hpp"

namespace arbor::cli {

// Camera path files are small text files; larger ones are refused before they are read.
constexpr std::size_t kMaxCameraPathBytes = 16u * 1024 * 1024;

// Each non-empty line not starting with '#' is "ex,ey,ez,tx,ty,tz[,fov]"; errors name the file and line (InputError).
// At least one camera.
std::vector<render::Camera> parseCameraPath(const std::string& text, const std::string& file);
std::vector<render::Camera> readCameraPath(const std::string& path);

struct WindowEvent {
  int frame = 0;
  std::string action;  // resize, minimise, restore, fullscreen, regenerate
  int width = 0, height = 0;
};

// "FRAME:ACTION,..." with ACTION resize=WxH, minimise, restore, fullscreen or regenerate; frames from 1.
std::vector<WindowEvent> parseEvents(const std::string& text);

}  // namespace arbor::cli
