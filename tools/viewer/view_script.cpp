#include "view_script.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "cli_values.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"

namespace arbor::viewer {

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

namespace {

// How an action's argument reads: nothing, WxH, a file, or '/'-separated numbers (a shape name first for `shape`).
enum class Argument { None, Size, File, Numbers };

struct EventAction {
  const char* name;
  Argument argument;
  bool shape = false;        // a shape name before the numbers
  std::size_t minNumbers = 0, maxNumbers = 0;
  bool index = false;        // the first number is a whole index
  bool scene = true;
};

constexpr EventAction kActions[] = {
    {"resize", Argument::Size, false, 0, 0, false, false},
    {"minimise", Argument::None, false, 0, 0, false, false},
    {"restore", Argument::None, false, 0, 0, false, false},
    {"fullscreen", Argument::None, false, 0, 0, false, false},
    {"regenerate", Argument::None},
    {"save", Argument::File},
    {"export", Argument::File},
    {"open", Argument::File},
    {"grow", Argument::None},
    {"pause", Argument::None},
    {"step", Argument::Numbers, false, 1, 1, true},
    {"finish", Argument::None},
    {"rewind", Argument::Numbers, false, 1, 1, true},
    {"reset", Argument::None},
    {"add-cloud", Argument::Numbers, true, 6, 9},
    {"move-cloud", Argument::Numbers, false, 4, 4, true},
    {"resize-cloud", Argument::Numbers, false, 4, 4, true},
    {"remove-cloud", Argument::Numbers, false, 1, 1, true},
    {"add-obstacle", Argument::Numbers, true, 6, 6},
    {"move-obstacle", Argument::Numbers, false, 4, 4, true},
    {"resize-obstacle", Argument::Numbers, false, 4, 4, true},
    {"remove-obstacle", Argument::Numbers, false, 1, 1, true},
};

const EventAction* findAction(const std::string& name) {
  for (const EventAction& a : kActions)
    if (name == a.name) return &a;
  return nullptr;
}

// Numbers in events stay within a million: coordinates, sizes, counts and indices alike.
constexpr double kLargestEventNumber = 1e6;

bool readArguments(const EventAction& action, const std::string& argument, WindowEvent& e) {
  switch (action.argument) {
    case Argument::None: return argument.empty();
    case Argument::File:
      e.text = argument;
      return !argument.empty();
    case Argument::Size: {
      std::size_t k = 0;
      return readCount(argument, k, 4, e.width) && k < argument.size() && argument[k++] == 'x' && readCount(argument, k, 4, e.height) &&
             k == argument.size() && e.width >= 1 && e.height >= 1 && e.width <= 8192 && e.height <= 8192;
    }
    case Argument::Numbers: break;
  }
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t slash; (slash = argument.find('/', start)) != std::string::npos; start = slash + 1) parts.push_back(argument.substr(start, slash - start));
  parts.push_back(argument.substr(start));
  std::size_t first = 0;
  if (action.shape) {
    e.text = parts.front();
    first = 1;
  }
  const std::size_t count = parts.size() - first;
  if (count < action.minNumbers || count > action.maxNumbers) return false;
  for (std::size_t i = first; i < parts.size(); ++i) {
    double v = 0.0;
    if (!cli::parseFinite(parts[i], v) || std::abs(v) > kLargestEventNumber) return false;
    if (action.index && i == first && (v < 0 || v != std::floor(v))) return false;
    e.numbers.push_back(v);
  }
  return true;
}

}  // namespace

std::vector<WindowEvent> parseEvents(const std::string& text) {
  const std::string allowed =
      "expected FRAME:ACTION[=ARGUMENTS] with frames from 1 to 1000000 and ACTION one of resize=WxH (1 to 8192), minimise, restore, "
      "fullscreen, regenerate, save=FILE.json, export=FILE.obj|.gltf|.glb, open=FILE, grow, pause, step=NODES, finish, rewind=AGE, reset, "
      "add-cloud=SHAPE/X/Y/Z/SX/SY/SZ[/POINTS/INFLUENCE/KILL], move-cloud=I/X/Y/Z, resize-cloud=I/SX/SY/SZ, remove-cloud=I, "
      "add-obstacle=box|sphere/X/Y/Z/SX/SY/SZ, move-obstacle=I/X/Y/Z, resize-obstacle=I/SX/SY/SZ, remove-obstacle=I "
      "(numbers finite, at most 1e6 in size; indices and counts whole)";
  std::vector<WindowEvent> events;
  for (const std::string& item : cli::splitList(text, "--events")) {
    WindowEvent e;
    std::size_t at = 0;
    bool ok = readCount(item, at, 7, e.frame) && e.frame >= 1 && e.frame <= 1000000 && at < item.size() && item[at++] == ':';
    if (ok) {
      const std::string rest = item.substr(at);
      const std::size_t equals = rest.find('=');
      e.action = rest.substr(0, equals);
      const EventAction* action = findAction(e.action);
      const bool hasArgument = equals != std::string::npos;
      ok = action && hasArgument == (action->argument != Argument::None) && readArguments(*action, hasArgument ? rest.substr(equals + 1) : "", e);
    }
    if (!ok) throw InputError(item, "--events", allowed);
    events.push_back(e);
  }
  return events;
}

bool isSceneEvent(const WindowEvent& event) {
  const EventAction* action = findAction(event.action);
  return action && action->scene;
}

}  // namespace arbor::viewer
