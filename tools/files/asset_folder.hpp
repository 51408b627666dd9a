#pragma once
// Where Arbor's assets (presets, grammars, textures) are, for every program that needs them: the arbor command,
// the viewer and the Python module. No Vulkan, no command-line library.
#include <filesystem>
#include <string>
#include <vector>

namespace arbor {

// The folder of the running program (from /proc/self/exe), where its installed files are found from; empty when
// the system does not say.
std::filesystem::path programFolder();

// $ARBOR_ASSETS first; then beside the running binary (installed: PREFIX/share/arbor; a copied tree: assets/);
// then the source tree this was built from. Throws InputError when none has presets: never an empty list.
std::string assetDirectory();

// Preset names: model files in assets/presets/*.json ("black-tupelo", ...), then L-system grammars in
// assets/lsystems/*.lsys ("fig-1-24a", ...), each group sorted.
std::vector<std::string> presetNames();

// A preset's file, or "" when `name` names none (a name with a '/' never does).
std::string presetFile(const std::string& name);

}  // namespace arbor
