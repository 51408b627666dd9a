// arbor bench generate and mesh: per preset (or a random branch graph), the time of each stage on one core.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/graph/random_graph.hpp"
#include "growth/growth_model.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/patch_set.hpp"

namespace arbor::cli {

namespace {

struct BenchOptions {
  AngleChoice angles = AngleChoice::File;
  std::vector<std::string> species;
  int repeat = 5;
  std::uint64_t seed = 1;
  int levels = 0;
  int graph = 0;  // internodes of a random branch graph (0: the species instead)
};

int runBenchGenerate(const BenchOptions& o) {
  const std::vector<std::string> names = o.species.empty() ? presetNames() : o.species;
  std::printf("%-22s %6s %9s %9s %9s %10s %10s\n", "species", "levels", "stems", "nodes", "leaves", "median ms",
              "min ms");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const TreeSource source = loadTreeArgument(names[i], nullptr, o.angles);
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    std::vector<double> times;
    Skeleton skeleton;
    for (int r = 0; r < o.repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      skeleton = source.grow(growth);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    std::printf("%-22s %6d %9zu %9zu %9zu %10.2f %10.2f\n", names[i].c_str(), skeleton.levels, skeleton.stems.size(),
                skeleton.nodes.size(), skeleton.leaves.size(), times[times.size() / 2], times.front());
    std::fflush(stdout);
  }
  return 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Medians over o.repeat runs of each stage, from the skeleton (grown, or converted from a graph) to the patches.
void timeMesh(const std::string& label, const BenchOptions& o, const std::function<Skeleton()>& makeSkeleton) {
  std::vector<double> skeletonMs, meshMs, patchMs, totalMs;
  std::size_t quads = 0, patches = 0, regular = 0;
  int levels = 0;
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  for (int r = 0; r < o.repeat; ++r) {
    const auto t0 = Clock::now();
    const Skeleton skeleton = makeSkeleton();
    const auto t1 = Clock::now();
    const TreeMesh tree = buildTreeMesh(skeleton);
    const auto t2 = Clock::now();
    const PatchSet set = buildPatches(tree.mesh);
    const auto t3 = Clock::now();
    skeletonMs.push_back(ms(t0, t1));
    meshMs.push_back(ms(t1, t2));
    patchMs.push_back(ms(t2, t3));
    totalMs.push_back(ms(t0, t3));
    quads = tree.mesh.quads.size();
    patches = set.size();
    regular = static_cast<std::size_t>(std::count(set.kind.begin(), set.kind.end(), PatchKind::Regular));
    levels = skeleton.levels;
  }
  std::printf("%-22s %6d %9zu %9zu %8zu %11.1f %9.1f %10.1f %10.1f\n", label.c_str(), levels, quads, patches, regular,
              median(skeletonMs), median(meshMs), median(patchMs), median(totalMs));
  std::fflush(stdout);
}

int runBenchMesh(const BenchOptions& o) {
  std::printf("%-22s %6s %9s %9s %8s %11s %9s %10s %10s\n", o.graph > 0 ? "graph" : "species", "levels", "quads", "patches", "regular",
              "skeleton ms", "mesh ms", "patches ms", "total ms");
  if (o.graph > 0) {
    // The graph is made outside the clock: a growth model hands it over; converting it is the skeleton stage.
    const BranchGraph graph = randomBranchGraph(o.seed, o.graph);
    timeMesh("random " + std::to_string(o.graph), o, [&] { return graphToSkeleton(graph); });
    return 0;
  }
  const std::vector<std::string> names = o.species.empty() ? presetNames() : o.species;
  for (const std::string& name : names) {
    const TreeSource source = loadTreeArgument(name, nullptr, o.angles);
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    timeMesh(name, o, [&] { return source.grow(growth); });
  }
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, Action& action) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that print figures (nothing is asserted).");
  bench->require_subcommand(1);
  auto o = std::make_shared<BenchOptions>();
  CLI::App* gen = bench->add_subcommand("generate", "Time skeleton generation per preset, one tree at a time (a Weber-Penn tree's leaves on every core).");
  gen->add_option("species", o->species, "Presets, or model, skeleton or graph files (default: every preset)");
  addAnglesOption(gen, o->angles);
  gen->add_option("--repeat", o->repeat, "Runs per species; the median and minimum are printed")
      ->check(Whole(1, 1000))
      ->capture_default_str();
  gen->add_option("--seed", o->seed, "Random seed")->check(Seed())->capture_default_str();
  gen->add_option("--levels", o->levels, "Stem levels (default: each species' Levels)")->check(Whole(1, 8));
  gen->callback([o, &action] { action = [o] { return runBenchGenerate(*o); }; });

  auto m = std::make_shared<BenchOptions>();
  CLI::App* mesh = bench->add_subcommand("mesh", "Time parameters (or a branch graph) -> skeleton -> mesh -> patches per preset, one tree at a time (the mesher on one core; leaves and the self-intersection search on every core).");
  mesh->add_option("species", m->species, "Presets, or model, skeleton or graph files (default: every preset)");
  addAnglesOption(mesh, m->angles);
  mesh->add_option("--repeat", m->repeat, "Runs per species; medians are printed")->check(Whole(1, 1000))->capture_default_str();
  mesh->add_option("--seed", m->seed, "Random seed")->check(Seed())->capture_default_str();
  mesh->add_option("--levels", m->levels, "Stem levels (default: each species' Levels)")->check(Whole(1, 8));
  mesh->add_option("--graph", m->graph,
                   "Instead of species: a random rooted graph of this many internodes (up to 6 children a node, near-parallel "
                   "and backward children; --seed picks it), converted to a skeleton, meshed and patched")
      ->check(Whole(2, 2000000));
  mesh->callback([m, &action] { action = [m] { return runBenchMesh(*m); }; });

  addBenchTessCommand(*bench, action);
  addBenchLeavesCommand(*bench, action);
  addBenchLsystemCommand(*bench, action);
  addBenchGrowCommand(*bench, action);
}

}  // namespace arbor::cli
