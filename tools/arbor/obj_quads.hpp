#pragma once
// Reading an OBJ file of quads back (for `arbor check`): positions and faces only; any other face, a bad
// number or index, or a statement that is not geometry is an InputError naming the file and the line.
#include <string>

#include "mesh/quad_mesh.hpp"

namespace arbor::cli {

// OBJ files up to this size are read whole (2.5 M quads with texture coordinates and normals fit).
constexpr std::size_t kMaxObjBytes = 1024 * 1024 * 1024;

QuadMesh readObjQuads(const std::string& path);

// The same from text already read; `file` names it in messages.
QuadMesh parseObjQuads(const std::string& text, const std::string& file);

}  // namespace arbor::cli
