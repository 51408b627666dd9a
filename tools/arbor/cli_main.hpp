#pragma once
// The start shared by Arbor's two programs: commands registered on one CLI, the arguments parsed, the chosen
// command run. `arbor-engine` holds every command; `arbor` holds those that need no GPU or window and starts
// without loading Vulkan, GLFW or X11 (a third of its start-up), handing every other command to `arbor-engine`.
#include <functional>
#include <span>

#include "commands.hpp"

namespace arbor::cli {

using AddCommand = void (*)(CLI::App&, Action&);

// Registers `commands`, parses the arguments and runs the chosen command through `guard` (runGuarded, or a
// program's own wrapper around it); the process's exit code. `otherwise`, when given, runs instead where argv[1]
// names none of `commands` and is not --version (arbor hands those to arbor-engine).
int runCli(int argc, char** argv, std::span<const AddCommand> commands, const std::function<int(const Action&)>& guard,
           const std::function<int()>& otherwise = {});

}  // namespace arbor::cli
