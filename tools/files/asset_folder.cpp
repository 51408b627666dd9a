#include "asset_folder.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "common/input_error.hpp"

namespace arbor {

namespace fs = std::filesystem;

namespace {

// Where presets live: species and other model files, then L-system grammars.
constexpr std::pair<const char*, const char*> kPresetFolders[] = {{"presets", ".json"}, {"lsystems", ".lsys"}};

}  // namespace

fs::path programFolder() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

std::string assetDirectory() {
  if (const char* env = std::getenv("ARBOR_ASSETS"); env && *env) {
    if (!fs::is_directory(fs::path(env) / "presets")) throw InputError(env, "ARBOR_ASSETS", "has no presets/ folder; point it at Arbor's assets");
    return env;
  }
  std::vector<fs::path> candidates;
  std::error_code ec;
  if (const fs::path bin = programFolder(); !bin.empty()) {
    candidates = {bin.parent_path() / "share" / "arbor", bin / "assets", bin.parent_path() / "assets"};
  }
  candidates.emplace_back(ARBOR_ASSET_DIR);
  std::string looked;
  for (const fs::path& candidate : candidates) {
    if (fs::is_directory(candidate / "presets", ec)) return candidate.string();
    looked += (looked.empty() ? "" : ", ") + candidate.string();
  }
  throw InputError("assets", "ARBOR_ASSETS", "no assets folder with presets found (looked in " + looked + "); install Arbor or set ARBOR_ASSETS");
}

std::vector<std::string> presetNames() {
  const fs::path assets = assetDirectory();
  std::vector<std::string> names;
  for (const auto& [folder, extension] : kPresetFolders) {
    std::vector<std::string> here;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(assets / folder, ec)) {
      if (entry.path().extension() == extension) here.push_back(entry.path().stem().string());
    }
    std::sort(here.begin(), here.end());
    names.insert(names.end(), here.begin(), here.end());
  }
  return names;
}

std::string presetFile(const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos) return "";
  const fs::path assets = assetDirectory();
  for (const auto& [folder, extension] : kPresetFolders) {
    const fs::path preset = assets / folder / (name + extension);
    std::error_code ec;
    if (fs::is_regular_file(preset, ec)) return preset.string();
  }
  return "";
}

}  // namespace arbor
