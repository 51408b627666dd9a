// arbor lsystem: derive a grammar and show it (string, SVG drawing, counts); arbor bench lsystem: modules per
// second derived and interpreted, and a grammar file to patches, per preset.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/lsystem/derivation.hpp"
#include "growth/lsystem/lsystem_model.hpp"
#include "growth/lsystem/lsystem_svg.hpp"
#include "growth/lsystem/turtle.hpp"
#include "tree/build_tree.hpp"

namespace arbor::cli {

namespace {

struct LsystemOptions {
  std::string grammar;
  std::string out;
  int steps = -1;               // -1: the grammar's n
  std::uint64_t seed = 0;       // 0: the grammar's seed
  std::size_t maxModules = 50'000'000;
  std::vector<std::string> presets;
  int repeat = 3;
};

// A grammar by file or preset name, read as the l-system model reads it.
lsys::Lsystem loadGrammar(const std::string& argument) {
  const TreeModel model = loadModelArgument(argument);
  const lsys::Lsystem* system = lsystemOf(model);
  if (!system) throw InputError(argument, "(argument)", std::string("is a ") + model.model() + " model, not an L-system grammar (.lsys)");
  return *system;
}

lsys::DeriveOptions deriveOptions(const LsystemOptions& o) {
  lsys::DeriveOptions d;
  if (o.steps >= 0) d.steps = o.steps;
  if (o.seed > 0) d.seed = o.seed;
  d.moduleLimit = o.maxModules;
  return d;
}

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

int runLsystem(const LsystemOptions& o) {
  const bool svg = endsWith(o.out, ".svg"), text = endsWith(o.out, ".txt");
  if (!o.out.empty() && !svg && !text) throw InputError(o.out, "--out", "allowed: .svg (a 2D drawing) or .txt (the derived string)");
  if (!o.out.empty()) requireOutputFile(o.out);
  const lsys::Lsystem system = loadGrammar(o.grammar);
  const lsys::DeriveOptions options = deriveOptions(o);
  const auto start = std::chrono::steady_clock::now();
  const lsys::ModuleString derived = lsys::derive(system, options);
  const double deriveMs = msSince(start);
  const auto turtleStart = std::chrono::steady_clock::now();
  const lsys::Interpretation drawn = lsys::interpret(derived, lsys::turtleSettings(system));
  const double turtleMs = msSince(turtleStart);
  if (svg) writeFileAtomically(o.out, lsys::writeLsystemSvg(system, options));
  if (text) writeFileAtomically(o.out, derived.text() + "\n");
  std::printf("%s: n = %d, %zu modules derived in %.1f ms; the turtle drew %zu internodes and %zu leaves in %.1f ms\n", system.name.c_str(),
              options.steps.value_or(system.derivationLength), derived.size(), deriveMs, drawn.segments, drawn.graph.leaves.size(), turtleMs);
  if (!o.out.empty()) std::printf("wrote %s\n", o.out.c_str());
  return 0;
}

int runBenchLsystem(const LsystemOptions& o) {
  std::vector<std::string> names = o.presets;
  if (names.empty()) {
    for (const std::string& name : presetNames())
      if (lsystemOf(loadModelArgument(name))) names.push_back(name);
  }
  std::printf("%-14s %11s %11s %10s %13s %9s %12s\n", "grammar", "modules", "internodes", "derive ms", "interpret ms", "Mmod/s",
              "to patches ms");
  for (const std::string& name : names) {
    const lsys::Lsystem system = loadGrammar(name);
    std::vector<double> derive, interpret, patches;
    std::size_t modules = 0, internodes = 0;
    for (int r = 0; r < o.repeat; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const lsys::ModuleString s = lsys::derive(system, deriveOptions(o));
      const auto t1 = std::chrono::steady_clock::now();
      const lsys::Interpretation drawn = lsys::interpret(s, lsys::turtleSettings(system));
      derive.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      interpret.push_back(msSince(t1));
      modules = s.size();
      internodes = drawn.segments;
      // The whole path a user takes: the file read, derived, drawn, converted, meshed and patched.
      const auto p0 = std::chrono::steady_clock::now();
      const TreeSource source = loadTreeArgument(name);
      buildTree(source.grow(GrowthOptions{}));
      patches.push_back(msSince(p0));
    }
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    const double seconds = (median(derive) + median(interpret)) / 1000.0;
    std::printf("%-14s %11zu %11zu %10.1f %13.1f %9.1f %12.1f\n", name.c_str(), modules, internodes, median(derive), median(interpret),
                seconds > 0.0 ? static_cast<double>(modules) / seconds / 1e6 : 0.0, median(patches));
    std::fflush(stdout);
  }
  return 0;
}

void addLimitOptions(CLI::App* cmd, LsystemOptions& o) {
  cmd->add_option("--n", o.steps, "Derivation length (default: the grammar's n)")->check(Whole(0, 1000));
  cmd->add_option("--seed", o.seed, "Seed of the stochastic productions (default: the grammar's seed)")->check(Seed());
  cmd->add_option("--max-modules", o.maxModules, "Refuse a derivation past this many modules (exit 2)")
      ->check(Whole(1, 1'000'000'000))
      ->capture_default_str();
}

}  // namespace

void addLsystemCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<LsystemOptions>();
  CLI::App* cmd = app.add_subcommand("lsystem", "Derive an L-system grammar (.lsys) and report it; write its 2D drawing (SVG) or derived string.");
  cmd->add_option("grammar", o->grammar, "A .lsys file or an L-system preset (see 'arbor species --list')")->required();
  cmd->add_option("--out", o->out, "Write the drawing (.svg: grammars turning only in the plane) or the derived string (.txt)");
  addLimitOptions(cmd, *o);
  cmd->callback([o, &action] { action = [o] { return runLsystem(*o); }; });
}

void addBenchLsystemCommand(CLI::App& bench, Action& action) {
  auto o = std::make_shared<LsystemOptions>();
  CLI::App* cmd = bench.add_subcommand("lsystem", "Modules per second derived and interpreted, and file to patches, per L-system preset (one thread).");
  cmd->add_option("grammars", o->presets, "L-system presets or .lsys files (default: every L-system preset)");
  cmd->add_option("--repeat", o->repeat, "Runs per grammar; medians are printed")->check(Whole(1, 1000))->capture_default_str();
  addLimitOptions(cmd, *o);
  cmd->callback([o, &action] { action = [o] { return runBenchLsystem(*o); }; });
}

}  // namespace arbor::cli
