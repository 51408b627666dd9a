#pragma once
// A tree's mesh written as the file its extension names (.obj quads y up, .gltf, .glb), atomically: what
// `generate` writes and what the viewer's panel exports.
#include <string>

#include "export/obj_export.hpp"
#include "mesh/quad_mesh.hpp"

namespace arbor::cli {

// True for .obj, .gltf and .glb.
bool isMeshFile(const std::string& path);

struct MeshFileOptions {
  bool triangles = false;  // .obj: two triangles per quad
  Up up = Up::Y;           // .obj: the up axis (glTF is y up by its specification)
};

// Throws InputError(path, field) for any other extension; nothing is written then.
void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, const MeshFileOptions& options = {},
                   const std::string& field = "--out");

}  // namespace arbor::cli
