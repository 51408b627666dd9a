#include "tree_file.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "assets.hpp"
#include "cli_values.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "export/gltf_export.hpp"
#include "export/obj_export.hpp"
#include "image/bark_texture.hpp"
#include "image/png_io.hpp"

namespace arbor::cli {

namespace {

// The bark's normal map: black to white in the height map is this many texels of relief (gentle, as the colour
// map already darkens the fissures).
constexpr double kBarkRelief = 6.0;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the texture (is the assets folder complete?)");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void requireMeshFile(const std::string& path, const std::string& field) {
  if (!isMeshFile(path)) throw InputError(path, field, "a mesh is written as .obj, .gltf or .glb");
}

}  // namespace

bool isMeshFile(const std::string& path) { return endsWith(path, ".obj") || endsWith(path, ".gltf") || endsWith(path, ".glb"); }

TreeFileOptions defaultTreeFileOptions() {
  TreeFileOptions options;
  options.asset.lods = 1;  // Blender imports every node of a glTF, coarser levels of detail on top of the finest
  return options;
}

void addExportOptions(CLI::App* cmd, ExportChoices& c) {
  cmd->add_option("--lods", c.lods,
                  "Levels of detail in a .gltf/.glb: the finest node names the coarser ones by MSFT_lod, each fakes one more stem "
                  "level as branch cards (engines pick one; Blender imports them all, one over another); an OBJ holds one")
      ->check(Whole(1, 8));
  cmd->add_flag("--no-leaves", c.noLeaves, "Leave the leaf cards out of a mesh file");
  cmd->add_flag("--no-cards", c.noCards, "Leave out the fake-branch cards (the stem levels not meshed, and stubs)");
  cmd->add_flag("--no-textures", c.noTextures,
                "No textures: glTF materials get flat colours; OBJ gets no .mtl and no PNG files beside it");
  cmd->add_flag("--triangles", c.triangles, "Write triangles instead of quads to .obj");
  cmd->add_option("--up", c.up, "The .obj's up axis: y (as Blender and most tools import OBJ) or z (Arbor's own axes)")
      ->check(CLI::IsMember({"y", "z"}))
      ->capture_default_str();
}

TreeFileOptions treeFileOptions(const std::string& path, const ExportChoices& c, const MeshOptions& mesh, int subdivide) {
  TreeFileOptions options = defaultTreeFileOptions();
  const bool obj = endsWith(path, ".obj");
  if (c.up != "y" && !obj) {
    throw InputError(path, "--up", "applies to .obj only (glTF is y up by its specification; the skeleton keeps Arbor's z up)");
  }
  if (c.triangles && !obj) {
    throw InputError(path, "--triangles", "applies to .obj only (glTF and GLB always hold triangles; a skeleton none)");
  }
  if (c.lods > 1 && obj) throw InputError(path, "--lods", "an OBJ holds one level of detail; levels of detail need .gltf or .glb");
  options.file = MeshFileOptions{c.triangles, c.up == "z" ? Up::Z : Up::Y};
  if (c.lods > 0) options.asset.lods = c.lods;
  options.asset.leaves = !c.noLeaves;
  options.asset.branchCards = !c.noCards;
  options.asset.mesh = mesh;
  options.asset.subdivide = subdivide;
  options.textures = !c.noTextures;
  return options;
}

AssetTextures exportTextures() {
  const std::string dir = assetDirectory() + "/textures/";
  AssetTextures textures;
  textures.barkColor = readBytes(dir + "bark_color.png");
  textures.barkNormal = encodePng(normalMapFromHeight(readPng(dir + "bark_height.png"), kBarkRelief));
  textures.leafAtlas = readBytes(dir + "leaf_atlas.png");
  return textures;
}

void writeTreeFile(const std::string& path, const Skeleton& skeleton, const std::string& name, const TreeFileOptions& options,
                   const QuadMesh* finest, const std::function<void(const std::string&)>& progress, const std::string& field) {
  requireMeshFile(path, field);
  const bool obj = endsWith(path, ".obj");
  TreeAssetOptions assetOptions = options.asset;
  if (obj) assetOptions.lods = 1;
  TreeAsset asset = makeTreeAsset(skeleton, name, assetOptions, finest, progress);
  if (options.textures) asset.textures = exportTextures();
  if (progress) progress("writing " + path);
  if (!obj) {
    writeFileAtomically(path, endsWith(path, ".gltf") ? writeGltf(asset) : writeGlb(asset));
    return;
  }
  namespace fs = std::filesystem;
  const fs::path file(path);
  const std::string stem = file.stem().string();
  const fs::path folder = file.parent_path();
  std::string mtl;
  if (options.textures) {
    // The maps first, the OBJ naming them last: a reader never finds an OBJ whose textures are still missing.
    const std::string color = stem + "_bark_color.png", normal = stem + "_bark_normal.png", atlas = stem + "_leaf_atlas.png";
    writeFileAtomically((folder / color).string(), asset.textures.barkColor);
    writeFileAtomically((folder / normal).string(), asset.textures.barkNormal);
    writeFileAtomically((folder / atlas).string(), asset.textures.leafAtlas);
    mtl = stem + ".mtl";
    writeFileAtomically((folder / mtl).string(), writeMtl(color, normal, atlas));
  }
  const AssetLod& lod = asset.lods.front();
  writeFileAtomically(path, [&](std::ostream& out) {
    writeObj(lod.bark, options.file.triangles, out, options.file.up, mtl);
    std::size_t vertices = lod.bark.vertexCount();
    if (!lod.branchCards.empty()) {
      writeObjCards(lod.branchCards, "branch_cards", mtl.empty() ? "" : "branch_cards", vertices, out, options.file.up);
      vertices += lod.branchCards.positions.size();
    }
    if (!asset.leaves.empty()) writeObjCards(asset.leaves, "leaves", mtl.empty() ? "" : "leaves", vertices, out, options.file.up);
  });
}

}  // namespace arbor::cli
