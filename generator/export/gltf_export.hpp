#pragma once
// glTF 2.0 for viewers and engines: the mesh triangulated, converted from Arbor's z-up to glTF's y-up.
//
// One scene, one node, one mesh with one primitive (uint32 indices) and a plain PBR bark material.
// Attributes: POSITION, NORMAL, TANGENT (w = 1), TEXCOORD_0 (u, v), and the application-specific
// _RADIUS, _LEVEL and _FLIP (float scalars: branch radius, stem level, flip coordinate uvw.z).
// Normals and tangents are made unit length and orthogonal, as the Khronos validator demands.
#include <string>

#include "mesh/quad_mesh.hpp"

namespace arbor {

// A self-contained .gltf: JSON with the binary buffer embedded as a base64 data URI.
// Needs every attribute for every vertex and at least one quad; throws std::invalid_argument otherwise.
std::string writeGltf(const QuadMesh& mesh, const std::string& name);

// The same asset as binary .glb bytes: 12-byte header, JSON chunk, BIN chunk. Same requirements.
std::string writeGlb(const QuadMesh& mesh, const std::string& name);

}  // namespace arbor
