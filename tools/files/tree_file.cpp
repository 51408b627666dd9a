#include "tree_file.hpp"

#include <atomic>
#include <filesystem>
#include <future>
#include <vector>

#include "asset_folder.hpp"
#include "common/atomic_file.hpp"
#include "common/background_thread.hpp"
#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "export/gltf_export.hpp"
#include "export/obj_export.hpp"

namespace arbor {

namespace {

void requireMeshFile(const std::string& path, const std::string& field) {
  if (!isMeshFile(path)) throw InputError(path, field, "a mesh is written as .obj, .gltf or .glb");
}

}  // namespace

bool isMeshFile(const std::string& path) { return endsWith(path, ".obj") || endsWith(path, ".gltf") || endsWith(path, ".glb"); }

void writeMeshFile(const std::string& path, const QuadMesh& mesh, const std::string& name, const MeshFileOptions& options,
                   const std::string& field) {
  requireMeshFile(path, field);
  if (endsWith(path, ".obj")) writeFileAtomically(path, [&](std::ostream& out) { writeObj(mesh, options.triangles, out, options.up); });
  else if (endsWith(path, ".gltf")) writeFileAtomically(path, writeGltf(mesh, name));
  else writeFileAtomically(path, writeGlb(mesh, name));
}

namespace {

// The texture files every export carries, in AssetTextures' order; `arbor textures` makes the normal map from the
// height map.
constexpr const char* kTextureFiles[3] = {"bark_color.png", "bark_normal.png", "leaf_atlas.png"};

std::string textureFolder() { return assetDirectory() + "/textures/"; }

}  // namespace

AssetTextures exportTextures() {
  const std::string folder = textureFolder();
  AssetTextures textures;
  textures.barkColor = readFile(folder + kTextureFiles[0]);
  textures.barkNormal = readFile(folder + kTextureFiles[1]);
  textures.leafAtlas = readFile(folder + kTextureFiles[2]);
  return textures;
}

void writeTreeFile(const std::string& path, const Skeleton& skeleton, const std::string& name, const TreeFileOptions& options,
                   std::shared_ptr<const TreeMesh> finest, const std::function<void(const std::string&)>& progress, const std::string& field) {
  requireMeshFile(path, field);
  const bool obj = endsWith(path, ".obj");
  TreeAssetOptions assetOptions = options.asset;
  if (obj) {
    assetOptions.lods = 1;
    assetOptions.leaves = false;  // the OBJ writer makes the cards as it prints them
    assetOptions.branchCards = false;
  }
  namespace fs = std::filesystem;
  const fs::path file(path);
  const std::string stem = file.stem().string();
  const fs::path folder = file.parent_path();
  const std::string mtl = obj && options.textures ? stem + ".mtl" : std::string();
  // A glTF's texture files are read, an OBJ's copied beside it by the kernel (under temporary names) and its leaf
  // lines printed, while the tree is meshed.
  std::future<AssetTextures> textures;
  if (options.textures && !obj) textures = std::async(std::launch::async, exportTextures);
  std::future<std::vector<StagedFile>> maps;
  if (options.textures && obj) {
    maps = std::async(std::launch::async, [&] {
      const std::string source = textureFolder();
      std::string names[3];
      std::vector<StagedFile> staged;
      for (std::size_t i = 0; i < 3; ++i) {
        names[i] = stem + "_" + kTextureFiles[i];
        staged.push_back(stageCopy(source + kTextureFiles[i], (folder / names[i]).string()));
      }
      staged.push_back(stageFile((folder / mtl).string(), [&](std::ostream& out) { out << writeMtl(names[0], names[1], names[2]); }));
      return staged;
    });
  }
  const std::vector<Leaf> noLeaves;
  std::atomic<bool> meshed{false};
  std::future<std::shared_ptr<const ObjLeafLines>> leafLines;
  if (obj) {
    leafLines = std::async(std::launch::async,
                           [&] {
                             runInBackground();
                             return printObjLeafLines(options.asset.leaves ? skeleton.leaves : noLeaves, options.file.up, [&] { return meshed.load(); }); });
  }
  struct Meshed {
    std::atomic<bool>& flag;
    ~Meshed() { flag = true; }  // on an error too: the printer stops at its next block instead of printing them all
  } meshedOnExit{meshed};
  TreeAsset asset = makeTreeAsset(skeleton, name, assetOptions, std::move(finest), progress);
  meshed = true;
  if (textures.valid()) asset.textures = textures.get();
  if (progress) progress("writing " + path);
  if (!obj) {
    writeFileAtomically(path, endsWith(path, ".gltf") ? writeGltf(asset) : writeGlb(asset));
    return;
  }
  const AssetLod& lod = asset.lods.front();
  const std::shared_ptr<const ObjLeafLines> leaves = leafLines.get();
  // Stubs are never meshed, so their cards are there whatever the levels (wheat's grains).
  const std::vector<ImpostorSegment> segments =
      options.asset.branchCards ? leftOutSegments(skeleton, lod.meshedLevels, lod.fakedStems) : std::vector<ImpostorSegment>{};
  StagedFile written = stageFile(path, [&](std::ostream& out) { writeObjAsset(*lod.bark, segments, *leaves, options.file.triangles, out, options.file.up, mtl); });
  // Every file whole before any is put in place (a full disk leaves none of them), then the maps and the .mtl, the
  // OBJ naming them last: a reader never finds an OBJ whose textures are still missing.
  if (maps.valid())
    for (StagedFile& staged : maps.get()) staged.commit();
  written.commit();
}

}  // namespace arbor
