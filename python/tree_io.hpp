#pragma once
// What the Python module needs from the command line's world without linking it (tools/arbor pulls in
// Vulkan): where the presets are, a source named by preset, path or parameters, and a mesh written as the
// file its extension names. Small equivalents of tools/arbor/assets.cpp and tree_file.cpp, same rules.
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "export/obj_export.hpp"
#include "growth/growth_model.hpp"
#include "mesh/quad_mesh.hpp"
#include "tree/tree_source.hpp"

namespace arbor::python {

// A path the caller gave that does not exist (Python: FileNotFoundError rather than ValueError).
class MissingFile : public InputError {
 public:
  using InputError::InputError;
};

// $ARBOR_ASSETS when set (it must hold presets/), else the source tree's assets/ the module was built from.
// Throws InputError when neither has presets: never an empty preset list.
std::string assetDirectory();

// As `arbor species --list`: assets/presets/*.json, then assets/lsystems/*.lsys, each group sorted.
std::vector<std::string> presetNames();

// A file that exists (a model .json/.xml/.lsys, an arbor-skeleton/1 or arbor-graph/1 .json), else a preset
// name. A path-like argument that names nothing throws MissingFile; an unknown name lists the presets.
TreeSource loadSource(const std::string& presetOrFile, ImportNotes* notes);

// Model parameters given as JSON text (a Python dict, serialised), read by the same reader as model files.
// Errors name `label` as their file.
TreeSource sourceFromJson(const std::string& json, const std::string& label, ImportNotes* notes);

// The file's kind by extension: .json (the skeleton, as `arbor generate --out x.json`), .obj, .gltf, .glb.
// meshFileType throws InputError(path, field) for anything but the three mesh files.
bool isSkeletonFile(const std::string& path);
enum class MeshFileType { Obj, Gltf, Glb };
MeshFileType meshFileType(const std::string& path, const std::string& field);

// The one place the module writes a mesh (atomically): OBJ quads with `up` as its up axis, glTF/GLB y up.
void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, Up up);

// The skeleton as arbor-skeleton/1 JSON (what grow() and the CLI read back as the same tree), atomically.
void writeSkeletonFile(const std::string& path, const Skeleton& skeleton);

}  // namespace arbor::python
