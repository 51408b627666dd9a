#pragma once
// What the Python module needs beyond the shared files library (tools/files: assets, tree files): a source
// named by preset, path or parameters with Python's kinds of error, and the skeleton file.
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "export/obj_export.hpp"
#include "files/asset_folder.hpp"
#include "files/tree_file.hpp"
#include "growth/growth_model.hpp"
#include "mesh/quad_mesh.hpp"
#include "tree/tree_source.hpp"

namespace arbor::python {

// A path the caller gave that does not exist (Python: FileNotFoundError rather than ValueError).
class MissingFile : public InputError {
 public:
  using InputError::InputError;
};

using arbor::assetDirectory;
using arbor::presetNames;

// A file that exists (a model .json/.xml/.lsys, an arbor-skeleton/1 or arbor-graph/1 .json), else a preset
// name. A path-like argument that names nothing throws MissingFile; an unknown name lists the presets.
TreeSource loadSource(const std::string& presetOrFile, ImportNotes* notes);

// Model parameters given as JSON text (a Python dict, serialised), read by the same reader as model files.
// Errors name `label` as their file.
TreeSource sourceFromJson(const std::string& json, const std::string& label, ImportNotes* notes);

// The file's kind by extension: .json (the skeleton, as `arbor generate --out x.json`), or a mesh file (.obj,
// .gltf, .glb: files/tree_file.hpp writes them).
bool isSkeletonFile(const std::string& path);
// The skeleton as arbor-skeleton/1 JSON (what grow() and the CLI read back as the same tree), atomically.
void writeSkeletonFile(const std::string& path, const Skeleton& skeleton);

}  // namespace arbor::python
