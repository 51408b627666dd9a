#include "tree_io.hpp"

#include <filesystem>

#include "common/atomic_file.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "files/asset_folder.hpp"
#include "growth/growth_models.hpp"
#include "growth/skeleton_json.hpp"

namespace arbor::python {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFileKinds = "a model file (.json, .xml, .lsys), an arbor-skeleton/1 or arbor-graph/1 .json file, or a preset name";

}  // namespace

TreeSource loadSource(const std::string& presetOrFile, ImportNotes* notes) {
  const ModelReadOptions options{false, notes};
  if (inputExists(presetOrFile)) return loadTreeSource(presetOrFile, options);
  if (const std::string preset = presetFile(presetOrFile); !preset.empty()) return TreeSource(loadModelFile(preset, options));
  // A folder or an extension in the argument: a file the caller meant, not a preset name mistyped.
  if (presetOrFile.find('/') != std::string::npos || fs::path(presetOrFile).has_extension())
    throw MissingFile(presetOrFile, "source", std::string("no such file (expected ") + kFileKinds + ")");
  std::string list;
  for (const std::string& name : presetNames()) list += (list.empty() ? "" : ", ") + name;
  const std::string close = closestName(presetOrFile, presetNames());
  throw InputError(presetOrFile, "source",
                   std::string("is neither a file nor a preset") + (close.empty() ? "" : " (did you mean '" + close + "'?)") + "; presets: " + list);
}

TreeSource sourceFromJson(const std::string& json, const std::string& label, ImportNotes* notes) {
  // The model reader tells model files apart by their extension; the label only names the text in errors.
  const std::string file = label + ".json";
  try {
    return TreeSource(readModelFile(json, file, ModelReadOptions{false, notes}));
  } catch (const InputError& e) {
    if (e.file() != file) throw;
    // "<label>.json: field 'F': message" -> "<label>: field 'F': message": no file of that name exists.
    const std::string prefix = file + ": field '" + e.field() + "': ";
    const std::string what = e.what();
    throw InputError(label, e.field(), what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
}

bool isSkeletonFile(const std::string& path) { return endsWith(path, ".json"); }

void writeSkeletonFile(const std::string& path, const Skeleton& skeleton) {
  writeFileAtomically(path, [&](std::ostream& out) { writeSkeletonJson(skeleton, out); });
}

}  // namespace arbor::python
