// arbor: the commands that need no GPU or window run here; any other argument list (render, view, bench,
// textures, accuracy, --help, a mistyped command) is handed to arbor-engine beside this program, unchanged.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "files/asset_folder.hpp"
#include "cli_main.hpp"

int main(int argc, char** argv) {
  using namespace arbor::cli;
  static constexpr AddCommand kCommands[] = {addGenerateCommand, addMeshCommand, addLsystemCommand,
                                             addGrowCommand,     addSpeciesCommand, addCheckCommand};
  // Its own commands and --version run here; anything else is arbor-engine's, given the same arguments.
  return runCli(argc, argv, kCommands, runGuarded, [argv] {
    std::filesystem::path bin = arbor::programFolder();
    if (bin.empty()) bin = std::filesystem::path(argv[0]).parent_path();
    const std::string engine = (bin / "arbor-engine").string();
    ::execv(engine.c_str(), argv);
    std::fprintf(stderr, "arbor: error: %s: cannot be run (%s); it holds the commands that use Vulkan and windows, installed beside arbor\n",
                 engine.c_str(), std::strerror(errno));
    return kExitFailure;
  });
}
