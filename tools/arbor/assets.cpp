#include "assets.hpp"

#include <filesystem>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "growth/growth_models.hpp"

namespace arbor::cli {

namespace fs = std::filesystem;

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
