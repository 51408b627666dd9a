#include "export_options.hpp"

#include "cli_values.hpp"
#include "common/input_error.hpp"
#include "common/text_util.hpp"

namespace arbor::cli {

void addWindOptions(CLI::App* cmd, WindSettings& wind, const std::string& effect) {
  cmd->add_option("--wind", wind.strength, "Wind strength (docs/wind.md): 0 still, 1 a strong breeze; " + effect)
      ->check(Number(0.0, 4.0))
      ->capture_default_str();
  cmd->add_option("--wind-azimuth", wind.azimuth, "Where the wind blows towards, degrees from +x counter-clockwise (Arbor's axes)")
      ->check(Number(-360.0, 360.0))
      ->capture_default_str();
  cmd->add_option("--gust-frequency", wind.gustFrequency, "Gusts per second; every motion repeats after one gust period")
      ->check(Number(0.02, 4.0))
      ->capture_default_str();
}

void addExportOptions(CLI::App* cmd, ExportChoices& c) {
  cmd->add_option("--lods", c.lods,
                  "Levels of detail in a .gltf/.glb: the finest node names the coarser ones by MSFT_lod, each fakes one more stem "
                  "level as branch cards (engines pick one; Blender imports them all, one over another); an OBJ holds one")
      ->check(Whole(1, 8));
  cmd->add_flag("--no-leaves", c.noLeaves, "Leave the leaf cards out of a mesh file");
  cmd->add_flag("--no-cards", c.noCards, "Leave out the fake-branch cards (the stem levels not meshed, stubs, and twigs the mesh could not join near their attachment)");
  cmd->add_flag("--no-textures", c.noTextures,
                "No textures: glTF materials get flat colours; OBJ gets no .mtl and no PNG files beside it");
  cmd->add_flag("--triangles", c.triangles, "Write triangles instead of quads to .obj");
  addWindOptions(cmd, c.wind, "above 0, a .gltf/.glb holds a wind animation (morph targets, one loop of gusts)");
  cmd->add_option("--wind-frames", c.windFrames, "Keyframes (morph targets) per loop")->check(Whole(4, 120))->capture_default_str();
  cmd->add_option("--up", c.up, "The .obj's up axis: y (as Blender and most tools import OBJ) or z (Arbor's own axes)")
      ->check(CLI::IsMember({"y", "z"}))
      ->capture_default_str();
}

TreeFileOptions treeFileOptions(const std::string& path, const ExportChoices& c, const MeshOptions& mesh, int subdivide) {
  TreeFileOptions options;
  const bool obj = endsWith(path, ".obj");
  if (c.up != "y" && !obj) {
    throw InputError(path, "--up", "applies to .obj only (glTF is y up by its specification; the skeleton keeps Arbor's z up)");
  }
  if (c.triangles && !obj) {
    throw InputError(path, "--triangles", "applies to .obj only (glTF and GLB always hold triangles; a skeleton none)");
  }
  if (c.lods > 1 && obj) throw InputError(path, "--lods", "an OBJ holds one level of detail; levels of detail need .gltf or .glb");
  if (c.wind.on() && obj) throw InputError(path, "--wind", "an OBJ cannot hold an animation; the wind animation needs .gltf or .glb");
  options.file = MeshFileOptions{c.triangles, c.up == "z" ? Up::Z : Up::Y};
  if (c.lods > 0) options.asset.lods = c.lods;
  options.asset.leaves = !c.noLeaves;
  options.asset.branchCards = !c.noCards;
  options.asset.mesh = mesh;
  options.asset.subdivide = subdivide;
  options.textures = !c.noTextures;
  options.asset.wind = c.wind;
  options.asset.windFrames = c.windFrames;
  return options;
}

}  // namespace arbor::cli
