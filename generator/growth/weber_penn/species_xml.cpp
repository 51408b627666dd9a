// Import of Arbaro's species files: <arbaro><species name=...><param name="NAME" value="V"/>...
// Per-level parameters carry the level as a prefix ("1Branches"); leaves use level min(Levels, 3).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <tinyxml2.h>

#include "species_fields.hpp"
#include "species_io.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"

namespace arbor {

namespace {

constexpr int kArbaroLevels = 4;  // Arbaro files describe levels 0..3

// Arbaro parameters that describe its own mesher or placement extras; read, reported, not used.
const std::vector<std::string> kIgnored = {"Smooth", "BranchDist"};

// Per-level parameters that may be absent (Arbaro supplies these defaults itself).
const std::map<std::string, double> kLevelDefaults = {
    {"SegSplits", 0}, {"SplitAngle", 0}, {"SplitAngleV", 0}, {"CurveBack", 0}, {"LengthV", 0}, {"RotateV", 0},
    {"DownAngleV", 0}, {"CurveV", 0}, {"Curve", 0}, {"Taper", 1}};
// Trunk entries that only matter for several trunks.
const std::map<std::string, double> kTrunkDefaults = {
    {"Branches", 1}, {"DownAngle", 0}, {"DownAngleV", 0}, {"Rotate", 0}, {"RotateV", 0}};

double parseValue(const std::string& text, const std::string& file, const std::string& name) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  while (end && *end && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (end == begin || (end && *end != '\0')) {
    throw SpeciesError(file, name, "value '" + text + "' is not a number");
  }
  if (!std::isfinite(x)) throw SpeciesError(file, name, "value '" + text + "' is not a finite number");
  return x;
}

// Arbaro's leaf shapes by name or number onto the four kinds of the leaf atlas.
LeafKind leafKindFromArbaro(const std::string& value, double scaleX) {
  if (value == "palm" || value == "8") return LeafKind::Frond;
  if (value == "sphere" || value == "cylinder" || value == "9") return LeafKind::Needle;
  return scaleX <= 0.3 ? LeafKind::Narrow : LeafKind::Broad;
}

struct RawParams {
  std::map<std::string, std::string> values;  // Arbaro name -> text
};

}  // namespace

SpeciesParams readSpeciesXml(const std::string& text, const std::string& file, ImportNotes* notes) {
  requireText(text, file);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    throw SpeciesError(file, "(document)",
                       "XML error at line " + std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr());
  }
  const tinyxml2::XMLElement* root = doc.FirstChildElement("arbaro");
  const tinyxml2::XMLElement* species = root ? root->FirstChildElement("species") : nullptr;
  if (!species) throw SpeciesError(file, "(document)", "expected <arbaro><species ...> as in Arbaro's species files");

  RawParams raw;
  for (const tinyxml2::XMLElement* e = species->FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::string(e->Name()) != "param") {
      throw SpeciesError(file, e->Name(), "unexpected element at line " + std::to_string(e->GetLineNum()) +
                                              "; only <param name=... value=.../> is allowed");
    }
    const char* name = e->Attribute("name");
    const char* value = e->Attribute("value");
    if (!name || !value) {
      throw SpeciesError(file, name ? name : "(param)",
                         "<param> at line " + std::to_string(e->GetLineNum()) + " needs name and value attributes");
    }
    if (!raw.values.emplace(name, value).second) {
      throw SpeciesError(file, name, "given twice (again at line " + std::to_string(e->GetLineNum()) + "); give each parameter once");
    }
  }

  SpeciesParams p;
  p.source = file;
  const char* speciesName = species->Attribute("name");
  p.name = speciesName && *speciesName ? speciesName : "unnamed";
  requireSpeciesName(p.name, file, "name");
  p.angleRule = AngleRule::Classic;  // the file's own DownAngle and SplitAngle: an Arbaro tree keeps its shape

  ImportNotes local;
  ImportNotes& out = notes ? *notes : local;
  std::map<std::string, bool> used;

  auto take = [&](const std::string& name) -> const std::string* {
    auto it = raw.values.find(name);
    if (it == raw.values.end()) return nullptr;
    used[name] = true;
    return &it->second;
  };

  // Tree-level parameters, checked against the same ranges as the JSON format.
  for (const TreeField& f : treeFields()) {
    if (!f.arbaroName || f.type == FieldType::Text) continue;
    if (f.type == FieldType::LeafShape) continue;  // mapped below, needs LeafScaleX
    const std::string* v = take(f.arbaroName);
    if (!v) {
      if (f.required) throw SpeciesError(file, f.arbaroName, "missing required parameter (" + rangeText(f.type, f.min, f.max) + ")");
      if (f.real) p.*f.real = f.fallback;
      if (f.integer) p.*f.integer = static_cast<int>(f.fallback);
      out.defaulted.push_back(std::string(f.arbaroName) + "=" + formatNumber(f.fallback));
      continue;
    }
    const double x = parseValue(*v, file, f.arbaroName);
    if ((f.type == FieldType::Integer && x != std::floor(x)) || x < f.min || x > f.max) {
      throw SpeciesError(file, f.arbaroName, formatNumber(x) + " is out of range; allowed " + rangeText(f.type, f.min, f.max));
    }
    if (f.real) p.*f.real = x;
    if (f.integer) p.*f.integer = static_cast<int>(x);
  }
  if (const std::string* shape = take("LeafShape")) {
    p.leafShape = leafKindFromArbaro(*shape, p.leafScaleX);
  } else {
    p.leafShape = LeafKind::Broad;
    out.defaulted.push_back("LeafShape=broad");
  }

  // Stem levels 0..Levels-1, each from "<n>Name" parameters.
  const int stemLevelCount = std::min(p.levels, kArbaroLevels);
  for (int n = 0; n < stemLevelCount; ++n) {
    StemLevelParams lp;
    for (const LevelField& f : levelFields()) {
      if (f.real == &StemLevelParams::branchRatio) continue;  // not an Arbaro parameter
      const std::string name = std::to_string(n) + f.key;
      const std::string* v = take(name);
      double x = 0;
      if (v) {
        x = parseValue(*v, file, name);
        if (f.key == std::string("CurveV") && x < 0) {
          throw SpeciesError(file, name, formatNumber(x) + ": helical stems (CurveV < 0) are not supported; allowed " +
                                             rangeText(f.type, f.min, f.max));
        }
        if ((f.type == FieldType::Integer && x != std::floor(x)) || x < f.min || x > f.max) {
          throw SpeciesError(file, name, formatNumber(x) + " is out of range; allowed " + rangeText(f.type, f.min, f.max));
        }
      } else {
        const auto& defaults = n == 0 && kTrunkDefaults.count(f.key) ? kTrunkDefaults : kLevelDefaults;
        auto d = defaults.find(f.key);
        if (d == defaults.end()) {
          throw SpeciesError(file, name, "missing parameter for stem level " + std::to_string(n) + " (" +
                                             rangeText(f.type, f.min, f.max) + ")");
        }
        x = d->second;
        out.defaulted.push_back(name + "=" + formatNumber(x));
      }
      if (f.real) lp.*f.real = x;
      if (f.integer) lp.*f.integer = static_cast<int>(x);
    }
    p.stemLevels.push_back(lp);
  }
  if (p.levels > kArbaroLevels) {
    throw SpeciesError(file, "Levels", std::to_string(p.levels) + " levels; Arbaro files describe at most 4 (integer in [1, 4])");
  }

  // Leaves take the angles of the level below the deepest stems (Arbaro clamps to level 3).
  const int leafLevel = std::min(p.levels, kArbaroLevels - 1);
  const std::pair<const char*, double SpeciesParams::*> leafAngles[] = {
      {"DownAngle", &SpeciesParams::leafDownAngle},
      {"DownAngleV", &SpeciesParams::leafDownAngleV},
      {"Rotate", &SpeciesParams::leafRotate},
      {"RotateV", &SpeciesParams::leafRotateV}};
  for (const auto& [key, member] : leafAngles) {
    const std::string name = std::to_string(leafLevel) + key;
    auto it = raw.values.find(name);
    if (it != raw.values.end()) {
      used[name] = true;
      const double x = parseValue(it->second, file, name);
      for (const TreeField& f : treeFields()) {
        if (f.real == member && (x < f.min || x > f.max)) {
          throw SpeciesError(file, name, formatNumber(x) + " is out of range for a leaf angle; allowed " + rangeText(f.type, f.min, f.max));
        }
      }
      p.*member = x;
    } else {
      for (const TreeField& f : treeFields()) {
        if (f.real == member) p.*member = f.fallback;
      }
      out.defaulted.push_back(name + "=" + formatNumber(p.*member) + " (leaf angle)");
    }
  }

  // Everything else must be a known Arbaro parameter of a level we do not use, or an ignored one.
  for (const auto& [name, value] : raw.values) {
    if (used.count(name)) continue;
    std::string bare = name;
    int level = -1;
    if (!bare.empty() && std::isdigit(static_cast<unsigned char>(bare[0]))) {
      level = bare[0] - '0';
      bare = bare.substr(1);
    }
    const bool ignored = std::find(kIgnored.begin(), kIgnored.end(), bare) != kIgnored.end();
    const LevelField* levelField = nullptr;
    for (const LevelField& f : levelFields()) {
      if (bare == f.key) levelField = &f;
    }
    if (ignored || (levelField && level >= 0 && level < kArbaroLevels)) {
      const double x = parseValue(value, file, name);  // still must be a number, and in range where it has one
      if (levelField && (x < levelField->min || x > levelField->max)) {
        throw SpeciesError(file, name, formatNumber(x) + " is out of range; allowed " + rangeText(levelField->type, levelField->min, levelField->max));
      }
      out.ignored.push_back(name);
      continue;
    }
    std::vector<std::string> known;
    for (const TreeField& f : treeFields()) {
      if (f.arbaroName) known.emplace_back(f.arbaroName);
    }
    for (const LevelField& f : levelFields()) known.push_back("1" + std::string(f.key));
    std::string message = "unknown Arbaro parameter";
    const std::string guess = closestName(name, known);
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    throw SpeciesError(file, name, message);
  }

  validateSpecies(p, file);
  return p;
}

}  // namespace arbor
