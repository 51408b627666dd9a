#pragma once
// The export options every command that writes a tree offers (generate, mesh, grow), checked against the file.
#include <string>

#include <CLI/CLI.hpp>

#include "files/tree_file.hpp"
#include "mesh/mesh_options.hpp"

namespace arbor::cli {

// What a user chooses about a tree file on the command line (generate, mesh, grow).
struct ExportChoices {
  int lods = 0;  // 0: the default (one)
  bool noLeaves = false, noCards = false, noTextures = false;
  bool triangles = false;
  std::string up = "y";
  WindSettings wind;  // strength 0: no wind animation
  int windFrames = 24;
};

// --wind, --wind-azimuth and --gust-frequency (generate, mesh, grow, render, view); `effect` says what the
// wind does in this command.
void addWindOptions(CLI::App* cmd, WindSettings& wind, const std::string& effect);

// --lods, --no-leaves, --no-cards, --no-textures, --triangles, --up and the wind animation's options.
void addExportOptions(CLI::App* cmd, ExportChoices& choices);

// The options for `path` from those choices: the defaults (TreeFileOptions{}) with the user's changes. Throws InputError
// naming the option when one does not apply to that file type (--lods above 1 or --triangles on glTF, --up
// on glTF). `mesh` and `subdivide` go to every level of detail.
TreeFileOptions treeFileOptions(const std::string& path, const ExportChoices& choices, const MeshOptions& mesh = {}, int subdivide = 0);

}  // namespace arbor::cli
