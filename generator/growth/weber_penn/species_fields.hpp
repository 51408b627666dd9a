#pragma once
// The one table of species fields: names, Arbaro names, ranges, defaults and meaning.
// JSON reading and writing, Arbaro XML import, validation and docs/species-format.md all use it.
#include <span>
#include <string>

#include "species.hpp"

namespace arbor {

enum class FieldType { Real, Integer, Text, AngleRule, LeafShape };

struct TreeField {
  const char* key;          // JSON key (Weber-Penn / Nystad name)
  const char* arbaroName;   // Arbaro XML parameter name, or nullptr
  FieldType type;
  double min, max;          // allowed closed range for numbers
  bool required;            // in JSON; optional fields take `fallback`
  double fallback;          // default for optional numeric fields (documented)
  const char* doc;
  double SpeciesParams::*real = nullptr;
  int SpeciesParams::*integer = nullptr;
};

struct LevelField {
  const char* key;          // JSON key inside a StemLevels entry; Arbaro uses "<n>key"
  FieldType type;
  double min, max;
  bool required;
  const char* doc;
  double StemLevelParams::*real = nullptr;
  int StemLevelParams::*integer = nullptr;
};

std::span<const TreeField> treeFields();
std::span<const LevelField> levelFields();

// Names accepted for AngleRule and LeafShape, in their JSON spelling.
const char* angleRuleName(AngleRule rule);
const char* leafKindName(LeafKind kind);
bool parseAngleRule(const std::string& text, AngleRule& out);
bool parseLeafKind(const std::string& text, LeafKind& out);

// "[0, 8]" style text for messages; integers print without decimals.
std::string rangeText(FieldType type, double min, double max);

}  // namespace arbor
