// arbor grow: a space-colonization model grown for N iterations, written as its branch graph or its mesh;
// arbor bench grow: attraction points, iterations, nodes and milliseconds of colonization per model, and the
// issue's floor (100,000 points in one sphere colonized to the end).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "export_options.hpp"
#include "common/atomic_file.hpp"
#include "common/text_util.hpp"
#include "export/obj_export.hpp"
#include "growth/space_colonization/space_colonization_model.hpp"
#include "tree/build_tree.hpp"

namespace arbor::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct GrowOptions {
  std::string model;
  std::string out;
  std::uint32_t steps = 0;          // iterations (growth ages); 0: to the end
  std::size_t stepSize = 10'000;    // nodes processed per pause (Patrick et al.'s step size)
  std::uint64_t seed = 1;
  ExportChoices exported;
};

struct BenchGrowOptions {
  std::vector<std::string> models;
  int repeat = 5;
  std::uint64_t seed = 1;
  std::uint32_t spherePoints = 100'000;  // the floor's row; 0 leaves it out
};

// A space-colonization model by file or preset; a file of another model is refused naming that model.
sc::SpaceColonization loadColonization(const std::string& argument) {
  const TreeModel model = loadModelArgument(argument);
  const sc::SpaceColonization* m = spaceColonizationOf(model);
  if (!m) {
    throw InputError(argument, "model", "'" + model.name() + "' is a model of " + model.model() +
                                            ", not space-colonization; 'arbor grow' grows space-colonization models "
                                            "(\"model\": \"space-colonization\"), 'arbor generate' grows this one");
  }
  return *m;
}

std::size_t enabledNodes(const sc::Colonizer& c) {
  return static_cast<std::size_t>(std::count_if(c.nodes().begin(), c.nodes().end(), [](const sc::Node& n) { return n.enabled; }));
}

int runGrow(const GrowOptions& o) {
  const bool graph = endsWith(o.out, ".json");
  if (!graph && !isMeshFile(o.out)) {
    throw InputError(o.out, "--out", "unsupported output type; allowed: .json (the enabled nodes as an arbor-graph/1 branch graph), "
                                     ".obj, .gltf or .glb (the tree as generate writes it)");
  }
  requireOutputFile(o.out);
  if (graph && (o.exported.triangles || o.exported.lods > 0 || o.exported.up != "y")) {
    throw InputError(o.out, "--out", "--lods, --triangles and --up apply to mesh files (.obj, .gltf, .glb), not to a branch graph");
  }
  // Checked before growing, so a refused option never costs a whole growth.
  const TreeFileOptions fileOptions = graph ? TreeFileOptions{} : treeFileOptions(o.out, o.exported);
  const sc::SpaceColonization model = loadColonization(o.model);
  const TreeLimits limits;
  const std::uint32_t until = o.steps == 0 ? std::numeric_limits<std::uint32_t>::max() : o.steps;

  const auto start = Clock::now();
  sc::Colonizer colonizer = startColonizer(model, o.seed);
  auto reported = start;
  while (!colonizer.finished() && colonizer.age() < until) {
    colonizer.step(o.stepSize, until);
    requireNodeLimit(colonizer, model, limits);
    if (Clock::now() - reported > std::chrono::seconds(1)) {  // long runs say where they are, once a second
      std::fprintf(stderr, "arbor grow: iteration %u, %zu nodes, %zu attraction points live\n", colonizer.age(), colonizer.nodes().size(),
                   colonizer.livePoints());
      reported = Clock::now();
    }
  }
  const double growMs = msSince(start);

  std::string written;
  if (graph) {
    writeFileAtomically(o.out, writeColonizationGraph(colonizer, model));
    written = "the branch graph";
  } else {
    // The tree build stage every command uses, as `arbor generate` meshes a model grown to the end.
    const Skeleton skeleton = colonizationSkeleton(colonizer, model, o.seed, limits);
    MeshOptions mesh;
    mesh.searchBesideMesher = true;  // a one-shot export, as in `arbor generate`
    const auto tree = std::make_shared<const TreeMesh>(buildTree(skeleton, BuildOptions{mesh, false}).mesh);
    writeTreeFile(o.out, skeleton, model.name, fileOptions, tree);
    written = std::to_string(tree->mesh.quads.size()) + " quads";
  }
  std::printf("%s, seed %llu: %u iterations (%s), %zu nodes, %zu enabled, %zu of %zu attraction points live, grown in %.1f ms\n",
              model.name.c_str(), static_cast<unsigned long long>(o.seed), colonizer.age(),
              colonizer.finished() ? "grown to the end" : "--steps reached", colonizer.nodes().size(), enabledNodes(colonizer),
              colonizer.livePoints(), colonizer.points().size(), growMs);
  std::printf("wrote %s (%s)\n", o.out.c_str(), written.c_str());
  return 0;
}

// The floor: `points` attraction points in one sphere of radius 4 m, 6 m up (influence 0.6 m, kill
// 0.2 m, D = 0.1 m), above a trunk of 20 segments.
sc::SpaceColonization floorSphere(std::uint32_t points) {
  sc::SpaceColonization m;
  m.name = "sphere-" + std::to_string(points);
  m.segmentLength = 0.1;
  m.trunkSegments = 20;
  sc::AttractionCloud cloud;
  cloud.shape = sc::CloudShape::Sphere;
  cloud.center = Vec3(0, 0, 6);
  cloud.size = Vec3(4.0);
  cloud.points = points;
  cloud.influence = 0.6;
  cloud.kill = 0.2;
  m.clouds.push_back(cloud);
  return m;
}

// Colonization only, from the model to the last iteration: the points sampled and indexed, the tree grown.
void benchRow(const std::string& label, const sc::SpaceColonization& model, const BenchGrowOptions& o) {
  std::vector<double> times;
  std::size_t points = 0, nodes = 0;
  std::uint32_t iterations = 0;
  for (int r = 0; r < o.repeat; ++r) {
    const auto start = Clock::now();
    sc::Colonizer colonizer = startColonizer(model, o.seed);
    colonizer.growToEnd();
    times.push_back(msSince(start));
    points = colonizer.points().size();
    nodes = colonizer.nodes().size();
    iterations = colonizer.age();
  }
  std::sort(times.begin(), times.end());
  std::printf("%-22s %9zu %10u %9zu %10.1f %10.1f\n", label.c_str(), points, iterations, nodes, times[times.size() / 2], times.front());
  std::fflush(stdout);
}

int runBenchGrow(const BenchGrowOptions& o) {
  std::vector<std::string> names = o.models;
  if (names.empty()) {
    for (const std::string& name : presetNames())
      if (spaceColonizationOf(loadModelArgument(name))) names.push_back(name);
  }
  std::vector<sc::SpaceColonization> models;  // all read before any is timed: a bad file fails at once
  for (const std::string& name : names) models.push_back(loadColonization(name));
  std::printf("%-22s %9s %10s %9s %10s %10s\n", "model", "points", "iterations", "nodes", "median ms", "min ms");
  for (std::size_t i = 0; i < names.size(); ++i) benchRow(names[i], models[i], o);
  if (o.spherePoints > 0) benchRow(floorSphere(o.spherePoints).name, floorSphere(o.spherePoints), o);
  return 0;
}

}  // namespace

void addGrowCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<GrowOptions>();
  CLI::App* cmd = app.add_subcommand("grow", "Grow a space-colonization model for N iterations and write that state as a branch graph or a mesh.");
  cmd->add_option("model", o->model, "A space-colonization model file (.json) or preset (see 'arbor species --list')")->required();
  cmd->add_option("--steps", o->steps, "Iterations (growth ages) to grow; 0: to the end")->check(Whole(0, 1'000'000'000))->capture_default_str();
  cmd->add_option("--step-size", o->stepSize,
                  "Nodes processed before growth pauses (Patrick et al.'s step size); the tree is the same for any, progress is "
                  "reported between pauses")
      ->check(Whole(1, 1'000'000'000))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "Seed: 1 grows with the file's seed, 2 with the next one, ...")->check(Seed())->capture_default_str();
  cmd->add_option("--out", o->out,
                  "Output file: .json writes the enabled nodes as an arbor-graph/1 branch graph ('arbor mesh', 'render' and 'view' "
                  "take it); .obj, .gltf or .glb write the tree as 'generate' does (closed quad mesh, leaf and branch cards, textures)")
      ->required();
  addExportOptions(cmd, o->exported);
  cmd->callback([o, &action] { action = [o] { return runGrow(*o); }; });
}

void addBenchGrowCommand(CLI::App& bench, Action& action) {
  auto o = std::make_shared<BenchGrowOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "grow", "Attraction points, iterations, nodes and milliseconds of space colonization to the end, per model, on one thread.");
  cmd->add_option("models", o->models, "Space-colonization presets or model files (default: every space-colonization preset)");
  cmd->add_option("--repeat", o->repeat, "Runs per model; the median and minimum are printed")->check(Whole(1, 1000))->capture_default_str();
  cmd->add_option("--seed", o->seed, "Seed")->check(Seed())->capture_default_str();
  cmd->add_option("--sphere", o->spherePoints,
                  "Points of the last row, the issue's floor: one sphere cloud (radius 4 m, influence 0.6 m, kill 0.2 m, D = 0.1 m) "
                  "colonized to the end; 0 leaves the row out")
      ->check(Whole(0, 10'000'000))
      ->capture_default_str();
  cmd->callback([o, &action] { action = [o] { return runBenchGrow(*o); }; });
}

}  // namespace arbor::cli
