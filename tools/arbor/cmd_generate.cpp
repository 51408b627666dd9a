// arbor generate: species parameters in, a tree out (skeleton JSON now; meshes with the mesh stage).
#include <chrono>
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "common/text_util.hpp"
#include "growth/skeleton_checks.hpp"
#include "growth/skeleton_json.hpp"
#include "growth/weber_penn.hpp"

namespace arbor::cli {

namespace {

struct GenerateOptions {
  std::string species;
  std::uint64_t seed = 1;
  int levels = 0;
  std::string out;
  bool quiet = false;
};

void printNotes(const std::string& species, const ImportNotes& notes) {
  if (!notes.defaulted.empty()) {
    std::string list;
    for (const std::string& d : notes.defaulted) list += (list.empty() ? "" : ", ") + d;
    std::fprintf(stderr, "arbor: note: %s: %zu parameters absent from the file took Arbaro defaults: %s\n",
                 species.c_str(), notes.defaulted.size(), list.c_str());
  }
  if (!notes.ignored.empty()) {
    std::string list;
    for (const std::string& d : notes.ignored) list += (list.empty() ? "" : ", ") + d;
    std::fprintf(stderr, "arbor: note: %s: read but not used: %s\n", species.c_str(), list.c_str());
  }
}

int runGenerate(const GenerateOptions& o) {
  if (!endsWith(o.out, ".json")) {
    throw SpeciesError(o.out, "--out", "unsupported output type; allowed: .json (skeleton)");
  }
  ImportNotes notes;
  const SpeciesParams params = loadSpeciesArgument(o.species, &notes);
  if (!o.quiet) printNotes(o.species, notes);

  GrowthOptions growth;
  growth.seed = o.seed;
  growth.levels = o.levels;
  const auto start = std::chrono::steady_clock::now();
  const Skeleton skeleton = generateSkeleton(params, growth);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  writeFileAtomically(o.out, writeSkeletonJson(skeleton));
  if (o.quiet) return 0;

  const SkeletonStats stats = skeletonStats(skeleton);
  std::string perLevel;
  for (std::size_t i = 0; i < stats.stemsPerLevel.size(); ++i) {
    perLevel += (i ? ", " : "") + std::to_string(stats.stemsPerLevel[i]);
  }
  std::printf("%s, seed %llu, %d levels: generated in %.1f ms\n", params.name.c_str(),
              static_cast<unsigned long long>(o.seed), skeleton.levels, ms);
  std::printf("  stems per level  %s\n", perLevel.c_str());
  std::printf("  nodes            %zu (%zu branch points)\n", stats.nodes, stats.branchPoints);
  std::printf("  leaves           %zu\n", stats.leaves);
  std::printf("  height           %.2f m, crown radius %.2f m, trunk base radius %.3f m\n", stats.height,
              stats.crownRadius, skeleton.nodes.empty() ? 0.0 : skeleton.nodes.front().radius);
  std::printf("  r^E conservation worst relative error %.1e (E = %.2f)\n", worstConservationError(skeleton),
              skeleton.exponent);
  std::printf("wrote %s\n", o.out.c_str());
  return 0;
}

}  // namespace

void addGenerateCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("generate", "Grow a tree from a preset or species file and write it.");
  cmd->add_option("species", o->species, "Preset name (see 'arbor species --list') or a .json/.xml species file")
      ->required();
  cmd->add_option("--seed", o->seed, "Random seed; the same seed gives byte-identical output")->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels to grow (default: the species' Levels)")
      ->check(CLI::Range(1, 8));
  cmd->add_option("--out", o->out, "Output file: .json writes the skeleton (nodes, stems, leaves)")->required();
  cmd->add_flag("--quiet", o->quiet, "Print nothing on success");
  cmd->callback([o, &action] { action = [o] { return runGenerate(*o); }; });
}

}  // namespace arbor::cli
