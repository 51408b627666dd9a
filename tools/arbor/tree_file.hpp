#pragma once
// A tree written as the file its extension names, atomically: what `generate` writes and what the viewer's panel
// exports. glTF/GLB hold the complete asset (levels of detail, leaf and fake-branch cards, textures inside);
// OBJ holds the finest level with its cards, and a .mtl with the textures as PNG files beside it.
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "export/obj_export.hpp"
#include "export/tree_asset.hpp"
#include "growth/skeleton.hpp"
#include "mesh/quad_mesh.hpp"

namespace arbor::cli {

// True for .obj, .gltf and .glb.
bool isMeshFile(const std::string& path);

struct MeshFileOptions {
  bool triangles = false;  // .obj: two triangles per quad
  Up up = Up::Y;           // .obj: the up axis (glTF is y up by its specification)
};

struct TreeFileOptions {
  MeshFileOptions file;
  TreeAssetOptions asset;  // asset.lods: levels of detail in a glTF/GLB (an OBJ holds the finest only)
  bool textures = true;    // bark colour, bark normal map and leaf atlas from the assets' textures
};

// The export defaults: one level of detail; leaves, cards and textures on.
TreeFileOptions defaultTreeFileOptions();

// What a user chooses about a tree file on the command line (generate, mesh, grow).
struct ExportChoices {
  int lods = 0;  // 0: the default (one)
  bool noLeaves = false, noCards = false, noTextures = false;
  bool triangles = false;
  std::string up = "y";
};

// --lods, --no-leaves, --no-cards, --no-textures, --triangles and --up.
void addExportOptions(CLI::App* cmd, ExportChoices& choices);

// The options for `path` from those choices: defaultTreeFileOptions with the user's changes. Throws InputError
// naming the option when one does not apply to that file type (--lods above 1 or --triangles on glTF, --up
// on glTF). `mesh` and `subdivide` go to every level of detail.
TreeFileOptions treeFileOptions(const std::string& path, const ExportChoices& choices, const MeshOptions& mesh = {}, int subdivide = 0);

// The bark colour, a normal map made from the bark height and the leaf atlas, as PNG bytes, from assets/textures.
AssetTextures exportTextures();

// Builds the asset (makeTreeAsset; `finest`: the finest level's coarse mesh when the caller has built it) and
// writes it. OBJ: `stem.mtl` and `stem_bark_color.png`, `stem_bark_normal.png`, `stem_leaf_atlas.png` beside it
// when textures are on. Throws InputError(path, field) for an extension that is not a mesh file, before anything
// is built or written. `progress` hears each step that may take a while.
void writeTreeFile(const std::string& path, const Skeleton& skeleton, const std::string& name, const TreeFileOptions& options,
                   const QuadMesh* finest = nullptr, const std::function<void(const std::string&)>& progress = {},
                   const std::string& field = "--out");

}  // namespace arbor::cli
