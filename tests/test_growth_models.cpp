// The growth-model interface: model files read by the model they name, models passed as values, parameters
// edited through the generic table, and Weber-Penn behind it growing exactly what it grew before.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "growth/growth_models.hpp"
#include "growth/skeleton_json.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "growth/weber_penn/weber_penn.hpp"
#include "growth/weber_penn/weber_penn_model.hpp"
#include "test_support.hpp"

using namespace arbor;

namespace {

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

// The skeleton file as written before stems carried their stub flag (so hashes recorded then still apply).
std::string withoutStubFlags(std::string text) {
  for (const char* field : {", \"stub\": false", ", \"stub\": true"}) {
    for (std::size_t at = text.find(field); at != std::string::npos; at = text.find(field, at)) text.erase(at, std::strlen(field));
  }
  return text;
}

std::string presetText(const std::string& name) { return readFile(std::string(ARBOR_ASSET_DIR) + "/presets/" + name + ".json"); }

std::string modelError(const std::string& text, const std::string& file = "m.json") {
  try {
    readModelFile(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("every preset grows the skeleton it grew before growth models existed (hash of its JSON, seed 1)", "[growth-models]") {
  // FNV-1a of `arbor generate PRESET --seed 1 --out x.json` as written by commit a92d57d, before the interface.
  const std::pair<const char*, std::uint64_t> recorded[] = {
      {"black-tupelo", 0xd15b1f93d42130ddull},    {"ca-black-oak", 0xc22e7011ea60df4full},
      {"lombardy-poplar", 0xd12aba40f8281679ull}, {"palm", 0xdd439b0fcf14226dull},
      {"quaking-aspen", 0x5a6c3a7fa72ef02full},   {"weeping-willow", 0x7e36ad31048721d6ull}};
  for (const auto& [preset, hash] : recorded) {
    INFO(preset);
    const TreeModel model = readModelFile(presetText(preset), std::string(preset) + ".json");
    CHECK(std::string(model.model()) == "weber-penn");
    GrowthOptions growth;
    growth.seed = 1;
    CHECK(fnv1a(withoutStubFlags(writeSkeletonJson(model.grow(growth)))) == hash);
  }
}

TEST_CASE("a model file names its model, none named is Weber-Penn, an unknown one is refused naming those allowed", "[growth-models]") {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(presetText("palm"));
  doc.erase("model");
  const TreeModel plain = readModelFile(doc.dump(), "palm.json");
  doc["model"] = "weber-penn";
  const TreeModel named = readModelFile(doc.dump(), "palm.json");
  CHECK(std::string(plain.model()) == "weber-penn");
  CHECK(plain.toJson() == named.toJson());
  CHECK(plain.toJson().find("\"model\": \"weber-penn\"") != std::string::npos);

  doc["model"] = "self-organizing";
  CHECK_THAT(modelError(doc.dump()), Catch::Contains("m.json") && Catch::Contains("model") &&
                                         Catch::Contains("'self-organizing' is not a growth model") && Catch::Contains("\"weber-penn\""));
  doc["model"] = "l-system";  // a model with a file type of its own is not read from JSON
  CHECK_THAT(modelError(doc.dump()), Catch::Contains("'l-system' models are read from .lsys files"));
  doc["model"] = 3;
  CHECK_THAT(modelError(doc.dump()), Catch::Contains("model") && Catch::Contains("allowed: \"weber-penn\""));
  CHECK_THAT(modelError("{}", "m.txt"), Catch::Contains("unknown model file type"));
  // A file too broken to name a model still gets the species reader's precise message.
  CHECK_THAT(modelError("{\"Name\": \"x\",}"), Catch::Contains("line 1"));
  CHECK_THAT(modelError(std::string(100, '[')), Catch::Contains("nested deeper"));
  // Weber-Penn's own reader refuses another model's name too.
  CHECK_THROWS_WITH(readSpeciesJson(doc.dump(), "m.json"), Catch::Contains("model"));
}

TEST_CASE("an Arbaro XML file is a Weber-Penn model, natural angles are a read option", "[growth-models]") {
  const std::string xml = readFile(std::string(TEST_DATA_DIR) + "/small-arbaro.xml");
  const TreeModel file = readModelFile(xml, "small.xml");
  const TreeModel natural = readModelFile(xml, "small.xml", ModelReadOptions{true, nullptr});
  REQUIRE(speciesOf(file));
  CHECK(speciesOf(file)->angleRule == AngleRule::Classic);
  CHECK(speciesOf(natural)->angleRule == AngleRule::Natural);
}

TEST_CASE("a tree model is a value: an edited copy leaves the original alone, and edits keep to the documented range", "[growth-models]") {
  const TreeModel original = weberPennModel(test::loadPreset("palm"));
  TreeModel copy = original;
  const std::vector<ModelParameter> parameters = copy.parameters();
  REQUIRE(!parameters.empty());
  std::size_t scale = parameters.size(), trunks = parameters.size();
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i].key == "Scale" && parameters[i].group.empty()) scale = i;
    if (parameters[i].key == "Branches" && parameters[i].group == "level 0") trunks = i;
  }
  REQUIRE(scale < parameters.size());
  REQUIRE(trunks < parameters.size());
  const double before = original.value(scale);
  copy.setValue(scale, before * 2.0);
  CHECK(copy.value(scale) == Approx(before * 2.0));
  CHECK(original.value(scale) == before);
  copy.setValue(scale, 1e300);
  CHECK(copy.value(scale) == parameters[scale].max);
  // The trunk count is a whole number of trunks, 1 to 64 (the hub's ports).
  CHECK(parameters[trunks].integer);
  CHECK(parameters[trunks].max == 64.0);
  copy.setValue(trunks, 2.6);
  CHECK(copy.value(trunks) == 3.0);
  CHECK(speciesOf(copy)->stemLevels[0].branches == 3.0);
  CHECK(speciesOf(original)->stemLevels[0].branches != 3.0);
}

TEST_CASE("the model list holds Weber-Penn with its format documentation and random parameters", "[growth-models]") {
  REQUIRE(!growthModels().empty());
  const GrowthModelInfo& wp = growthModels().front();
  CHECK(std::string(wp.name) == "weber-penn");
  CHECK(wp.formatMarkdown() == speciesFormatMarkdown());
  const TreeModel random = wp.random(7);
  CHECK(readModelFile(random.toJson(), "r.json").toJson() == random.toJson());
}

TEST_CASE("the space-colonization row draws random models that read back as that model", "[growth-models]") {
  const GrowthModelInfo* row = nullptr;
  for (const GrowthModelInfo& m : growthModels())
    if (std::string(m.name) == "space-colonization") row = &m;
  REQUIRE(row != nullptr);
  REQUIRE(row->random != nullptr);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TreeModel random = row->random(seed);
    CHECK(std::string(random.model()) == "space-colonization");
    CHECK(readModelFile(random.toJson(), "r.json").toJson() == random.toJson());
  }
}
