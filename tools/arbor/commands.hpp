#pragma once
// Each subcommand registers itself on the CLI and sets the action main() runs after parsing.
#include <CLI/CLI.hpp>
#include <functional>

namespace arbor::cli {

using Action = std::function<int()>;

// Exit codes: 0 success, 1 a failure while running (I/O; for `check`, mesh-made intersections), 2 bad input or usage.
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

// --mesh-displaced (generate, render, check): what MeshOptions::fakeDisplaced draws as fake branches, meshed instead.
constexpr const char* kMeshDisplacedHelp =
    "Mesh the twigs (and twig-bearing branches) the mesh could not join near where they attach: those their parent "
    "could join only more than half a parent radius along (meshed from that far slab), thin twigs inside or shallow "
    "along their parent, twigs just before their parent splits or just past it inside another of its clones, twigs passing "
    "through a neighbouring branch's joint, twigs (and branches bearing only twigs, fronds a quarter of their parent's base radius thick, and clones as thin "
    "that end a branch bearing nothing) whose neck or first band the mesh made cross another branch or their own tube, or crosses their own parent (default: fake branches on their skeletons, as stubs)";

// What generate and check report as "faked stems" (each kind is listed in kMeshDisplacedHelp).
constexpr const char* kFakedStemsNote = "twigs the mesh could not join near where they attach, or whose joint crossed another branch, with their clones: fake branches";

void addGenerateCommand(CLI::App& app, Action& action);
void addMeshCommand(CLI::App& app, Action& action);
void addSpeciesCommand(CLI::App& app, Action& action);
void addBenchCommand(CLI::App& app, Action& action);
void addBenchTessCommand(CLI::App& bench, Action& action);  // under `bench`
void addBenchLeavesCommand(CLI::App& bench, Action& action);  // under `bench`
void addBenchLsystemCommand(CLI::App& bench, Action& action);  // under `bench`
void addLsystemCommand(CLI::App& app, Action& action);
void addGrowCommand(CLI::App& app, Action& action);
void addBenchGrowCommand(CLI::App& bench, Action& action);  // under `bench`
void addRenderCommand(CLI::App& app, Action& action);
void addViewCommand(CLI::App& app, Action& action);
void addTexturesCommand(CLI::App& app, Action& action);
void addAccuracyCommand(CLI::App& app, Action& action);
void addCheckCommand(CLI::App& app, Action& action);

// Runs an action, turning the project's exceptions into messages and exit codes.
int runGuarded(const Action& action);

}  // namespace arbor::cli
