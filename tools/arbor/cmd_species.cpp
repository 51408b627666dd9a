// arbor species: list growth models and presets, show a model file's parameters, or convert an Arbaro XML file
// to Arbor JSON.
#include <filesystem>
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "growth/growth_models.hpp"

namespace arbor::cli {

namespace fs = std::filesystem;

namespace {

struct SpeciesOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species;
  std::string out;
  bool list = false;
  bool formatDoc = false;
  std::string random;  // a seed: a random species within the documented ranges
  std::string model = "weber-penn";  // for --random and --format-doc
};

const GrowthModelInfo& modelNamed(const std::string& name) {
  std::string names;
  for (const GrowthModelInfo& m : growthModels()) {
    if (name == m.name) return m;
    names += std::string(names.empty() ? "" : ", ") + m.name;
  }
  throw InputError(name, "--model", "is not a growth model; allowed: " + names);
}

// A skeleton or graph file holds a tree already grown: it has no parameters to print.
TreeModel modelOf(const TreeSource& source, const std::string& file) {
  if (!source.model()) throw InputError(file, "format", "holds a tree already grown, not a model file; 'arbor mesh', 'render' and 'view' take it");
  return *source.model();
}

int runSpecies(const SpeciesOptions& o) {
  const GrowthModelInfo& model = modelNamed(o.model);
  if (o.formatDoc) {
    if (!model.formatMarkdown) throw InputError(o.model, "--model", std::string("its format is documented in ") + model.format);
    std::fputs(model.formatMarkdown().c_str(), stdout);
    return 0;
  }
  if (!o.random.empty() && !model.random) {
    std::string withRandom;
    for (const GrowthModelInfo& m : growthModels())
      if (m.random) withRandom += std::string(withRandom.empty() ? "" : ", ") + m.name;
    throw InputError(o.model, "--model", "has no random parameters; --random is for " + withRandom);
  }
  if (o.random.empty() && (o.list || o.species.empty())) {
    std::printf("growth models:\n");
    for (const GrowthModelInfo& m : growthModels()) std::printf("  %-12s %s (%s)\n", m.name, m.summary, m.format);
    std::printf("presets in %s/presets:\n", assetDirectory().c_str());
    for (const std::string& name : presetNames()) {
      const TreeModel preset = loadModelArgument(name);
      std::printf("  %-18s %-12s %s\n", name.c_str(), preset.model(), preset.name().c_str());
    }
    return 0;
  }
  if (!o.random.empty() && !o.species.empty()) throw InputError(o.species, "--random", "give either a species or --random SEED, not both");
  if (!o.out.empty()) requireOutputFile(o.out);
  if (!o.out.empty() && fs::path(o.out).extension() != ".json")
    throw InputError(o.out, "--out", "species are written as Arbor JSON: give a .json file (Arbaro XML is read, not written)");
  ImportNotes notes;
  const TreeModel tree = o.random.empty() ? modelOf(loadTreeArgument(o.species, &notes, o.angles), o.species) : model.random(std::stoull(o.random));
  const std::string json = tree.toJson();
  if (o.out.empty()) {
    std::fputs(json.c_str(), stdout);
  } else {
    writeFileAtomically(o.out, json);
    std::printf("wrote %s (%s)\n", o.out.c_str(), tree.name().c_str());
  }
  for (const std::string& d : notes.defaulted) std::fprintf(stderr, "arbor: note: defaulted %s\n", d.c_str());
  return 0;
}

}  // namespace

void addSpeciesCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<SpeciesOptions>();
  CLI::App* cmd = app.add_subcommand("species", "List growth models and presets, or print / convert a model file (an Arbaro species too) as Arbor JSON.");
  cmd->add_option("species", o->species, "Preset name, .json model file or .xml Arbaro species file (omit to list models and presets)");
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--out", o->out, "Write the species as Arbor JSON to this file instead of printing it");
  cmd->add_flag("--list", o->list, "List the growth models and the presets (with the model of each)");
  cmd->add_option("--random", o->random,
                  "Write random parameters of --model (stress tests): weber-penn draws every field evenly from its documented "
                  "range, space-colonization draws clouds, obstacles, radii and leaves")
      ->check(Seed());
  cmd->add_flag("--format-doc", o->formatDoc, "Print the model file format documentation (Markdown) of --model");
  cmd->add_option("--model", o->model, "Growth model for --random and --format-doc (default: weber-penn; see --list)");
  cmd->callback([o, &action] { action = [o] { return runSpecies(*o); }; });
}

}  // namespace arbor::cli
