#pragma once
// Weber-Penn behind the growth-model interface: a species' parameters as a TreeModel.
#include <cstdint>
#include <string>

#include "growth/growth_model.hpp"
#include "species.hpp"

namespace arbor {

TreeModel weberPennModel(SpeciesParams species);

// A species file's text as a Weber-Penn model: Arbor JSON, or an Arbaro XML file when `xml`.
TreeModel readWeberPennModel(const std::string& text, const std::string& file, bool xml, const ModelReadOptions& options);

// A species with every field drawn evenly from its documented range, as a model.
TreeModel randomWeberPennModel(std::uint64_t seed);

// The species behind a model; nullptr when another model grew it (Weber-Penn's own tools and tests).
const SpeciesParams* speciesOf(const TreeModel& model);

}  // namespace arbor
