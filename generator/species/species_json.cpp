// Arbor's own species format: a JSON object whose keys are the Weber-Penn / Nystad parameter names.
#include <cmath>
#include <nlohmann/json.hpp>

#include "species_fields.hpp"
#include "species_io.hpp"
#include "common/atomic_file.hpp"
#include "common/text_util.hpp"

namespace arbor {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr const char* kFormatKey = "Format";
constexpr const char* kFormatValue = "arbor-species/1";
constexpr const char* kLevelsKey = "StemLevels";

std::string typeName(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

// Reads one numeric field with its type and range checked.
double readNumber(const json& v, FieldType type, double min, double max, const std::string& file,
                  const std::string& field) {
  if (!v.is_number()) {
    throw SpeciesError(file, field, "expected " + rangeText(type, min, max) + ", got " + typeName(v));
  }
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw SpeciesError(file, field, "not a finite number; allowed " + rangeText(type, min, max));
  if (type == FieldType::Integer && x != std::floor(x)) {
    throw SpeciesError(file, field, formatNumber(x) + " is not a whole number; allowed " + rangeText(type, min, max));
  }
  if (x < min || x > max) {
    throw SpeciesError(file, field, formatNumber(x) + " is out of range; allowed " + rangeText(type, min, max));
  }
  return x;
}

std::string readString(const json& v, const std::string& file, const std::string& field, const std::string& allowed) {
  if (!v.is_string()) throw SpeciesError(file, field, "expected " + allowed + ", got " + typeName(v));
  return v.get<std::string>();
}

template <class Fields>
void rejectUnknownKeys(const json& object, const Fields& fields, const std::string& file, const std::string& prefix,
                       std::initializer_list<const char*> extra) {
  std::vector<std::string> known;
  for (const auto& f : fields) known.emplace_back(f.key);
  for (const char* e : extra) known.emplace_back(e);
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    std::string message = "unknown field";
    const std::string guess = closestName(it.key(), known);
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    throw SpeciesError(file, prefix + it.key(), message);
  }
}

void readTreeField(const json& root, const TreeField& f, SpeciesParams& p, const std::string& file) {
  const std::string field = f.key;
  if (!root.contains(f.key)) {
    if (f.required) {
      std::string allowed = f.type == FieldType::Text ? "a string" : rangeText(f.type, f.min, f.max);
      throw SpeciesError(file, field, "missing required field (" + allowed + ")");
    }
    if (f.real) p.*f.real = f.fallback;
    if (f.integer) p.*f.integer = static_cast<int>(f.fallback);
    return;
  }
  const json& v = root.at(f.key);
  switch (f.type) {
    case FieldType::Text:
      p.name = readString(v, file, field, "a string");
      if (p.name.empty()) throw SpeciesError(file, field, "must not be empty");
      break;
    case FieldType::AngleRule: {
      const std::string s = readString(v, file, field, "\"natural\" or \"classic\"");
      if (!parseAngleRule(s, p.angleRule))
        throw SpeciesError(file, field, "'" + s + "' is not allowed; use \"natural\" or \"classic\"");
      break;
    }
    case FieldType::LeafShape: {
      const std::string allowed = "\"broad\", \"narrow\", \"frond\" or \"needle\"";
      const std::string s = readString(v, file, field, allowed);
      if (!parseLeafKind(s, p.leafShape)) throw SpeciesError(file, field, "'" + s + "' is not allowed; use " + allowed);
      break;
    }
    case FieldType::Real: p.*f.real = readNumber(v, f.type, f.min, f.max, file, field); break;
    case FieldType::Integer:
      p.*f.integer = static_cast<int>(readNumber(v, f.type, f.min, f.max, file, field));
      break;
  }
}

StemLevelParams readLevel(const json& entry, std::size_t index, const std::string& file) {
  const std::string prefix = std::string(kLevelsKey) + "[" + std::to_string(index) + "].";
  if (!entry.is_object()) throw SpeciesError(file, prefix.substr(0, prefix.size() - 1), "expected an object");
  rejectUnknownKeys(entry, levelFields(), file, prefix, {});
  StemLevelParams lp;
  for (const LevelField& f : levelFields()) {
    const std::string field = prefix + f.key;
    if (!entry.contains(f.key)) {
      if (f.required) throw SpeciesError(file, field, "missing required field (" + rangeText(f.type, f.min, f.max) + ")");
      continue;
    }
    const double x = readNumber(entry.at(f.key), f.type, f.min, f.max, file, field);
    if (f.real) lp.*f.real = x;
    if (f.integer) lp.*f.integer = static_cast<int>(x);
    if (f.real == &StemLevelParams::branchRatio) lp.branchRatioGiven = true;
  }
  return lp;
}

// nlohmann reports a byte offset; name the line, column and the field being read there.
[[noreturn]] void throwParseError(const std::string& text, const json::parse_error& e, const std::string& file) {
  const std::size_t at = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
  }
  std::string field = lastJsonKeyBefore(text, at);
  std::string message = "invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(column);
  const std::string tail = text.substr(at, 8);
  if (tail.rfind("NaN", 0) == 0 || tail.rfind("Inf", 0) == 0 || tail.rfind("-Inf", 0) == 0 ||
      tail.rfind("nan", 0) == 0 || tail.rfind("inf", 0) == 0) {
    message += ": NaN and Infinity are not numbers in JSON; give a finite number";
  }
  throw SpeciesError(file, field.empty() ? "(document)" : field, message);
}

}  // namespace

SpeciesParams readSpeciesJson(const std::string& text, const std::string& file) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throwParseError(text, e, file);
  }
  if (!root.is_object()) throw SpeciesError(file, "(document)", "expected a JSON object of species parameters");

  std::vector<const char*> extra = {kFormatKey, kLevelsKey};
  rejectUnknownKeys(root, treeFields(), file, "", {kFormatKey, kLevelsKey});
  if (root.contains(kFormatKey)) {
    const std::string fmt = readString(root.at(kFormatKey), file, kFormatKey, "\"arbor-species/1\"");
    if (fmt != kFormatValue) throw SpeciesError(file, kFormatKey, "'" + fmt + "' is not supported; use \"arbor-species/1\"");
  }

  SpeciesParams p;
  p.source = file;
  for (const TreeField& f : treeFields()) readTreeField(root, f, p, file);

  if (!root.contains(kLevelsKey)) {
    throw SpeciesError(file, kLevelsKey, "missing required field (an array with one object per stem level)");
  }
  const json& levels = root.at(kLevelsKey);
  if (!levels.is_array() || levels.empty() || levels.size() > 8) {
    throw SpeciesError(file, kLevelsKey, "expected an array of 1 to 8 level objects, got " + typeName(levels));
  }
  for (std::size_t i = 0; i < levels.size(); ++i) p.stemLevels.push_back(readLevel(levels[i], i, file));

  validateSpecies(p, file);
  return p;
}

std::string writeSpeciesJson(const SpeciesParams& p) {
  ordered_json root;
  root[kFormatKey] = kFormatValue;
  for (const TreeField& f : treeFields()) {
    switch (f.type) {
      case FieldType::Text: root[f.key] = p.name; break;
      case FieldType::AngleRule: root[f.key] = angleRuleName(p.angleRule); break;
      case FieldType::LeafShape: root[f.key] = leafKindName(p.leafShape); break;
      case FieldType::Real: root[f.key] = p.*f.real; break;
      case FieldType::Integer: root[f.key] = p.*f.integer; break;
    }
  }
  ordered_json levels = ordered_json::array();
  for (const StemLevelParams& lp : p.stemLevels) {
    ordered_json entry;
    for (const LevelField& f : levelFields()) {
      if (f.real == &StemLevelParams::branchRatio && !lp.branchRatioGiven) continue;
      if (f.real) entry[f.key] = lp.*f.real;
      if (f.integer) entry[f.key] = lp.*f.integer;
    }
    levels.push_back(entry);
  }
  root[kLevelsKey] = levels;
  return root.dump(2) + "\n";
}

void validateSpecies(const SpeciesParams& p, const std::string& file) {
  if (static_cast<int>(p.stemLevels.size()) < p.levels) {
    throw SpeciesError(file, "StemLevels",
                       "has " + std::to_string(p.stemLevels.size()) + " entries but Levels is " +
                           std::to_string(p.levels) + "; every stem level needs its entry");
  }
  const double trunks = p.stemLevels[0].branches;
  if (trunks < 1 || trunks > 64 || trunks != std::floor(trunks)) {
    throw SpeciesError(file, "StemLevels[0].Branches",
                       formatNumber(trunks) + " trunks is not allowed; allowed integer in [1, 64]");
  }
  if (p.stemLevels[0].length <= 0) {
    throw SpeciesError(file, "StemLevels[0].Length", "the trunk needs a length; allowed number in (0, 50]");
  }
}

SpeciesParams loadSpeciesFile(const std::string& path, ImportNotes* notes) {
  const bool json = endsWith(path, ".json"), xml = endsWith(path, ".xml");
  if (!json && !xml) throw SpeciesError(path, "(file)", "unknown species file type; use .json (Arbor) or .xml (Arbaro)");
  std::string text;
  try {
    text = readFile(path);
  } catch (const std::runtime_error&) {
    throw SpeciesError(path, "(file)", "cannot be opened for reading");
  }
  return json ? readSpeciesJson(text, path) : readSpeciesXml(text, path, notes);
}

SpeciesError::SpeciesError(std::string file, std::string field, const std::string& message)
    : std::runtime_error(file + ": field '" + field + "': " + message), file_(std::move(file)), field_(std::move(field)) {}

}  // namespace arbor
