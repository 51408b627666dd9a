#pragma once
// Reading and writing species files: Arbor JSON (documented in docs/species-format.md) and Arbaro XML.
#include <cstdint>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "growth/growth_model.hpp"
#include "species.hpp"

namespace arbor {

// Bad input: names the file, the field and what is allowed. Callers exit with code 2.
class SpeciesError : public InputError {
 public:
  using InputError::InputError;
};

// The name species files give their growth model ("model": "weber-penn"; absent means the same).
constexpr const char* kWeberPennModel = "weber-penn";

// Species files are small; anything larger is refused before it is parsed.
constexpr std::size_t kMaxSpeciesFileBytes = 1024 * 1024;

SpeciesParams readSpeciesJson(const std::string& text, const std::string& file);
SpeciesParams readSpeciesXml(const std::string& text, const std::string& file, ImportNotes* notes = nullptr);

// Loads by extension: .json (Arbor) or .xml (Arbaro). Throws SpeciesError.
SpeciesParams loadSpeciesFile(const std::string& path, ImportNotes* notes = nullptr);

// Canonical Arbor JSON: every field written, in table order.
std::string writeSpeciesJson(const SpeciesParams& params);

// The field-by-field documentation of the format (docs/species-format.md).
std::string speciesFormatMarkdown();

// A species name is 1 to 200 bytes of printable UTF-8 (it reaches terminals and JSON files unchanged).
void requireSpeciesName(const std::string& name, const std::string& file, const std::string& field);

// A species with every field drawn evenly from its documented range (stress tests; the same seed, the same species).
SpeciesParams randomSpecies(std::uint64_t seed);

// Range and cross-field checks shared by both readers.
void validateSpecies(const SpeciesParams& params, const std::string& file);

}  // namespace arbor
