#include "tree_file.hpp"

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "export/gltf_export.hpp"
#include "export/obj_export.hpp"

namespace arbor::cli {

bool isMeshFile(const std::string& path) { return endsWith(path, ".obj") || endsWith(path, ".gltf") || endsWith(path, ".glb"); }

void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, const MeshFileOptions& options,
                   const std::string& field) {
  if (endsWith(path, ".obj")) writeFileAtomically(path, [&](std::ostream& out) { writeObj(mesh, options.triangles, out, options.up); });
  else if (endsWith(path, ".gltf")) writeFileAtomically(path, writeGltf(mesh, name));
  else if (endsWith(path, ".glb")) writeFileAtomically(path, writeGlb(mesh, name));
  else throw InputError(path, field, "a mesh is written as .obj, .gltf or .glb");
}

}  // namespace arbor::cli
