#pragma once
// The start shared by Arbor's two programs: commands registered on one CLI, the arguments parsed, the chosen
// command run. `arbor-engine` holds every command; `arbor` holds those that need no GPU or window and starts
// without loading Vulkan, GLFW or X11 (a third of its start-up), handing every other command to `arbor-engine`.
#include <functional>
#include <span>

#include "commands.hpp"

namespace arbor::cli {

using AddCommand = void (*)(CLI::App&, Action&);

// Whether argv[1] names one of `commands` (checked before parsing, by registering them on a scratch CLI).
bool namesOneOf(int argc, char** argv, std::span<const AddCommand> commands);

// Registers `commands`, parses the arguments and runs the chosen command through `guard` (runGuarded, or a
// program's own wrapper around it); the process's exit code.
int runCli(int argc, char** argv, std::span<const AddCommand> commands, const std::function<int(const Action&)>& guard);

}  // namespace arbor::cli
