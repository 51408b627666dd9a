// arbor bench generate: per preset, nodes, leaves and the time to grow the skeleton on one core.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "commands.hpp"
#include "growth/weber_penn.hpp"

namespace arbor::cli {

namespace {

struct BenchOptions {
  std::vector<std::string> species;
  int repeat = 5;
  std::uint64_t seed = 1;
  int levels = 0;
};

int runBenchGenerate(const BenchOptions& o) {
  const std::vector<std::string> names = o.species.empty() ? presetNames() : o.species;
  std::printf("%-22s %6s %9s %9s %9s %10s %10s\n", "species", "levels", "stems", "nodes", "leaves", "median ms",
              "min ms");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const SpeciesParams params = loadSpeciesArgument(names[i]);
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    std::vector<double> times;
    Skeleton skeleton;
    for (int r = 0; r < o.repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      skeleton = generateSkeleton(params, growth);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    std::printf("%-22s %6d %9zu %9zu %9zu %10.2f %10.2f\n", names[i].c_str(), skeleton.levels, skeleton.stems.size(),
                skeleton.nodes.size(), skeleton.leaves.size(), times[times.size() / 2], times.front());
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, Action& action) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that print figures (nothing is asserted).");
  bench->require_subcommand(1);
  auto o = std::make_shared<BenchOptions>();
  CLI::App* gen = bench->add_subcommand("generate", "Time skeleton generation per preset (one thread).");
  gen->add_option("species", o->species, "Presets or species files (default: every preset)");
  gen->add_option("--repeat", o->repeat, "Runs per species; the median and minimum are printed")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  gen->add_option("--seed", o->seed, "Random seed")->capture_default_str();
  gen->add_option("--levels", o->levels, "Stem levels (default: each species' Levels)")->check(CLI::Range(1, 8));
  gen->callback([o, &action] { action = [o] { return runBenchGenerate(*o); }; });
}

}  // namespace arbor::cli
