// Arbor's own species format: a JSON object whose keys are the Weber-Penn / Nystad parameter names.
#include <cmath>
#include <nlohmann/json.hpp>

#include "species_fields.hpp"
#include "species_io.hpp"
#include "common/atomic_file.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "growth/json_fields.hpp"

namespace arbor {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr const char* kFormatKey = "Format";
constexpr const char* kFormatValue = "arbor-species/1";
constexpr const char* kLevelsKey = "StemLevels";
constexpr const char* kModelKey = "model";  // the growth model a file names (growth/growth_models.cpp)

using json_fields::typeName;

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
      requireSpeciesName(p.name, file, field);
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
[[noreturn]] void throwParseError(const std::string& text, std::size_t byte, const std::string& file) {
  const std::size_t at = std::min<std::size_t>(byte == 0 ? 0 : byte - 1, text.size());
  std::string field = lastJsonKeyBefore(text, at);
  std::string message = "invalid JSON at " + lineAndColumn(text, at);
  const std::string tail = text.substr(at, 8);
  if (tail.rfind("NaN", 0) == 0 || tail.rfind("Inf", 0) == 0 || tail.rfind("-Inf", 0) == 0 ||
      tail.rfind("nan", 0) == 0 || tail.rfind("inf", 0) == 0) {
    message += ": NaN and Infinity are not numbers in JSON; give a finite number";
  }
  throw SpeciesError(file, field.empty() ? "(document)" : field, message);
}

// Brackets nested deeper than any species file needs are refused before the parser recurses into them.
void requireShallow(const std::string& text, const std::string& file, int maxDepth) {
  const std::size_t at = jsonNestingPast(text, maxDepth);
  if (at == std::string::npos) return;
  throw SpeciesError(file, "(document)", "nested deeper than " + std::to_string(maxDepth) + " levels at " + lineAndColumn(text, at) +
                                             "; a species file is an object of numbers with one array of level objects");
}

// Where the parser stands: one frame per open object or array, so that a repeated key can be named by its path.
struct JsonPath {
  struct Frame {
    bool object = false;
    std::vector<std::string> keys;  // objects: keys seen so far
    std::size_t index = 0;          // arrays: the element being read
  };
  std::vector<Frame> frames;

  std::string prefix() const {
    std::string out;
    for (const Frame& f : frames) {
      if (f.object && !f.keys.empty() && &f != &frames.back()) out += (out.empty() ? "" : ".") + f.keys.back();
      if (!f.object) out += "[" + std::to_string(f.index) + "]";
    }
    return out;
  }
  void elementDone() {
    if (!frames.empty() && !frames.back().object) ++frames.back().index;
  }
};

// Parses with nlohmann, refusing what it would silently accept: a key given twice in one object (the last one
// would win) and numbers beyond a double (reported by the library without a place).
json parseStrict(const std::string& text, const std::string& file) {
  JsonPath path;
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: path.frames.push_back({true, {}, 0}); break;
      case json::parse_event_t::array_start: path.frames.push_back({false, {}, 0}); break;
      case json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        auto& keys = path.frames.back().keys;
        if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
          const std::string prefix = path.prefix();
          throw SpeciesError(file, prefix.empty() ? key : prefix + "." + key, "given twice in one object; give each field once");
        }
        keys.push_back(key);
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        path.frames.pop_back();
        path.elementDone();
        break;
      case json::parse_event_t::value: path.elementDone(); break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::parse_error& e) {
    throwParseError(text, e.byte, file);
  } catch (const json::out_of_range& e) {
    // "number overflow parsing '1e309'": find the number to name its place and field.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string token = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = token.empty() ? std::string::npos : text.find(token);
    const std::string field = at == std::string::npos ? "" : lastJsonKeyBefore(text, at);
    throw SpeciesError(file, field.empty() ? "(document)" : field,
                       (token.empty() ? std::string("a number") : "'" + token + "'") + " is beyond the range of a double" +
                           (at == std::string::npos ? "" : " at " + lineAndColumn(text, at)) + "; give a finite number");
  } catch (const json::exception& e) {
    throw SpeciesError(file, "(document)", std::string("invalid JSON: ") + e.what());
  }
}

}  // namespace

SpeciesParams readSpeciesJson(const std::string& text, const std::string& file) {
  requireText(text, file);
  requireShallow(text, file, 8);
  const json root = parseStrict(text, file);
  if (!root.is_object()) throw SpeciesError(file, "(document)", "expected a JSON object of species parameters");

  rejectUnknownKeys(root, treeFields(), file, "", {kFormatKey, kLevelsKey, kModelKey});
  if (root.contains(kModelKey)) {
    const std::string model = readString(root.at(kModelKey), file, kModelKey, "\"" + std::string(kWeberPennModel) + "\"");
    if (model != kWeberPennModel) throw SpeciesError(file, kModelKey, "'" + model + "' is not this model; a species file is \"" + kWeberPennModel + "\"");
  }
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
  root[kModelKey] = kWeberPennModel;
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

void requireSpeciesName(const std::string& name, const std::string& file, const std::string& field) {
  const std::string allowed = "; allowed: 1 to 200 bytes of printable UTF-8 text";
  if (name.empty() || name.size() > 200) throw SpeciesError(file, field, "has " + std::to_string(name.size()) + " bytes" + allowed);
  if (!isValidUtf8(name)) throw SpeciesError(file, field, "is not valid UTF-8" + allowed);
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) throw SpeciesError(file, field, "holds a control character" + allowed);
  }
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
  const std::string text = readInputFile(path, kMaxSpeciesFileBytes);
  return json ? readSpeciesJson(text, path) : readSpeciesXml(text, path, notes);
}

}  // namespace arbor
