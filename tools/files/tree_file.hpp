#pragma once
// A tree written as the file its extension names, atomically: what `generate` writes, what the viewer's panel
// exports and what the Python module's Tree.export writes. glTF/GLB hold the complete asset (levels of detail, leaf and fake-branch cards, textures inside);
// OBJ holds the finest level with its cards, and a .mtl with the textures as PNG files beside it.
#include <functional>
#include <string>

#include "export/obj_export.hpp"
#include "export/tree_asset.hpp"
#include "growth/skeleton.hpp"
#include "mesh/quad_mesh.hpp"

namespace arbor {

// True for .obj, .gltf and .glb.
bool isMeshFile(const std::string& path);

struct MeshFileOptions {
  bool triangles = false;  // .obj: two triangles per quad
  Up up = Up::Y;           // .obj: the up axis (glTF is y up by its specification)
};

// A bare quad mesh (no cards, no textures) as the file the extension names: .obj quads, .gltf, .glb. Throws
// InputError(path, field) for any other extension; nothing is written then.
void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, const MeshFileOptions& options = {},
                   const std::string& field = "--out");

struct TreeFileOptions {
  MeshFileOptions file;
  // asset.lods: levels of detail in a glTF/GLB, one by default (Blender imports every node, the coarser ones
  // on top of the finest); an OBJ holds the finest only. Leaves and cards on by default.
  TreeAssetOptions asset;
  bool textures = true;    // bark colour, bark normal map and leaf atlas from the assets' textures
};

// The bark colour, a normal map made from the bark height and the leaf atlas, as PNG bytes, from assets/textures.
AssetTextures exportTextures();

// Builds the asset (makeTreeAsset; `finest`: the finest level's coarse mesh when the caller has built it, shared) and
// writes it. OBJ: `stem.mtl` and `stem_bark_color.png`, `stem_bark_normal.png`, `stem_leaf_atlas.png` beside it
// when textures are on. Throws InputError(path, field) for an extension that is not a mesh file, before anything
// is built or written. `progress` hears each step that may take a while.
void writeTreeFile(const std::string& path, const Skeleton& skeleton, const std::string& name, const TreeFileOptions& options,
                   std::shared_ptr<const TreeMesh> finest = nullptr, const std::function<void(const std::string&)>& progress = {},
                   const std::string& field = "--out");

}  // namespace arbor
