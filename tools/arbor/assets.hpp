#pragma once
// Presets and files named on the command line; where the assets are is files/asset_folder.hpp.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "files/asset_folder.hpp"
#include "growth/growth_model.hpp"
#include "tree/tree_source.hpp"

namespace arbor::cli {

using arbor::assetDirectory;
using arbor::presetNames;

// Which angles a loaded species follows: the file's own (an Arbaro XML file's DownAngle and SplitAngle, a JSON
// file's AngleRule) or Murray's natural angles whatever the file says.
enum class AngleChoice { File, Natural };

// --angles natural|file on a command that loads species; a bad value is a usage error (exit 2) naming both.
void addAnglesOption(CLI::App* cmd, AngleChoice& angles);

// A path that exists is read as a model file (any growth model, or an Arbaro species); otherwise the argument
// must name a preset. Throws InputError naming the argument and the presets on offer.
TreeModel loadModelArgument(const std::string& presetOrFile, ImportNotes* notes = nullptr, AngleChoice angles = AngleChoice::File);

// The same, but a file may also be a skeleton (arbor-skeleton/1) or a branch graph (arbor-graph/1) given whole.
TreeSource loadTreeArgument(const std::string& presetOrFile, ImportNotes* notes = nullptr, AngleChoice angles = AngleChoice::File);

}  // namespace arbor::cli
