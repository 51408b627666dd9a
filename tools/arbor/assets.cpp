#include "assets.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <utility>
#include <unistd.h>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "growth/growth_models.hpp"

namespace arbor::cli {

namespace fs = std::filesystem;

std::string assetDirectory() {
  // $ARBOR_ASSETS first; then beside the binary (installed: PREFIX/share/arbor; a copied tree: assets/); then
  // the source tree the binary was built from. None with presets: an error, never an empty preset list.
  if (const char* env = std::getenv("ARBOR_ASSETS"); env && *env) {
    if (!fs::is_directory(fs::path(env) / "presets")) throw InputError(env, "ARBOR_ASSETS", "has no presets/ folder; point it at Arbor's assets");
    return env;
  }
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates = {exe.parent_path().parent_path() / "share" / "arbor", exe.parent_path() / "assets", exe.parent_path().parent_path() / "assets"};
  }
  candidates.emplace_back(ARBOR_ASSET_DIR);
  std::string looked;
  for (const fs::path& candidate : candidates) {
    if (fs::is_directory(candidate / "presets", ec)) return candidate.string();
    looked += (looked.empty() ? "" : ", ") + candidate.string();
  }
  throw InputError("assets", "ARBOR_ASSETS", "no assets folder with presets found (looked in " + looked + "); install Arbor or set ARBOR_ASSETS");
}

namespace {

// Where presets live: species and other model files, then L-system grammars.
constexpr std::pair<const char*, const char*> kPresetFolders[] = {{"presets", ".json"}, {"lsystems", ".lsys"}};

}  // namespace

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const auto& [folder, extension] : kPresetFolders) {
    std::vector<std::string> here;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::path(assetDirectory()) / folder, ec)) {
      if (entry.path().extension() == extension) here.push_back(entry.path().stem().string());
    }
    std::sort(here.begin(), here.end());
    names.insert(names.end(), here.begin(), here.end());
  }
  return names;
}

void addAnglesOption(CLI::App* cmd, AngleChoice& angles) {
  cmd->add_option_function<std::string>(
         "--angles", [&angles](const std::string& text) { angles = text == "natural" ? AngleChoice::Natural : AngleChoice::File; },
         "Branch and split angles: 'file' keeps the species file's own (Arbaro XML: its DownAngle and SplitAngle; "
         "JSON: its AngleRule), 'natural' uses Murray's angles from the radii (default: file)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return text == "natural" || text == "file" ? "" : "'" + text + "': allowed natural or file";
          },
          "natural|file"));
}

namespace {

// A preset's file, or "" when the argument names none.
std::string presetFile(const std::string& name) {
  if (name.find('/') != std::string::npos) return "";
  for (const auto& [folder, extension] : kPresetFolders) {
    const fs::path preset = fs::path(assetDirectory()) / folder / (name + extension);
    std::error_code ec;
    if (fs::is_regular_file(preset, ec)) return preset.string();
  }
  return "";
}

[[noreturn]] void neitherFileNorPreset(const std::string& argument, const std::string& files) {
  // A path (a folder or an extension in it) is a file the user meant, not a preset name mistyped.
  if (argument.find('/') != std::string::npos || fs::path(argument).has_extension())
    throw InputError(argument, "(argument)", "no such file (expected " + files + ", or a preset name)");
  std::string list;
  for (const std::string& name : presetNames()) list += (list.empty() ? "" : ", ") + name;
  throw InputError(argument, "(argument)", "is neither " + files + " nor a preset; presets: " + list);
}

}  // namespace

TreeModel loadModelArgument(const std::string& presetOrFile, ImportNotes* notes, AngleChoice angles) {
  const ModelReadOptions options{angles == AngleChoice::Natural, notes};
  if (inputExists(presetOrFile)) return loadModelFile(presetOrFile, options);
  if (const std::string preset = presetFile(presetOrFile); !preset.empty()) return loadModelFile(preset, options);
  neitherFileNorPreset(presetOrFile, "a model file (.json, .xml)");
}

TreeSource loadTreeArgument(const std::string& presetOrFile, ImportNotes* notes, AngleChoice angles) {
  const ModelReadOptions options{angles == AngleChoice::Natural, notes};
  if (inputExists(presetOrFile)) return loadTreeSource(presetOrFile, options);
  if (const std::string preset = presetFile(presetOrFile); !preset.empty()) return TreeSource(loadModelFile(preset, options));
  neitherFileNorPreset(presetOrFile, "a model, skeleton or graph file (.json, .xml)");
}

}  // namespace arbor::cli
