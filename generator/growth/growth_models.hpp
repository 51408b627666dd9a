#pragma once
// Every growth model Arbor has, and model files read by the model they name. A new model is one folder under
// growth/ and one row in growth_models.cpp.
#include <cstdint>
#include <span>
#include <string>

#include "growth_model.hpp"

namespace arbor {

struct GrowthModelInfo {
  const char* name;       // as model files name it: {"model": "weber-penn", ...}
  const char* summary;    // one line for `arbor species --list`
  const char* format;     // where its file format is documented
  const char* extension;  // its own file type besides .json ("" for none); .xml is Arbaro's (Weber-Penn)
  // A model file's text as this model; `xml` for an Arbaro species file. Throws InputError naming file and field.
  TreeModel (*read)(const std::string& text, const std::string& file, bool xml, const ModelReadOptions& options);
  std::string (*formatMarkdown)();          // the file format, field by field (`arbor species --format-doc`); or null
  TreeModel (*random)(std::uint64_t seed);  // every parameter drawn from its documented range (stress tests); or null
};

std::span<const GrowthModelInfo> growthModels();

// Model files are small; anything larger is refused before it is parsed.
constexpr std::size_t kMaxModelFileBytes = 1024 * 1024;

// A .json file names its model in "model" (absent: weber-penn, so every species file keeps working); an .xml
// file is an Arbaro species (weber-penn); a model's own extension (.lsys) is that model's. Throws InputError
// naming the file and the field.
TreeModel readModelFile(const std::string& text, const std::string& file, const ModelReadOptions& options = {});
TreeModel loadModelFile(const std::string& path, const ModelReadOptions& options = {});

}  // namespace arbor
