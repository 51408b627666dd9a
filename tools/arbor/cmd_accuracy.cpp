// arbor accuracy: per preset, how far ACC's patches lie from OpenSubdiv's exact limit surface, relative to
// the branch radius, for regular and extraordinary patches apart (docs/ACCURACY.md).
#include <chrono>
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "growth/growth_model.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/acc_accuracy.hpp"
#include "tree/build_tree.hpp"
#include "patches/patch_set.hpp"

namespace arbor::cli {

namespace {

struct AccuracyOptions {
  AngleChoice angles = AngleChoice::File;
  std::vector<std::string> species;
  std::uint64_t seed = 1;
  int levels = 0;
  std::size_t maxPatches = 0;
  int samples = 5;
};

int runAccuracy(const AccuracyOptions& o) {
  const std::vector<std::string> names = o.species.empty() ? presetNames() : o.species;
  std::printf("%-22s %9s %9s %9s %11s %11s %11s %11s %9s\n", "species", "quads", "regular", "extraord", "reg max",
              "reg rms", "extra max", "extra rms", "seconds");
  std::fflush(stdout);
  for (const std::string& name : names) {
    // OpenSubdiv evaluation takes minutes on the large presets: say what is running before it starts.
    std::fprintf(stderr, "arbor accuracy: measuring %s ...\n", name.c_str());
    const auto start = std::chrono::steady_clock::now();
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    const TreeGeometry built = buildTree(loadTreeArgument(name, nullptr, o.angles).grow(growth));
    const TreeMesh& tree = built.mesh;
    const PatchSet& set = built.patches;
    const AccAccuracy a = measureAccAccuracy(tree.mesh, set, o.maxPatches, o.samples);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-22s %9zu %9zu %9zu %11.3e %11.3e %11.3e %11.3e %9.2f\n", name.c_str(), tree.mesh.quads.size(),
                a.regularPatches, a.extraordinaryPatches, a.regularMax, a.regularRms, a.extraordinaryMax,
                a.extraordinaryRms, seconds);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

void addAccuracyCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<AccuracyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "accuracy", "Distance of ACC's patches from the exact limit surface (OpenSubdiv), relative to the branch radius.");
  cmd->add_option("species", o->species, "Presets, or model, skeleton or graph files (default: every preset)");
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--seed", o->seed, "Random seed")->check(Seed())->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels (default: each species' Levels)")->check(Whole(1, 8));
  cmd->add_option("--max-patches", o->maxPatches, "Measure every k-th patch so that at most this many are (0: all)")
      ->check(Whole(0, 100000000))
      ->capture_default_str();
  cmd->add_option("--samples", o->samples, "Samples per patch side, corners included (2, 3 or 5: where the reference is exact)")
      ->check(Whole(2, 64))
      ->capture_default_str();
  cmd->callback([o, &action] { action = [o] { return runAccuracy(*o); }; });
}

}  // namespace arbor::cli
