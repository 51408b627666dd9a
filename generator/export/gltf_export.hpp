#pragma once
// glTF 2.0 for viewers and engines: a tree asset triangulated, converted from Arbor's z-up to glTF's y-up.
//
// One scene whose node is the finest level of detail; coarser ones are further nodes named by the MSFT_lod
// extension (with MSFT_screencoverage in its extras). Each level's mesh has the bark primitive, a fake-branch
// card primitive (double-sided bark) where it has cards, and the leaf cards (alpha-masked, double-sided, the
// same accessors in every level). Bark attributes: POSITION, NORMAL, TANGENT (along +u, w the handedness the
// normal map needs), TEXCOORD_0 (u, v: tiles along the branch with the sampler's repeat), and the
// application-specific _RADIUS, _LEVEL and _FLIP (branch radius, stem level, flip coordinate uvw.z). Textures
// are PNG images in the buffer. Normals and tangents are unit length and orthogonal, as the validator demands.
#include <string>

#include "mesh/quad_mesh.hpp"
#include "tree_asset.hpp"

namespace arbor {

// A self-contained .gltf: JSON with the binary buffer (and the images in it) embedded as a base64 data URI.
// Throws std::invalid_argument for a mesh it cannot describe (missing attributes, no faces, non-finite values).
std::string writeGltf(const TreeAsset& tree);

// The same asset as binary .glb bytes: 12-byte header, JSON chunk, BIN chunk.
std::string writeGlb(const TreeAsset& tree);

// A bark mesh alone (barkOnlyAsset). A self-contained .gltf: JSON with the binary buffer embedded as a base64 data URI.
// Needs every attribute for every vertex and at least one quad; throws std::invalid_argument otherwise.
std::string writeGltf(const QuadMesh& mesh, const std::string& name);

// The same asset as binary .glb bytes: 12-byte header, JSON chunk, BIN chunk. Same requirements.
std::string writeGlb(const QuadMesh& mesh, const std::string& name);

}  // namespace arbor
