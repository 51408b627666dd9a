#include "view_script.hpp"

#include <cctype>
#include <stdexcept>

#include "cli_values.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"

namespace arbor::cli {

namespace {

// Digits only, at most `maxDigits`: "%d" would wrap, and a sign or a blank has no place in a frame number.
bool readCount(const std::string& text, std::size_t& at, std::size_t maxDigits, int& out) {
  const std::size_t start = at;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) && at - start < maxDigits + 1) ++at;
  if (at == start || at - start > maxDigits) return false;
  out = std::stoi(text.substr(start, at - start));
  return true;
}

}  // namespace

std::vector<render::Camera> parseCameraPath(const std::string& text, const std::string& file) {
  requireText(text, file, "--camera-path");
  std::vector<render::Camera> keys;
  std::size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto last = line.find_last_not_of(" \t\r");
    try {
      keys.push_back(render::parseCamera(line.substr(first, last - first + 1)));
    } catch (const std::invalid_argument& e) {
      throw InputError(file, "line " + std::to_string(number), e.what());
    }
  }
  if (keys.empty()) throw InputError(file, "--camera-path", "no camera in the file (one ex,ey,ez,tx,ty,tz[,fov] per line)");
  return keys;
}

std::vector<render::Camera> readCameraPath(const std::string& path) {
  return parseCameraPath(readInputFile(path, kMaxCameraPathBytes, "--camera-path"), path);
}

std::vector<WindowEvent> parseEvents(const std::string& text) {
  const std::string allowed =
      "expected FRAME:resize=WxH, FRAME:minimise, FRAME:restore, FRAME:fullscreen or FRAME:regenerate, frames from 1 to 1000000, "
      "sizes from 1 to 8192";
  std::vector<WindowEvent> events;
  for (const std::string& item : splitList(text, "--events")) {
    WindowEvent e;
    std::size_t at = 0;
    bool ok = readCount(item, at, 7, e.frame) && e.frame >= 1 && e.frame <= 1000000 && at < item.size() && item[at++] == ':';
    if (ok) {
      const std::string rest = item.substr(at);
      if (rest.rfind("resize=", 0) == 0) {
        std::size_t k = 7;
        e.action = "resize";
        ok = readCount(rest, k, 4, e.width) && k < rest.size() && rest[k++] == 'x' && readCount(rest, k, 4, e.height) && k == rest.size() &&
             e.width >= 1 && e.height >= 1 && e.width <= 8192 && e.height <= 8192;
      } else {
        e.action = rest;
        ok = rest == "minimise" || rest == "restore" || rest == "fullscreen" || rest == "regenerate";
      }
    }
    if (!ok) throw InputError(item, "--events", allowed);
    events.push_back(e);
  }
  return events;
}

}  // namespace arbor::cli
