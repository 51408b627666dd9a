// arbor species: list presets, show a species' parameters, or convert an Arbaro XML file to Arbor JSON.
#include <cstdio>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "species/species_io.hpp"

namespace arbor::cli {

namespace {

struct SpeciesOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species;
  std::string out;
  bool list = false;
  bool formatDoc = false;
  std::string random;  // a seed: a random species within the documented ranges
};

int runSpecies(const SpeciesOptions& o) {
  if (o.formatDoc) {
    std::fputs(speciesFormatMarkdown().c_str(), stdout);
    return 0;
  }
  if (o.random.empty() && (o.list || o.species.empty())) {
    std::printf("presets in %s/presets:\n", assetDirectory().c_str());
    for (const std::string& name : presetNames()) std::printf("  %s\n", name.c_str());
    return 0;
  }
  if (!o.random.empty() && !o.species.empty()) throw SpeciesError(o.species, "--random", "give either a species or --random SEED, not both");
  if (!o.out.empty()) requireOutputFile(o.out);
  ImportNotes notes;
  const SpeciesParams params = o.random.empty() ? loadSpeciesArgument(o.species, &notes, o.angles) : randomSpecies(std::stoull(o.random));
  const std::string json = writeSpeciesJson(params);
  if (o.out.empty()) {
    std::fputs(json.c_str(), stdout);
  } else {
    writeFileAtomically(o.out, json);
    std::printf("wrote %s (%s)\n", o.out.c_str(), params.name.c_str());
  }
  for (const std::string& d : notes.defaulted) std::fprintf(stderr, "arbor: note: defaulted %s\n", d.c_str());
  return 0;
}

}  // namespace

void addSpeciesCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<SpeciesOptions>();
  CLI::App* cmd = app.add_subcommand("species", "List presets, or print / convert a species file as Arbor JSON.");
  cmd->add_option("species", o->species, "Preset name or .json/.xml species file (omit to list presets)");
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--out", o->out, "Write the species as Arbor JSON to this file instead of printing it");
  cmd->add_flag("--list", o->list, "List the presets");
  cmd->add_option("--random", o->random, "Write a random species: every field drawn evenly from its documented range (stress tests)")
      ->check(Seed());
  cmd->add_flag("--format-doc", o->formatDoc, "Print the species format documentation (Markdown)");
  cmd->callback([o, &action] { action = [o] { return runSpecies(*o); }; });
}

}  // namespace arbor::cli
