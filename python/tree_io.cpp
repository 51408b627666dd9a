#include "tree_io.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "common/atomic_file.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "export/gltf_export.hpp"
#include "growth/growth_models.hpp"
#include "growth/skeleton_json.hpp"

namespace arbor::python {

namespace fs = std::filesystem;

namespace {

// Where presets live, as the CLI has them: model files, then L-system grammars.
constexpr std::pair<const char*, const char*> kPresetFolders[] = {{"presets", ".json"}, {"lsystems", ".lsys"}};

constexpr const char* kFileKinds = "a model file (.json, .xml, .lsys), an arbor-skeleton/1 or arbor-graph/1 .json file, or a preset name";

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

}  // namespace

std::string assetDirectory() {
  if (const char* env = std::getenv("ARBOR_ASSETS"); env && *env) {
    if (!fs::is_directory(fs::path(env) / "presets")) throw InputError(env, "ARBOR_ASSETS", "has no presets/ folder; point it at Arbor's assets");
    return env;
  }
  std::error_code ec;
  if (fs::is_directory(fs::path(ARBOR_ASSET_DIR) / "presets", ec)) return ARBOR_ASSET_DIR;
  throw InputError(ARBOR_ASSET_DIR, "ARBOR_ASSETS",
                   "the assets this module was built with are gone (no presets/ folder); set ARBOR_ASSETS to Arbor's assets folder");
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

MeshFileType meshFileType(const std::string& path, const std::string& field) {
  if (endsWith(path, ".obj")) return MeshFileType::Obj;
  if (endsWith(path, ".gltf")) return MeshFileType::Gltf;
  if (endsWith(path, ".glb")) return MeshFileType::Glb;
  throw InputError(path, field, "a tree is written as .obj, .gltf or .glb (the mesh) or .json (the skeleton)");
}

void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, Up up) {
  switch (meshFileType(path, "path")) {
    case MeshFileType::Obj: writeFileAtomically(path, [&](std::ostream& out) { writeObj(mesh, false, out, up); }); break;
    case MeshFileType::Gltf: writeFileAtomically(path, writeGltf(mesh, name)); break;
    case MeshFileType::Glb: writeFileAtomically(path, writeGlb(mesh, name)); break;
  }
}

void writeSkeletonFile(const std::string& path, const Skeleton& skeleton) {
  writeFileAtomically(path, [&](std::ostream& out) { writeSkeletonJson(skeleton, out); });
}

}  // namespace arbor::python
