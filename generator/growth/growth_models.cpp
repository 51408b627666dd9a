#include "growth_models.hpp"

#include <array>
#include <nlohmann/json.hpp>

#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "lsystem/lsystem_model.hpp"
#include "space_colonization/space_colonization_model.hpp"
#include "weber_penn/species_io.hpp"
#include "weber_penn/weber_penn_model.hpp"

namespace arbor {

namespace {

// An L-system file is its grammar: .lsys text, whatever reader asked.
TreeModel readLsystem(const std::string& text, const std::string& file, bool, const ModelReadOptions& options) {
  return readLsystemModel(text, file, options);
}

// A space-colonization file is JSON naming its model; never an Arbaro XML.
TreeModel readSpaceColonization(const std::string& text, const std::string& file, bool, const ModelReadOptions& options) {
  return readSpaceColonizationModel(text, file, options);
}

const std::array<GrowthModelInfo, 3> kModels{{
    {"weber-penn", "Weber & Penn's parametric trees with da Vinci's and Murray's natural rules (Arbor JSON or Arbaro XML species)",
     "docs/species-format.md", "", readWeberPennModel, speciesFormatMarkdown, randomWeberPennModel},
    {"l-system", "Lindenmayer systems (ABOP ch. 1-2): bracketed, stochastic, context-sensitive, parametric, 3D turtle (.lsys grammars)",
     "docs/lsystem-format.md", ".lsys", readLsystem, nullptr, nullptr},
    {"space-colonization", "Space colonization (Runions et al. 2007) with clouds, obstacles and gravitropism (Patrick, Rege & Bailey)",
     "docs/space-colonization-format.md", "", readSpaceColonization, nullptr, randomSpaceColonizationModel},
}};

constexpr const char* kModelKey = "model";

// The model a JSON file names; "" when it names none, or is not an object a model could read (the default
// model's reader then says precisely what is wrong with it).
std::string namedModel(const std::string& text, const std::string& file) {
  if (jsonNestingPast(text, 64) != std::string::npos) return "";
  const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
  if (root.is_discarded() || !root.is_object() || !root.contains(kModelKey)) return "";
  const nlohmann::json& model = root.at(kModelKey);
  std::string names;
  for (const GrowthModelInfo& m : kModels)
    if (!*m.extension) names += std::string(names.empty() ? "" : ", ") + "\"" + m.name + "\"";  // those read from JSON
  if (!model.is_string()) throw InputError(file, kModelKey, "expected the name of a growth model; allowed: " + names);
  const std::string name = model.get<std::string>();
  for (const GrowthModelInfo& m : kModels) {
    if (name == m.name && *m.extension) {
      throw InputError(file, kModelKey, "'" + name + "' models are read from " + m.extension + " files, not JSON (" + m.format + ")");
    }
    if (name == m.name) return name;
  }
  throw InputError(file, kModelKey, "'" + name + "' is not a growth model; allowed: " + names);
}

// The model whose own file type this is (.lsys), or null.
const GrowthModelInfo* byExtension(const std::string& file) {
  for (const GrowthModelInfo& m : kModels) {
    if (*m.extension && endsWith(file, m.extension)) return &m;
  }
  return nullptr;
}

void requireModelExtension(const std::string& file) {
  if (!endsWith(file, ".xml") && !endsWith(file, ".json") && !byExtension(file)) {
    throw InputError(file, "(file)", "unknown model file type; use .json (Arbor, any model), .xml (an Arbaro species) or .lsys (an L-system)");
  }
}

}  // namespace

std::span<const GrowthModelInfo> growthModels() { return kModels; }

TreeModel readModelFile(const std::string& text, const std::string& file, const ModelReadOptions& options) {
  requireModelExtension(file);
  if (const GrowthModelInfo* own = byExtension(file)) return own->read(text, file, false, options);
  const bool xml = endsWith(file, ".xml");
  if (const std::string format = xml ? "" : topLevelJsonString(text, "format"); format == "arbor-skeleton/1" || format == "arbor-graph/1") {
    throw InputError(file, "format", "'" + format + "' is a tree already grown, not a model file; 'arbor mesh', 'render' and 'view' take it");
  }
  const std::string name = xml ? "" : namedModel(text, file);
  for (const GrowthModelInfo& m : kModels) {
    if (name == m.name) return m.read(text, file, xml, options);
  }
  return kModels.front().read(text, file, xml, options);  // no model named: Weber-Penn, as files were before models
}

TreeModel loadModelFile(const std::string& path, const ModelReadOptions& options) {
  requireModelExtension(path);  // before reading: a file of another kind is never opened
  return readModelFile(readInputFile(path, kMaxModelFileBytes), path, options);
}

}  // namespace arbor
