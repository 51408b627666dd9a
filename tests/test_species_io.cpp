// Species files: every preset loads and round-trips; Arbaro XML imports; every class of bad input is
// refused with one message naming the file, the field and what is allowed.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "test_support.hpp"

using namespace arbor;
using nlohmann::json;

namespace {

// A valid species document to break in one place at a time.
json validDocument() { return json::parse(writeSpeciesJson(test::steadySpecies())); }

// The message of the SpeciesError that reading `text` throws ("" if it reads fine).
std::string jsonError(const std::string& text) {
  try {
    readSpeciesJson(text, "bad.json");
  } catch (const SpeciesError& e) {
    return e.what();
  }
  return "";
}

std::string xmlError(const std::string& text) {
  try {
    readSpeciesXml(text, "bad.xml");
  } catch (const SpeciesError& e) {
    return e.what();
  }
  return "";
}

std::string smallXml() { return readFile(std::string(TEST_DATA_DIR) + "/small-arbaro.xml"); }

}  // namespace

TEST_CASE("every preset loads, validates and round-trips through JSON", "[species]") {
  const auto names = test::presetNames();
  REQUIRE(names.size() >= 6);
  for (const std::string& name : names) {
    INFO(name);
    const SpeciesParams p = test::loadPreset(name);
    CHECK(!p.name.empty());
    const std::string once = writeSpeciesJson(p);
    const std::string twice = writeSpeciesJson(readSpeciesJson(once, name));
    CHECK(once == twice);
  }
}

TEST_CASE("the six species the issue names are presets", "[species]") {
  const auto names = test::presetNames();
  for (const char* wanted : {"quaking-aspen", "black-tupelo", "ca-black-oak", "weeping-willow", "lombardy-poplar", "palm"}) {
    CHECK(std::find(names.begin(), names.end(), wanted) != names.end());
  }
}

TEST_CASE("a valid document reads back exactly", "[species]") {
  const SpeciesParams p = readSpeciesJson(validDocument().dump(), "ok.json");
  CHECK(p.levels == 3);
  CHECK(p.stemLevels.size() == 3);
  CHECK(p.stemLevels[1].branches == 12);
  CHECK(p.stemLevels[1].branchRatioGiven);
  CHECK(p.treeShapeExponent == 2.49);  // optional field: its documented default
}

TEST_CASE("unknown fields are refused with a suggestion", "[species][invalid]") {
  json doc = validDocument();
  doc["Brnaches"] = 3;
  const std::string e = jsonError(doc.dump());
  CHECK_THAT(e, Catch::Contains("bad.json") && Catch::Contains("'Brnaches'") && Catch::Contains("unknown field"));
  doc = validDocument();
  doc["StemLevels"][1]["Lenght"] = 0.3;
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels[1].Lenght'") && Catch::Contains("did you mean 'Length'"));
}

TEST_CASE("wrong types are refused naming the expected type and range", "[species][invalid]") {
  json doc = validDocument();
  doc["Levels"] = "three";
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'Levels'") && Catch::Contains("integer in [1, 6]") && Catch::Contains("a string"));
  doc = validDocument();
  doc["StemLevels"][0]["CurveRes"] = 2.5;
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels[0].CurveRes'") && Catch::Contains("not a whole number"));
  doc = validDocument();
  doc["AngleRule"] = "murray";
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'AngleRule'") && Catch::Contains("\"natural\" or \"classic\""));
  doc = validDocument();
  doc["StemLevels"] = json::object();
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels'") && Catch::Contains("array"));
}

TEST_CASE("out-of-range values are refused naming the allowed range", "[species][invalid]") {
  json doc = validDocument();
  doc["Shape"] = 9;
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'Shape'") && Catch::Contains("9 is out of range") && Catch::Contains("[0, 8]"));
  doc = validDocument();
  doc["StemLevels"][2]["Taper"] = 3.5;
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels[2].Taper'") && Catch::Contains("[0, 3]"));
  doc = validDocument();
  doc["TreeShapeExponent"] = 0.5;
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'TreeShapeExponent'") && Catch::Contains("[1.5, 4]"));
  doc = validDocument();
  doc["Levels"] = 5;  // more levels than StemLevels entries
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels'") && Catch::Contains("Levels is 5"));
}

TEST_CASE("NaN and infinities are refused naming the field", "[species][invalid]") {
  std::string text = validDocument().dump(2);
  const std::string key = "\"Scale\": ";
  const auto at = text.find(key);
  REQUIRE(at != std::string::npos);
  text.replace(at + key.size(), text.find(',', at) - at - key.size(), "NaN");
  const std::string e = jsonError(text);
  CHECK_THAT(e, Catch::Contains("'Scale'") && Catch::Contains("NaN") && Catch::Contains("line"));
}

TEST_CASE("missing required fields are named with their range", "[species][invalid]") {
  json doc = validDocument();
  doc.erase("Ratio");
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'Ratio'") && Catch::Contains("missing required field") &&
                                        Catch::Contains("[0.0001, 0.5]"));
  doc = validDocument();
  doc["StemLevels"][1].erase("Rotate");
  CHECK_THAT(jsonError(doc.dump()), Catch::Contains("'StemLevels[1].Rotate'") && Catch::Contains("missing"));
}

TEST_CASE("broken JSON names the line and the field being read", "[species][invalid]") {
  const std::string e = jsonError("{\n  \"Name\": \"x\",\n  \"Shape\": 3,,\n}");
  CHECK_THAT(e, Catch::Contains("invalid JSON at line 3") && Catch::Contains("'Shape'"));
  CHECK_THAT(jsonError("[1, 2]"), Catch::Contains("expected a JSON object"));
}

TEST_CASE("Arbaro XML imports with level prefixes and leaf angles", "[species][xml]") {
  ImportNotes notes;
  const SpeciesParams p = readSpeciesXml(smallXml(), "small-arbaro.xml", &notes);
  CHECK(p.name == "test_shrub");
  CHECK(p.levels == 2);
  REQUIRE(p.stemLevels.size() == 2);
  CHECK(p.stemLevels[0].taper == 0.9);
  CHECK(p.stemLevels[1].branches == 14);
  CHECK(p.stemLevels[1].downAngleV == -20);
  CHECK(p.baseSplits == 1);
  CHECK(p.trunkScale == 1.2);
  // Leaves take the angles of level Levels.
  CHECK(p.leafDownAngle == 35);
  CHECK(p.leafRotate == -90);
  CHECK(p.leafShape == LeafKind::Broad);
  // The file's own DownAngle and SplitAngle, so an Arbaro tree keeps its shape; and so written to JSON.
  CHECK(p.angleRule == AngleRule::Classic);
  CHECK(readSpeciesJson(writeSpeciesJson(p), "converted.json").angleRule == AngleRule::Classic);
  // Absent parameters are reported, never silent; Arbaro-only ones are listed as ignored.
  CHECK(std::find(notes.defaulted.begin(), notes.defaulted.end(), "PruneRatio=0") != notes.defaulted.end());
  CHECK(std::find(notes.ignored.begin(), notes.ignored.end(), "Smooth") != notes.ignored.end());
  CHECK(std::find(notes.ignored.begin(), notes.ignored.end(), "1BranchDist") != notes.ignored.end());
}

TEST_CASE("bad Arbaro files are refused naming the parameter", "[species][xml][invalid]") {
  std::string xml = smallXml();
  CHECK_THAT(xmlError(xml.substr(0, xml.size() / 2)), Catch::Contains("XML error at line"));
  std::string unknown = xml;
  unknown.replace(unknown.find("\"Smooth\""), 8, "\"Smoth\"");
  CHECK_THAT(xmlError(unknown), Catch::Contains("'Smoth'") && Catch::Contains("unknown Arbaro parameter"));
  std::string nan = xml;
  nan.replace(nan.find("value=\"0.03\""), 12, "value=\"nan\"");
  CHECK_THAT(xmlError(nan), Catch::Contains("'Ratio'") && Catch::Contains("not a finite number"));
  std::string range = xml;
  range.replace(range.find("value=\"137\""), 11, "value=\"400\"");
  CHECK_THAT(xmlError(range), Catch::Contains("'1Rotate'") && Catch::Contains("[-360, 360]"));
  std::string missing = xml;
  missing.erase(missing.find("<param name=\"1Length\""), std::string("<param name=\"1Length\" value=\"0.45\"/>").size());
  CHECK_THAT(xmlError(missing), Catch::Contains("'1Length'") && Catch::Contains("missing parameter"));
  CHECK_THAT(xmlError("<arbaro><tree/></arbaro>"), Catch::Contains("expected <arbaro><species"));
}

TEST_CASE("unknown file types and missing files are refused", "[species][invalid]") {
  CHECK_THROWS_WITH(loadSpeciesFile("tree.yaml"), Catch::Contains("tree.yaml") && Catch::Contains(".json"));
  CHECK_THROWS_WITH(loadSpeciesFile("/nonexistent/tree.json"), Catch::Contains("cannot be opened"));
}

TEST_CASE("all of Arbaro's species files import", "[species][xml][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  for (const std::string& file : files) {
    INFO(file);
    ImportNotes notes;
    CHECK_NOTHROW(loadSpeciesFile(file, &notes));
  }
  CHECK(files.size() == 16);
}

TEST_CASE("docs/species-format.md is the documentation the parser generates", "[species][docs]") {
  CHECK(readFile(std::string(ARBOR_SOURCE_DIR) + "/docs/species-format.md") == speciesFormatMarkdown());
}
