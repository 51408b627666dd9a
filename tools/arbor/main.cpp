// arbor-engine: every command of Arbor, those that render, view and benchmark on the GPU among them (`arbor`
// hands those here).
#include <cstdio>

#include "cli_main.hpp"
#include "vk/context.hpp"

int main(int argc, char** argv) {
  using namespace arbor::cli;
  // The order of `arbor --help`.
  static constexpr AddCommand kCommands[] = {addGenerateCommand, addMeshCommand,     addLsystemCommand, addGrowCommand,
                                             addSpeciesCommand,  addBenchCommand,    addRenderCommand,  addViewCommand,
                                             addTexturesCommand, addAccuracyCommand, addCheckCommand};
  return runCli(argc, argv, kCommands, [](const Action& action) {
    return runGuarded([&] {
      try {
        return action();
      } catch (const arbor::vk::VulkanError& e) {
        std::fprintf(stderr, "arbor: Vulkan error: %s\n", e.what());
        return kExitFailure;
      }
    });
  });
}
