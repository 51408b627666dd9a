// The arbor program as a user runs it: exit codes, messages naming file and field, nothing half-written.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstring>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <cctype>
#include <sstream>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

using Result = arbor::test::CommandResult;

Result run(const std::string& arguments) { return arbor::test::runCommand(std::string(ARBOR_BINARY) + " " + arguments + " 2>&1"); }

std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = arbor::test::tempPath(name);
  std::ofstream(path) << content;
  return path;
}

// The JSON chunk of a GLB file (after the 12-byte header and the chunk's 8-byte header).
nlohmann::json readGlbJson(const std::string& path) {
  const std::string bytes = arbor::readFile(path);
  std::uint32_t length = 0;
  REQUIRE(bytes.size() > 20);
  std::memcpy(&length, bytes.data() + 12, 4);
  return nlohmann::json::parse(bytes.substr(20, length));
}

// Every preset of every growth model: assets/presets/*.json and assets/lsystems/*.lsys, by name.
std::vector<std::string> allPresets() {
  std::vector<std::string> names;
  for (const char* folder : {"presets", "lsystems"})
    for (const auto& e : fs::directory_iterator(fs::path(ARBOR_ASSET_DIR) / folder)) names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("arbor starts without Vulkan, GLFW or X11 and hands the engine's commands to arbor-engine beside it", "[cli]") {
  // What the dynamic loader maps for the commands without a GPU or window (a third of a small export's start-up).
  const Result needed = arbor::test::runCommand("readelf -d " + std::string(ARBOR_BINARY) + " 2>&1");
  REQUIRE(needed.exitCode == 0);
  CHECK_THAT(needed.output, Catch::Contains("(NEEDED)") && !Catch::Contains("libvulkan") && !Catch::Contains("libglfw") && !Catch::Contains("libX11"));
  // Help lists every command, the engine's too, and an engine command runs through arbor.
  const Result help = run("--help");
  CHECK(help.exitCode == 0);
  CHECK_THAT(help.output, Catch::Contains("generate") && Catch::Contains("render") && Catch::Contains("view") && Catch::Contains("bench"));
  CHECK(run("textures --help").exitCode == 0);
  // Alone, without arbor-engine beside it: its own commands run, the engine's fail naming what is missing.
  const fs::path alone = fs::path(arbor::test::tempPath("arbor-alone"));
  fs::remove_all(alone);
  fs::create_directories(alone);
  fs::copy_file(ARBOR_BINARY, alone / "arbor");
  const std::string program = (alone / "arbor").string();
  CHECK(arbor::test::runCommand(program + " generate palm --quiet --out " + (alone / "palm.obj").string() + " 2>&1").exitCode == 0);
  const Result version = arbor::test::runCommand(program + " --version 2>&1");
  CHECK(version.exitCode == 0);
  CHECK_THAT(version.output, Catch::StartsWith("arbor "));
  const Result render = arbor::test::runCommand(program + " render palm --out " + (alone / "palm.png").string() + " 2>&1");
  CHECK(render.exitCode == 1);
  CHECK_THAT(render.output, Catch::Contains((alone / "arbor-engine").string()) && Catch::Contains("cannot be run"));
  CHECK_FALSE(fs::exists(alone / "palm.png"));
}

TEST_CASE("generate writes a skeleton and a summary", "[cli]") {
  const std::string out = arbor::test::tempPath("aspen.json");
  const Result r = run("generate quaking-aspen --seed 3 --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("Quaking Aspen") && Catch::Contains("nodes") && Catch::Contains("wrote"));
  const auto doc = nlohmann::json::parse(arbor::readFile(out));
  CHECK(doc["format"] == "arbor-skeleton/1");
  CHECK(doc["seed"] == 3);
  CHECK(doc["nodes"].size() > 100);
  CHECK(doc["leaves"].size() > 100);
  CHECK(doc["nodes"][0]["parent"] == -1);
}

TEST_CASE("the same command twice writes byte-identical files", "[cli]") {
  const std::string a = arbor::test::tempPath("a.json"), b = arbor::test::tempPath("b.json");
  REQUIRE(run("generate palm --seed 9 --quiet --out " + a).exitCode == 0);
  REQUIRE(run("generate palm --seed 9 --quiet --out " + b).exitCode == 0);
  CHECK(arbor::readFile(a) == arbor::readFile(b));
}

TEST_CASE("bad species files exit with 2, name file and field, and leave the output alone", "[cli]") {
  const std::string bad = writeTemp("bad-species.json", "{\"Name\": \"x\", \"Shape\": 12}");
  const std::string out = writeTemp("keep.json", "previous content");
  const Result r = run("generate " + bad + " --out " + out);
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.output, Catch::Contains("bad-species.json") && Catch::Contains("'Shape'") && Catch::Contains("[0, 8]"));
  CHECK(arbor::readFile(out) == "previous content");

  const std::string xml = writeTemp("bad.xml", "<arbaro><species name='x'><param name='Shape' value='1'/>");
  const Result x = run("generate " + xml + " --out " + arbor::test::tempPath("x.json"));
  CHECK(x.exitCode == 2);
  CHECK_THAT(x.output, Catch::Contains("bad.xml") && Catch::Contains("XML error"));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("x.json")));
}

TEST_CASE("species --list names the growth models and each preset's model, a file naming no known model exits 2", "[cli]") {
  const Result list = run("species --list");
  CHECK(list.exitCode == 0);
  CHECK_THAT(list.output, Catch::Contains("growth models:") && Catch::Contains("weber-penn") && Catch::Contains("presets in"));
  CHECK_THAT(list.output, Catch::Matches("(.|\n)*black-tupelo +weber-penn +Black Tupelo(.|\n)*"));

  const std::string other = writeTemp("other-model.json", "{\"model\": \"self-organizing\", \"Name\": \"x\"}");
  const Result r = run("generate " + other + " --out " + arbor::test::tempPath("o.json"));
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.output, Catch::Contains("other-model.json") && Catch::Contains("model") && Catch::Contains("allowed: \"weber-penn\""));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("o.json")));
}

TEST_CASE("mesh takes a branch graph or a skeleton file, a skeleton meshes exactly as the tree it was written from", "[cli][graph]") {
  // A trunk of five internodes, then a node with four children (one nearly along the trunk, one backward).
  nlohmann::json doc = {{"format", "arbor-graph/1"}, {"nodes", nlohmann::json::array()}};
  auto add = [&](int parent, double x, double y, double z) {
    const int id = static_cast<int>(doc["nodes"].size());
    doc["nodes"].push_back({{"id", id}, {"parent", parent}, {"position", {x, y, z}}});
    return id;
  };
  int top = add(-1, 0, 0, 0);
  for (int k = 1; k <= 5; ++k) top = add(top, 0, 0, 0.5 * k);
  for (const auto& d : {glm::dvec3(0.3, 0, 0.1), glm::dvec3(0, 0.3, 0.1), glm::dvec3(0.02, 0, 0.3), glm::dvec3(-0.2, -0.2, -0.15)}) {
    int parent = top;
    for (int k = 1; k <= 6; ++k) parent = add(parent, k * d.x, k * d.y, 2.5 + k * d.z);
  }
  const std::string file = writeTemp("fan-graph.json", doc.dump());
  const std::string obj = arbor::test::tempPath("fan.obj");
  const Result r = run("mesh " + file + " --out " + obj);
  CHECK(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("closed 2-manifold, 1 piece(s)") && Catch::Contains("from its file"));
  CHECK(fs::file_size(obj) > 1000);
  const Result check = run("check " + file);
  CHECK(check.exitCode == 0);  // no mesh-made crossings at this fan

  // A node named twice, and a cycle: refused naming the node.
  doc["nodes"][3]["parent"] = 5;
  const Result cycle = run("mesh " + writeTemp("cycle-graph.json", doc.dump()) + " --out " + arbor::test::tempPath("c.obj"));
  CHECK(cycle.exitCode == 2);
  CHECK_THAT(cycle.output, Catch::Contains("cycle-graph.json") && Catch::Contains("3"));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("c.obj")));

  // A skeleton written and read back meshes to the same bytes; this one has stubs (cards, not tubes), which
  // the file once lost.
  const std::string skeleton = arbor::test::tempPath("poplar-skeleton.json"), direct = arbor::test::tempPath("poplar-direct.obj"),
                    again = arbor::test::tempPath("poplar-again.obj");
  REQUIRE(run("generate lombardy-poplar --seed 2 --quiet --out " + skeleton).exitCode == 0);
  CHECK_THAT(arbor::readFile(skeleton), Catch::Contains("\"stub\": true"));
  REQUIRE(run("generate lombardy-poplar --seed 2 --quiet --no-textures --out " + direct).exitCode == 0);
  REQUIRE(run("mesh " + skeleton + " --quiet --no-textures --out " + again).exitCode == 0);
  CHECK(arbor::readFile(direct) == arbor::readFile(again));
  nlohmann::json written = nlohmann::json::parse(arbor::readFile(skeleton));
  written["stems"][1]["stub"] = "yes";
  const Result badStub = run("mesh " + writeTemp("bad-stub.json", written.dump()) + " --out " + arbor::test::tempPath("s.obj"));
  CHECK(badStub.exitCode == 2);
  CHECK_THAT(badStub.output, Catch::Contains("bad-stub.json") && Catch::Contains("stems[1].stub") && Catch::Contains("true or false"));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("s.obj")));
  // A stub's children are stubs too: a tube there would have no parent surface to leave from.
  written["stems"][1]["stub"] = false;
  written["stems"][0]["stub"] = true;
  const Result stubParent = run("mesh " + writeTemp("stub-parent.json", written.dump()) + " --out " + arbor::test::tempPath("s.obj"));
  CHECK(stubParent.exitCode == 2);
  CHECK_THAT(stubParent.output, Catch::Contains("stub-parent.json") && Catch::Contains("stems[1].stub") && Catch::Contains("grows from stem 0"));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("s.obj")));
  const Result species = run("species " + skeleton);
  CHECK(species.exitCode == 2);
  CHECK_THAT(species.output, Catch::Contains("not a model file"));
}

TEST_CASE("lsystem derives a grammar, draws it as SVG, and refuses bad grammars and runaway derivations with 2", "[cli][lsystem]") {
  const std::string svg = arbor::test::tempPath("fig-1-24a.svg");
  const Result r = run("lsystem fig-1-24a --out " + svg);
  CHECK(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("7811 modules") && Catch::Contains("3125 internodes"));
  const std::string drawing = arbor::readFile(svg);
  CHECK(drawing.rfind("<svg", 0) == 0);
  CHECK(drawing.find("<path") != std::string::npos);

  const std::string bad = writeTemp("bad.lsys", "n: 3\naxiom: F\nF -> F[+F(\n");
  const Result syntax = run("lsystem " + bad + " --out " + arbor::test::tempPath("bad.svg"));
  CHECK(syntax.exitCode == 2);
  CHECK_THAT(syntax.output, Catch::Contains("bad.lsys") && Catch::Contains("line 3"));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("bad.svg")));

  const std::string txt = arbor::test::tempPath("runaway.txt");
  const Result runaway = run("lsystem fig-1-24a --n 12 --max-modules 100000 --out " + txt);
  CHECK(runaway.exitCode == 2);
  CHECK_FALSE(fs::exists(txt));

  // The same grammar is a tree for every command that takes one.
  const std::string obj = arbor::test::tempPath("bush.obj");
  const Result mesh = run("generate fig-1-25 --out " + obj);
  CHECK(mesh.exitCode == 0);
  CHECK_THAT(mesh.output, Catch::Contains("closed 2-manifold, 1 piece(s)"));
  const Result list = run("species --list");
  CHECK_THAT(list.output, Catch::Contains("l-system") && Catch::Matches("(.|\\n)*fig-2-6a +l-system(.|\\n)*"));
}

TEST_CASE("grow writes the state after N iterations as a branch graph or a mesh, the same for any step size", "[cli][sc]") {
  const std::string a = arbor::test::tempPath("grow-12-a.json"), b = arbor::test::tempPath("grow-12-b.json");
  const Result r = run("grow sc-open-broadleaf --steps 12 --step-size 1 --out " + a);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("12 iterations (--steps reached)") && Catch::Contains("wrote " + a));
  REQUIRE(run("grow sc-open-broadleaf --steps 12 --step-size 100000 --out " + b).exitCode == 0);
  CHECK(arbor::readFile(a) == arbor::readFile(b));

  // To the end: the graph holds every enabled node; after 12 iterations fewer, and it meshes closed.
  const std::string end = arbor::test::tempPath("grow-end.json");
  const Result full = run("grow sc-between-walls --out " + end);
  REQUIRE(full.exitCode == 0);
  CHECK_THAT(full.output, Catch::Contains("grown to the end"));
  const auto graph = nlohmann::json::parse(arbor::readFile(end));
  CHECK(graph["format"] == "arbor-graph/1");
  CHECK_THAT(full.output, Catch::Contains(", " + std::to_string(graph["nodes"].size()) + " enabled,"));
  CHECK(nlohmann::json::parse(arbor::readFile(a))["nodes"].size() < graph["nodes"].size());
  const Result meshed = run("mesh " + a + " --out " + arbor::test::tempPath("grow-12.obj"));
  CHECK(meshed.exitCode == 0);
  CHECK_THAT(meshed.output, Catch::Contains("closed 2-manifold, 1 piece(s)"));

  // The mesh of a tree grown to the end is the one `generate` writes for the model.
  const std::string grown = arbor::test::tempPath("grow-end.obj"), generated = arbor::test::tempPath("generate-end.obj");
  REQUIRE(run("grow sc-around-sphere --seed 2 --no-textures --out " + grown).exitCode == 0);
  REQUIRE(run("generate sc-around-sphere --seed 2 --no-textures --quiet --out " + generated).exitCode == 0);
  CHECK(arbor::readFile(grown) == arbor::readFile(generated));

  // A random space-colonization model is a file grow takes.
  const std::string random = arbor::test::tempPath("random-sc.json");
  REQUIRE(run("species --random 5 --model space-colonization --out " + random).exitCode == 0);
  CHECK(run("grow " + random + " --out " + arbor::test::tempPath("random-sc.obj")).exitCode == 0);
}

TEST_CASE("grow refuses other models, bad files and outputs with 2 and writes nothing", "[cli][sc]") {
  const std::string out = writeTemp("grow-keep.json", "previous content");
  const std::string badCloud = writeTemp("grow-bad-cloud.json", R"({"model": "space-colonization", "segmentLength": 0.1,
    "trunk": {"segments": 3, "width": 0.1},
    "clouds": [{"shape": "sphere", "center": [0, 0, 1], "radius": 1, "points": 10, "influence": 0.2, "kill": 0.3}]})");
  const std::pair<std::string, std::vector<std::string>> cases[] = {
      {"grow palm --out " + out, {"palm", "weber-penn", "not space-colonization"}},
      {"grow fig-1-25 --out " + out, {"fig-1-25", "l-system"}},
      {"grow " + badCloud + " --out " + out, {"grow-bad-cloud.json", "clouds[0].kill"}},
      {"grow no-such-model --out " + out, {"no-such-model", "sc-open-broadleaf"}},
      {"grow sc-open-broadleaf --steps -3 --out " + out, {"--steps"}},
      {"grow sc-open-broadleaf --step-size 0 --out " + out, {"--step-size"}},
  };
  for (const auto& [arguments, needles] : cases) {
    const Result r = run(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exitCode == 2);
    for (const std::string& n : needles) CHECK_THAT(r.output, Catch::Contains(n));
    CHECK(arbor::readFile(out) == "previous content");
  }
  const std::string png = arbor::test::tempPath("grow.png");
  const Result wrongType = run("grow sc-open-broadleaf --out " + png);
  CHECK(wrongType.exitCode == 2);
  CHECK_THAT(wrongType.output, Catch::Contains("--out") && Catch::Contains(".obj"));
  CHECK_FALSE(fs::exists(png));
}

TEST_CASE("bench grow prints a row per space-colonization model and the floor's sphere", "[cli][sc]") {
  const Result r = run("bench grow sc-sculpted-crown sc-between-walls --repeat 1 --sphere 2000");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("iterations") && Catch::Contains("median ms"));
  CHECK_THAT(r.output, Catch::Matches("(.|\n)*sc-sculpted-crown +2400 +[0-9]+ +[0-9]+ (.|\n)*"));
  CHECK_THAT(r.output, Catch::Matches("(.|\n)*sc-between-walls +2500 (.|\n)*"));
  CHECK_THAT(r.output, Catch::Matches("(.|\n)*sphere-2000 +2000 (.|\n)*"));
  const Result other = run("bench grow palm --repeat 1 --sphere 0");
  CHECK(other.exitCode == 2);
  CHECK_THAT(other.output, Catch::Contains("palm") && Catch::Contains("weber-penn"));
}

TEST_CASE("unknown presets list the presets on offer", "[cli]") {
  const Result r = run("generate no-such-tree --out " + arbor::test::tempPath("n.json"));
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.output, Catch::Contains("no-such-tree") && Catch::Contains("black-tupelo"));
}

TEST_CASE("usage errors exit with 2", "[cli]") {
  CHECK(run("generate palm").exitCode == 2);                                   // --out missing
  CHECK(run("generate palm --levels 0 --out x.json").exitCode == 2);           // out of range
  CHECK(run("generate palm --out " + arbor::test::tempPath("p.txt")).exitCode == 2);  // unknown output type
  CHECK(run("frobnicate").exitCode == 2);
}

TEST_CASE("every subcommand has --help", "[cli]") {
  for (const char* command : {"", "generate", "species", "grow", "bench", "bench generate", "bench mesh", "bench tess", "bench leaves",
                              "bench grow", "render", "view", "textures", "accuracy"}) {
    const Result r = run(std::string(command) + " --help");
    INFO(command);
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Catch::Contains("Usage") || Catch::Contains("usage") || Catch::Contains("OPTIONS"));
  }
}

TEST_CASE("species converts an Arbaro file to Arbor JSON that reads back", "[cli]") {
  const std::string out = arbor::test::tempPath("shrub.json");
  const Result r = run(std::string("species ") + TEST_DATA_DIR + "/small-arbaro.xml --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const Result g = run("generate " + out + " --quiet --out " + arbor::test::tempPath("shrub-skeleton.json"));
  CHECK(g.exitCode == 0);
}

TEST_CASE("an Arbaro file keeps its own angles unless --angles natural, and the choice round-trips", "[cli]") {
  const std::string xml = std::string(TEST_DATA_DIR) + "/small-arbaro.xml";
  auto convert = [](const std::string& arguments, const std::string& name) {
    const std::string out = arbor::test::tempPath(name);
    const Result r = run("species " + arguments + " --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return out;
  };
  const std::string classic = convert(xml, "angles-file.json");
  CHECK(nlohmann::json::parse(arbor::readFile(classic))["AngleRule"] == "classic");
  CHECK(nlohmann::json::parse(arbor::readFile(convert(xml + " --angles file", "angles-file2.json")))["AngleRule"] == "classic");
  const std::string natural = convert(xml + " --angles natural", "angles-natural.json");
  CHECK(nlohmann::json::parse(arbor::readFile(natural))["AngleRule"] == "natural");
  // JSON keeps its own field under --angles file; --angles natural overrides it.
  CHECK(nlohmann::json::parse(arbor::readFile(convert(classic, "angles-again.json")))["AngleRule"] == "classic");
  CHECK(nlohmann::json::parse(arbor::readFile(convert(natural, "angles-again2.json")))["AngleRule"] == "natural");
  CHECK(nlohmann::json::parse(arbor::readFile(convert(classic + " --angles natural", "angles-forced.json")))["AngleRule"] == "natural");
  // The tree grown from the file with --angles natural is the tree of the natural JSON, not the file's.
  const std::string a = arbor::test::tempPath("angles-a.json"), b = arbor::test::tempPath("angles-b.json"),
                    c = arbor::test::tempPath("angles-c.json");
  REQUIRE(run("generate " + xml + " --quiet --angles natural --out " + a).exitCode == 0);
  REQUIRE(run("generate " + natural + " --quiet --out " + b).exitCode == 0);
  REQUIRE(run("generate " + xml + " --quiet --out " + c).exitCode == 0);
  auto nodes = [](const std::string& path) { return nlohmann::json::parse(arbor::readFile(path))["nodes"]; };
  CHECK(nodes(a) == nodes(b));
  CHECK(nodes(a) != nodes(c));
}

TEST_CASE("every command that loads species takes --angles", "[cli]") {
  for (const char* command : {"generate", "species", "bench generate", "bench mesh", "bench tess", "bench leaves", "render", "view",
                              "accuracy"}) {
    const Result r = run(std::string(command) + " --help");
    INFO(command);
    CHECK_THAT(r.output, Catch::Contains("--angles") && Catch::Contains("natural|file"));
  }
}

TEST_CASE("generate writes a tree mesh as OBJ that reads back closed", "[cli][mesh]") {
  const std::string out = arbor::test::tempPath("palm.obj");
  const Result r = run("generate palm --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("closed 2-manifold") && Catch::Contains("patches"));
  const std::string text = arbor::readFile(out);
  std::size_t faces = 0, vertices = 0;
  for (std::size_t at = 0; (at = text.find('\n', at)) != std::string::npos; ++at) {
    faces += text.compare(at + 1, 2, "f ") == 0 ? 1 : 0;
    vertices += text.compare(at + 1, 2, "v ") == 0 ? 1 : 0;
  }
  CHECK(faces > 1000);
  CHECK(vertices > 1000);
}

TEST_CASE("a generated tree as glTF and GLB passes the Khronos validator", "[cli][mesh]") {
  for (const char* extension : {".gltf", ".glb"}) {
    const std::string out = arbor::test::tempPath(std::string("aspen") + extension);
    REQUIRE(run("generate quaking-aspen --levels 2 --quiet --out " + out).exitCode == 0);
    const Result v = arbor::test::runCommand("node " + std::string(ARBOR_SOURCE_DIR) + "/tools/validate-gltf.mjs " + out + " 2>&1");
    INFO(v.output);
    CHECK(v.exitCode == 0);
    CHECK_THAT(v.output, Catch::Contains("0 errors"));
  }
}

TEST_CASE("every preset's complete export (levels of detail, cards, leaves, textures, wind) passes the validator cleanly", "[cli][mesh][validator]") {
  for (const std::string& preset : allPresets()) {
    const std::string out = arbor::test::tempPath("complete-" + preset + ".glb");
    const Result r = run("generate " + preset + " --lods 3 --wind 1 --wind-frames 4 --quiet --out " + out);
    INFO(preset << ": " << r.output);
    REQUIRE(r.exitCode == 0);
    const Result v = arbor::test::runCommand("node " + std::string(ARBOR_SOURCE_DIR) + "/tools/validate-gltf.mjs " + out + " 2>&1");
    INFO(v.output);
    CHECK(v.exitCode == 0);
    CHECK_THAT(v.output, Catch::Contains(": 0 errors, 0 warnings"));
    const nlohmann::json doc = readGlbJson(out);
    bool leaves = false;  // L-system presets grow none
    for (const auto& m : doc["materials"]) leaves = leaves || m["name"] == "leaves";
    CHECK(doc["images"].size() == (leaves ? 3u : 2u));
  }
}

TEST_CASE("an OBJ export brings its .mtl and textures beside it, or none with --no-textures", "[cli][mesh]") {
  const std::string dir = arbor::test::tempPath("obj-textures");
  fs::remove_all(dir);
  fs::create_directories(dir);
  REQUIRE(run("generate palm --quiet --out " + dir + "/palm.obj").exitCode == 0);
  CHECK(fs::file_size(dir + "/palm.mtl") > 100);
  for (const char* texture : {"bark_color.png", "bark_normal.png", "leaf_atlas.png"}) {
    INFO(texture);
    CHECK(arbor::readFile(dir + "/palm_" + texture) == arbor::readFile(std::string(ARBOR_ASSET_DIR) + "/textures/" + texture));
  }
  const std::string obj = arbor::readFile(dir + "/palm.obj");
  CHECK_THAT(obj, Catch::Contains("mtllib palm.mtl") && Catch::Contains("\no leaves\n") && Catch::Contains("usemtl leaves"));
  REQUIRE(run("generate palm --quiet --no-textures --no-leaves --out " + dir + "/bare.obj").exitCode == 0);
  CHECK_FALSE(fs::exists(dir + "/bare.mtl"));
  CHECK_FALSE(fs::exists(dir + "/bare_bark_color.png"));
  const std::string bare = arbor::readFile(dir + "/bare.obj");
  CHECK(bare.find("mtllib") == std::string::npos);
  CHECK(bare.find("o leaves") == std::string::npos);
  // Options that do not fit the file are refused before anything is written.
  const Result lods = run("generate palm --lods 2 --out " + dir + "/lods.obj");
  CHECK(lods.exitCode == 2);
  CHECK_THAT(lods.output, Catch::Contains("--lods"));
  CHECK_FALSE(fs::exists(dir + "/lods.obj"));
}

TEST_CASE("an OBJ export that cannot be written whole puts none of its files in place", "[cli][mesh]") {
  const fs::path dir = arbor::test::tempPath("obj-too-large");
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Files up to 1,000 KiB: each texture fits (at most 492 KiB), the palm's OBJ (about 2 MB) does not. The signal
  // for a file past the limit is ignored, so the write fails with EFBIG instead of killing the process.
  const Result r = arbor::test::runCommand("sh -c \"trap '' XFSZ; ulimit -f 1000; exec " + std::string(ARBOR_BINARY) + " generate palm --quiet --out " +
                                           (dir / "palm.obj").string() + "\" 2>&1");
  CHECK(r.exitCode == 1);
  CHECK_THAT(r.output, Catch::Contains("palm.obj") && Catch::Contains("File too large"));
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
  CHECK(left.empty());
}

TEST_CASE("subdivided export has four times the quads per level", "[cli][mesh]") {
  const std::string coarse = arbor::test::tempPath("coarse.obj"), fine = arbor::test::tempPath("fine.obj");
  REQUIRE(run("generate palm --quiet --no-leaves --no-cards --out " + coarse).exitCode == 0);
  REQUIRE(run("generate palm --quiet --no-leaves --no-cards --subdivide 2 --out " + fine).exitCode == 0);
  auto countFaces = [](const std::string& text) {
    std::size_t faces = 0;
    for (std::size_t at = 0; (at = text.find("\nf ", at)) != std::string::npos; ++at) ++faces;
    return faces;
  };
  CHECK(countFaces(arbor::readFile(fine)) == 16 * countFaces(arbor::readFile(coarse)));
}

TEST_CASE("arbor maps OpenSubdiv only for --subdivide, from its module, and says so when the module is missing", "[cli][mesh]") {
  // The dynamic loader's own account of the files it opens.
  auto opened = [](const std::string& arbor, const std::string& arguments) {
    return arbor::test::runCommand("LD_DEBUG=files " + arbor + " " + arguments + " 2>&1");
  };
  const arbor::test::CommandResult plain = opened(ARBOR_BINARY, "generate palm --quiet --out " + arbor::test::tempPath("plain.obj"));
  REQUIRE(plain.exitCode == 0);
  CHECK(plain.output.find("libosdCPU") == std::string::npos);
  CHECK(plain.output.find("libarbor_subdivide") == std::string::npos);
  const arbor::test::CommandResult smooth = opened(ARBOR_BINARY, "generate palm --quiet --subdivide 1 --out " + arbor::test::tempPath("smooth.obj"));
  REQUIRE(smooth.exitCode == 0);
  CHECK(smooth.output.find("libarbor_subdivide.so") != std::string::npos);
  CHECK(smooth.output.find("libosdCPU") != std::string::npos);
  // A copy of the program alone: plain exports still work, --subdivide fails naming the module and where it looked.
  const std::string alone = arbor::test::tempPath("alone");
  fs::create_directories(alone);
  fs::copy_file(ARBOR_BINARY, alone + "/arbor", fs::copy_options::overwrite_existing);
  CHECK(run("generate palm --quiet --out " + alone + "/plain.obj").exitCode == 0);
  const arbor::test::CommandResult missing =
      arbor::test::runCommand(alone + "/arbor generate palm --quiet --subdivide 1 --out " + alone + "/smooth.obj 2>&1");
  CHECK(missing.exitCode == 1);
  CHECK(missing.output.find("libarbor_subdivide.so") != std::string::npos);
  CHECK(missing.output.find(alone) != std::string::npos);
  CHECK_FALSE(fs::exists(alone + "/smooth.obj"));
}

TEST_CASE("mesh options that make no sense for a skeleton are refused", "[cli]") {
  CHECK(run("generate palm --subdivide 1 --out " + arbor::test::tempPath("s.json")).exitCode == 2);
}

namespace {

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
std::pair<std::uint32_t, std::uint32_t> pngSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  REQUIRE(in.gcount() == 24);
  REQUIRE(header[1] == 'P');
  const auto word = [&](int at) {
    return (std::uint32_t{header[at]} << 24) | (std::uint32_t{header[at + 1]} << 16) | (std::uint32_t{header[at + 2]} << 8) | header[at + 3];
  };
  return {word(16), word(20)};
}

}  // namespace

TEST_CASE("render writes a PNG of the asked size and reports the triangles it generated", "[cli][render]") {
  const std::string out = arbor::test::tempPath("render-palm.png");
  fs::remove(out);
  const Result r = run("render palm --levels 1 --mode acc --tess 3 --size 64x80 --validation --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("generated (clipping primitives)"));
  CHECK_THAT(r.output, Catch::Contains("validation on"));
  CHECK(pngSize(out) == std::make_pair(64u, 80u));
}

TEST_CASE("render with fake branches and leaves says how many it drew", "[cli][render]") {
  const std::string out = arbor::test::tempPath("render-aspen-impostors.png");
  fs::remove(out);
  const Result r = run("render quaking-aspen --levels 1 --impostor-levels 1 --leaves --mode flat --size 64x80 --validation --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("leaves, "));
  CHECK_THAT(r.output, Catch::Contains("fake-branch segments"));
  CHECK_THAT(r.output, !Catch::Contains("not drawn"));
  CHECK(pngSize(out) == std::make_pair(64u, 80u));
}

TEST_CASE("render refuses bad options with 2, naming the option, and writes nothing", "[cli][render]") {
  const std::string out = arbor::test::tempPath("render-bad.png");
  fs::remove(out);
  const std::pair<const char*, const char*> cases[] = {
      {"render palm --mode smooth --out ", "--mode"},
      {"render palm --size 64by80 --out ", "--size"},
      {"render palm --size 8x8 --out ", "--size"},
      {"render palm --tess 65 --out ", "--tess"},
      {"render palm --camera 1,2,3 --out ", "--camera"},
      {"render palm --camera 0,0,1,0,0,1 --out ", "--camera"},
      {"render no-such-tree --out ", "no-such-tree"},
      {"render palm --impostor-levels 4 --out ", "--impostor-levels"},
      {"render palm --levels 7 --impostor-levels 2 --out ", "at most 8"},
      {"render palm --leaf-density 1.5 --out ", "--leaf-density"},
      {"render palm --light 30,95 --out ", "--light"},
  };
  for (const auto& [arguments, field] : cases) {
    const Result r = run(std::string(arguments) + out);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Catch::Contains(field));
    CHECK_FALSE(fs::exists(out));
  }
  const Result jpeg = run("render palm --out " + arbor::test::tempPath("render-bad.jpg"));
  CHECK(jpeg.exitCode == 2);
  CHECK_THAT(jpeg.output, Catch::Contains("PNG"));
}

TEST_CASE("bench leaves adds two triangles per leaf to the tree alone, with and without self-shadowing", "[cli][render]") {
  const std::string csv = arbor::test::tempPath("bench-leaves.csv");
  fs::remove(csv);
  const Result r = run("bench leaves quaking-aspen --counts 100,1000 --shadow-leaves 0,16 --mode flat --size 64x48 --frames 1 --csv " + csv);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("| leaves | self-shadowing |"));
  CHECK_THAT(r.output, Catch::Contains("[5/5]"));  // progress
  std::istringstream rows(arbor::readFile(csv));
  std::string line;
  std::getline(rows, line);
  CHECK(line.rfind("leaves,shadow_leaves,triangles,", 0) == 0);
  std::vector<std::array<unsigned long long, 3>> table;
  while (std::getline(rows, line)) {
    std::array<unsigned long long, 3> v{};
    REQUIRE(std::sscanf(line.c_str(), "%llu,%llu,%llu", &v[0], &v[1], &v[2]) == 3);
    table.push_back(v);
  }
  REQUIRE(table.size() == 5);
  CHECK(table[0][0] == 0);
  for (const auto& row : table) CHECK(row[2] == table[0][2] + 2 * row[0]);
  CHECK(table[2][1] == 16);
}

TEST_CASE("bench tess measures the ceiling and the CPU-subdivided mesh with the same triangles, and plots", "[cli][render]") {
  const std::string csv = arbor::test::tempPath("bench-tess.csv"), plot = arbor::test::tempPath("bench-tess.png");
  fs::remove(csv);
  fs::remove(plot);
  const Result r = run("bench tess palm --levels 1 --modes flat,acc --factors 1,2,4 --size 64x48 --frames 1 --subdivide-up-to 4 --csv " +
                       csv + " --plot " + plot);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("of ceiling"));
  CHECK_THAT(r.output, Catch::Contains("[7/7]"));  // progress: three ceiling cells, flat, three ACC cells
  std::map<std::string, unsigned long long> triangles, drawn;  // "mode xfactor"
  std::istringstream rows(arbor::readFile(csv));
  std::string line;
  std::getline(rows, line);
  while (std::getline(rows, line)) {
    char mode[32] = {};
    double factor = 0, adaptive = 0, displacement = 0;
    unsigned long long count = 0, patches = 0;
    REQUIRE(std::sscanf(line.c_str(), "%31[^,],%lf,%lf,%lf,%llu,%llu", mode, &factor, &adaptive, &displacement, &count, &patches) == 6);
    triangles[std::string(mode) + " x" + std::to_string(static_cast<int>(factor))] = count;
    drawn[std::string(mode) + " x" + std::to_string(static_cast<int>(factor))] = patches;
  }
  for (int f : {1, 2, 4}) {
    INFO("factor " << f);
    const std::string x = " x" + std::to_string(f);
    REQUIRE(triangles.count("acc" + x));
    // 2 f^2 triangles per patch the culling pass kept; the flat mesh draws 2 per quad, all of them.
    CHECK(triangles["acc" + x] == drawn["acc" + x] * 2 * static_cast<unsigned long long>(f * f));
    CHECK(drawn["acc" + x] <= triangles["flat x1"] / 2);
    CHECK(triangles["ceiling" + x] == triangles["acc" + x]);
    CHECK(triangles["cpu-subdivided" + x] == triangles["flat x1"] * static_cast<unsigned long long>(f * f));  // 4^k quads each
  }
  CHECK(pngSize(plot) == std::make_pair(1120u, 420u));
}

TEST_CASE("bench tess on a forest of instanced trees", "[cli][render]") {
  const Result r = run("bench tess palm --scene forest 4 --modes acc --factors 2 --size 64x48 --frames 1 --no-ceiling");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("trees in view"));
  CHECK_THAT(r.output, Catch::Contains("| acc x2 |"));
}

TEST_CASE("textures and bench tess refuse values out of range with 2", "[cli]") {
  const std::pair<std::string, const char*> cases[] = {
      {"textures --size 100 --out " + arbor::test::tempPath("textures-bad"), "--size"},
      {"bench tess palm --factors 1,99", "--factors"},
      {"bench tess palm --modes acc,magic", "--modes"},
      {"bench tess palm --scene meadow", "--scene"},
      {"bench leaves palm --counts 10,many", "--counts"},
      {"bench leaves palm --counts 90000000", "--counts"},
  };
  for (const auto& [arguments, field] : cases) {
    const Result r = run(arguments);
    INFO(arguments << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Catch::Contains(field));
  }
}

namespace {

// The subcommands `arbor --help` (or `arbor bench --help`) lists, each as "  name   description".
std::vector<std::string> listedSubcommands(const std::string& help) {
  std::vector<std::string> names;
  const std::size_t section = help.find("Subcommands:");
  std::istringstream in(section == std::string::npos ? "" : help.substr(section));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && line.rfind("  ", 0) == 0) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    names.push_back(name);
  }
  return names;
}

}  // namespace

TEST_CASE("README names every option of every command", "[cli][docs]") {
  const std::string readme = arbor::readFile(std::string(ARBOR_SOURCE_DIR) + "/README.md");
  std::vector<std::string> commands;
  for (const std::string& c : listedSubcommands(run("--help").output)) {
    if (c != "bench") commands.push_back(c);
  }
  for (const std::string& c : listedSubcommands(run("bench --help").output)) commands.push_back("bench " + c);
  REQUIRE(commands.size() >= 15);
  for (const std::string& command : commands) {
    const std::string help = run(command + " --help").output;
    for (std::size_t at = help.find("--"); at != std::string::npos; at = help.find("--", at + 2)) {
      std::size_t end = at + 2;
      while (end < help.size() && (std::islower(static_cast<unsigned char>(help[end])) || std::isdigit(static_cast<unsigned char>(help[end])) || help[end] == '-')) ++end;
      const std::string option = help.substr(at, end - at);
      if (option.size() < 3 || option == "--help") continue;
      INFO(command << " " << option);
      CHECK(readme.find(option) != std::string::npos);
    }
  }
}
