#pragma once
// Reading and writing species files: Arbor JSON (documented in docs/species-format.md) and Arbaro XML.
#include <stdexcept>
#include <string>
#include <vector>

#include "species.hpp"

namespace arbor {

// Bad input: names the file, the field and what is allowed. Callers exit with code 2.
class SpeciesError : public std::runtime_error {
 public:
  SpeciesError(std::string file, std::string field, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

// Parameters an Arbaro file left out and the default each took (reported, never silent).
struct ImportNotes {
  std::vector<std::string> defaulted;  // "0Branches=1", ...
  std::vector<std::string> ignored;    // Arbaro parameters read but not used ("Smooth", ...)
};

SpeciesParams readSpeciesJson(const std::string& text, const std::string& file);
SpeciesParams readSpeciesXml(const std::string& text, const std::string& file, ImportNotes* notes = nullptr);

// Loads by extension: .json (Arbor) or .xml (Arbaro). Throws SpeciesError.
SpeciesParams loadSpeciesFile(const std::string& path, ImportNotes* notes = nullptr);

// Canonical Arbor JSON: every field written, in table order.
std::string writeSpeciesJson(const SpeciesParams& params);

// The field-by-field documentation of the format (docs/species-format.md).
std::string speciesFormatMarkdown();

// Range and cross-field checks shared by both readers.
void validateSpecies(const SpeciesParams& params, const std::string& file);

}  // namespace arbor
