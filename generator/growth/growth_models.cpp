#include "growth_models.hpp"

#include <array>
#include <nlohmann/json.hpp>

#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "weber_penn/species_io.hpp"
#include "weber_penn/weber_penn_model.hpp"

namespace arbor {

namespace {

const std::array<GrowthModelInfo, 1> kModels{{
    {"weber-penn", "Weber & Penn's parametric trees with da Vinci's and Murray's natural rules (Arbor JSON or Arbaro XML species)",
     "docs/species-format.md", readWeberPennModel, speciesFormatMarkdown, randomWeberPennModel},
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
  for (const GrowthModelInfo& m : kModels) names += std::string(names.empty() ? "" : ", ") + "\"" + m.name + "\"";
  if (!model.is_string()) throw InputError(file, kModelKey, "expected the name of a growth model; allowed: " + names);
  const std::string name = model.get<std::string>();
  for (const GrowthModelInfo& m : kModels) {
    if (name == m.name) return name;
  }
  throw InputError(file, kModelKey, "'" + name + "' is not a growth model; allowed: " + names);
}

void requireModelExtension(const std::string& file) {
  if (!endsWith(file, ".xml") && !endsWith(file, ".json")) {
    throw InputError(file, "(file)", "unknown model file type; use .json (Arbor, any model) or .xml (an Arbaro species)");
  }
}

}  // namespace

std::span<const GrowthModelInfo> growthModels() { return kModels; }

TreeModel readModelFile(const std::string& text, const std::string& file, const ModelReadOptions& options) {
  requireModelExtension(file);
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
