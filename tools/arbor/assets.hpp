#pragma once
// Where presets and other assets live: $ARBOR_ASSETS, the source tree's assets/, or ../assets beside the binary.
#include <string>
#include <vector>

#include "species/species.hpp"
#include "species/species_io.hpp"

namespace arbor::cli {

std::string assetDirectory();

// Preset names ("black-tupelo", ...) from assets/presets/*.json, sorted.
std::vector<std::string> presetNames();

// A path that exists is read as a species file; otherwise the argument must name a preset.
// Throws SpeciesError naming the argument and the presets on offer.
SpeciesParams loadSpeciesArgument(const std::string& presetOrFile, ImportNotes* notes = nullptr);

}  // namespace arbor::cli
