// Every bad input found by the reliability review (issue 12) as a regression case: each is refused with exit
// code 2 and one message naming the file, the field or line and what is allowed, and nothing is written;
// valid but oversized requests are refused before memory or time runs away.
#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "common/atomic_file.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

using Result = arbor::test::CommandResult;
using nlohmann::json;

Result run(const std::string& arguments) { return arbor::test::runCommand(std::string(ARBOR_BINARY) + " " + arguments + " 2>&1"); }

// The run may use at most 2 GiB of address space (unbounded growth fails fast instead of swapping), and a
// hang ends in a failure after two minutes rather than a stuck suite. Sanitizer builds reserve terabytes of
// shadow memory, so there only the time guard applies.
Result runBounded(const std::string& arguments) {
#ifdef ARBOR_SANITIZED
  const std::string limit = "";
#else
  const std::string limit = "ulimit -v 2097152; ";
#endif
  return arbor::test::runCommand("sh -c '" + limit + "exec timeout 120 " + ARBOR_BINARY + " " + arguments + "' 2>&1");
}

std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = arbor::test::tempPath(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

json palm() { return json::parse(arbor::readFile(std::string(ARBOR_ASSET_DIR) + "/presets/palm.json")); }

std::string arbaroAspen() { return arbor::readFile(std::string(TEST_DATA_DIR) + "/small-arbaro.xml"); }

// A species file given by editing the palm preset.
std::string palmWith(const std::string& name, const std::function<void(json&)>& edit) {
  json j = palm();
  edit(j);
  return writeTemp(name, j.dump(1));
}

void checkRefused(const Result& r, std::initializer_list<std::string> needles) {
  INFO(r.output);
  CHECK(r.exitCode == 2);
  for (const std::string& n : needles) CHECK_THAT(r.output, Catch::Contains(n));
}

}  // namespace

TEST_CASE("species files that are not plain text files are refused with 2", "[cli][refusal]") {
  const std::string fifo = arbor::test::tempPath("fifo.json");
  fs::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  checkRefused(runBounded("generate " + fifo + " --out " + arbor::test::tempPath("f.json")), {"fifo.json", "FIFO"});

  const std::string a = arbor::test::tempPath("loop-a.json"), b = arbor::test::tempPath("loop-b.json");
  fs::remove(a), fs::remove(b);
  fs::create_symlink(b, a), fs::create_symlink(a, b);
  checkRefused(run("generate " + a + " --out " + arbor::test::tempPath("f.json")), {"loop-a.json", "symbolic links"});

  // 50 MB of a valid-looking document: refused by its size before anything is parsed.
  const std::string big = writeTemp("huge.json", "{\"Junk\": [" + std::string(50'000'000, ' ') + "]}");
  checkRefused(runBounded("generate " + big + " --out " + arbor::test::tempPath("f.json")), {"huge.json", "at most 1 MiB"});

  const std::string directory = arbor::test::tempPath("species-dir.json");
  fs::create_directories(directory);
  checkRefused(run("generate " + directory + " --out " + arbor::test::tempPath("f.json")), {"species-dir.json", "directory"});
}

TEST_CASE("JSON the library would take silently is refused with 2, naming the field", "[cli][refusal]") {
  std::string text = palm().dump(1);
  const struct {
    std::string name, content;
    std::vector<std::string> needles;
  } cases[] = {
      {"overflow.json", std::string(text).replace(text.find("\"Scale\": ") + 9, 4, "1e309"), {"'Scale'", "1e309", "range of a double", "line"}},
      {"duplicate.json", std::string(text).replace(text.find("\"Levels\""), 8, "\"Scale\": 3, \"Levels\""), {"'Scale'", "given twice"}},
      {"nul.json", text + std::string(1, '\0') + "garbage", {"NUL byte", "line"}},
      {"trailing.json", text + "{}", {"invalid JSON", "line"}},
      {"deep.json", std::string(100, '[') + std::string(100, ']'), {"nested deeper"}},
      {"utf8.json", std::string(text).replace(text.find("\"Palm\""), 6, "\"P\xff" "alm\""), {"UTF-8"}},
      {"control.json", std::string(text).replace(text.find("\"Palm\""), 6, "\"P\\u001b[31malm\""), {"'Name'", "control character"}},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const std::string out = arbor::test::tempPath("refused-" + c.name);
    const Result r = run("generate " + writeTemp(c.name, c.content) + " --out " + out);
    std::vector<std::string> needles = c.needles;
    needles.push_back(c.name);
    INFO(r.output);
    CHECK(r.exitCode == 2);
    for (const std::string& n : needles) CHECK_THAT(r.output, Catch::Contains(n));
    CHECK_FALSE(fs::exists(out));
  }
  // A key given twice inside a level names the level.
  json j = palm();
  const std::string levels = j.dump(1);
  const std::string dup = std::string(levels).replace(levels.find("\"Length\""), 8, "\"Length\": 0.5, \"Length\"");
  checkRefused(run("generate " + writeTemp("dup-level.json", dup) + " --out " + arbor::test::tempPath("f.json")), {"StemLevels[0].Length", "given twice"});
}

TEST_CASE("Arbaro XML is range-checked on every level and leaf angle, and its name must be UTF-8", "[cli][refusal]") {
  const std::string xml = arbaroAspen();
  // The test shrub has two levels: level 2 gives its leaves' angles, level 3 it does not grow at all.
  const auto withParam = [&](const std::string& name, const std::string& value) {
    std::string s = xml;
    const std::size_t at = s.find("name=\"" + name + "\"");
    if (at == std::string::npos) return s.insert(s.find("</species>"), "<param name=\"" + name + "\" value=\"" + value + "\"/>\n");
    const std::size_t begin = s.find("value=\"", at) + 7;
    return s.replace(begin, s.find('"', begin) - begin, value);
  };
  const std::pair<std::string, std::string> cases[] = {
      {withParam("2DownAngle", "1e300"), "'2DownAngle'"},  // a leaf angle
      {withParam("2Rotate", "100000"), "'2Rotate'"},
      {withParam("3RotateV", "1e300"), "'3RotateV'"},      // a level the tree does not grow
      {withParam("3Branches", "-5"), "'3Branches'"},
  };
  for (const auto& [content, field] : cases) {
    const Result r = run("generate " + writeTemp("angles.xml", content) + " --out " + arbor::test::tempPath("x.json"));
    INFO(field << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Catch::Contains(field) && Catch::Contains("out of range"));
  }
  std::string twice = xml;
  twice.insert(twice.find("</species>"), "<param name=\"Scale\" value=\"9\"/>\n");
  checkRefused(run("generate " + writeTemp("twice.xml", twice) + " --out " + arbor::test::tempPath("x.json")), {"'Scale'", "given twice"});
  std::string latin = xml;
  latin.replace(latin.find("name=") + 6, 0, "\xe9t\xe9 ");
  const std::string file = writeTemp("latin1.xml", latin);
  checkRefused(run("species " + file + " --out " + arbor::test::tempPath("latin1.json")), {"latin1.xml", "UTF-8", "line"});
  checkRefused(run("generate " + file + " --out " + arbor::test::tempPath("latin1-tree.json")), {"latin1.xml", "UTF-8"});
}

TEST_CASE("command-line numbers must be finite, in range and whole where they count", "[cli][refusal]") {
  const std::string out = arbor::test::tempPath("numbers.obj"), png = arbor::test::tempPath("numbers.png");
  fs::remove(out);
  const std::pair<std::string, std::string> cases[] = {
      {"generate palm --ring-spacing nan --out " + out, "--ring-spacing"},
      {"generate palm --ring-spacing inf --out " + out, "--ring-spacing"},
      {"generate palm --ring-spacing 1e-300 --out " + out, "--ring-spacing"},
      {"generate palm --max-ring-distance nan --out " + out, "--max-ring-distance"},
      {"generate palm --seed -1 --out " + out, "--seed"},
      {"generate palm --seed 18446744073709551616 --out " + out, "--seed"},
      {"generate palm --seed 0x10 --out " + out, "--seed"},
      {"generate palm --levels 2.5 --out " + out, "--levels"},
      {"generate palm --out " + arbor::test::tempPath(".obj"), "file name"},
      {"render palm --tess nan --out " + png, "--tess"},
      {"render palm --adaptive inf --out " + png, "--adaptive"},
      {"render palm --displace nan --out " + png, "--displace"},
      {"render palm --azimuth nan --out " + png, "--azimuth"},
      {"render palm --elevation nan --out " + png, "--elevation"},
      {"render palm --leaf-density nan --out " + png, "--leaf-density"},
      {"render palm --leaf-lod inf --out " + png, "--leaf-lod"},
      {"render palm --camera nan,0,0,0,0,1 --out " + png, "--camera"},
      {"render palm --size 4294967360x64 --out " + png, "--size"},
      {"view palm --tess nan --offscreen --out " + arbor::test::tempPath("view-nan"), "--tess"},
      {"view palm --forest -1 --offscreen --out " + arbor::test::tempPath("view-nan"), "--forest"},
      {"view palm --anisotropy 0.5 --offscreen --out " + arbor::test::tempPath("view-nan"), "--anisotropy"},
      {"view palm --events 1:resize=4294967360x1 --offscreen --out " + arbor::test::tempPath("view-nan"), "--events"},
      {"bench tess palm --factors 1,,2", "--factors"},
      {"bench tess palm --factors ,,", "--factors"},
      {"bench tess palm --modes acc,", "--modes"},
      {"bench leaves palm --counts nan", "--counts"},
      {"generate palm --angles murray --out " + out, "--angles"},
      {"species palm --angles classic", "--angles"},
      {"render palm --angles '' --out " + png, "--angles"},
  };
  for (const auto& [arguments, field] : cases) {
    INFO(arguments);
    const Result r = run(arguments);
    checkRefused(r, {field});
    if (field == "--angles") checkRefused(r, {"allowed natural or file"});
  }
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(png));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("view-nan")));
}

TEST_CASE("an output path that cannot be written is refused with 2 before any work", "[cli][refusal]") {
  checkRefused(run("generate palm --out /nonexistent-dir/palm.json"), {"/nonexistent-dir/palm.json", "does not exist"});
  checkRefused(run("render palm --out /nonexistent-dir/palm.png"), {"/nonexistent-dir/palm.png", "does not exist"});
  checkRefused(run("generate palm --out " + arbor::test::tempPath("")), {"--out"});
  const std::string file = writeTemp("a-file", "x");
  checkRefused(run("view palm --offscreen --frames 1 --out " + file + "/shots"), {"--out"});
}

TEST_CASE("misdirected requests are named for what they are: a missing path, an unknown command, a format not written", "[cli][refusal]") {
  const std::string out = arbor::test::tempPath("misdirected.obj");
  checkRefused(run("generate " + arbor::test::tempPath("no-such-model.json") + " --out " + out), {"no such file", "no-such-model.json"});
  checkRefused(run("frobnicate"), {"unknown command 'frobnicate'", "generate", "view"});
  checkRefused(run("species palm --out " + arbor::test::tempPath("palm.xml")), {"--out", ".json"});
  checkRefused(run("generate palm --triangles --out " + arbor::test::tempPath("palm.glb")), {"--triangles", ".obj only"});
  CHECK_FALSE(fs::exists(arbor::test::tempPath("palm.xml")));
  CHECK_FALSE(fs::exists(arbor::test::tempPath("palm.glb")));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("a refused benchmark leaves an existing CSV as it was", "[cli][refusal]") {
  const std::string csv = writeTemp("keep.csv", "earlier figures\n");
  checkRefused(run("bench tess palm --modes magic --csv " + csv), {"--modes"});
  checkRefused(run("bench leaves palm --counts 0.5 --csv " + csv), {"--counts"});
  CHECK(arbor::readFile(csv) == "earlier figures\n");
  checkRefused(run("bench tess palm --csv /nonexistent-dir/t.csv"), {"--csv", "does not exist"});
}

TEST_CASE("bench leaves says how many leaves the species can grow", "[cli][refusal]") {
  const Result r = runBounded("bench leaves palm --counts 4000000");
  INFO(r.output);
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.output, Catch::Contains("--counts") && Catch::Contains("palm grows at most"));
  CHECK_THAT(r.output, !Catch::Contains("at most 0 leaves"));
}

TEST_CASE("oversized trees, meshes and subdivisions are refused before memory runs out", "[cli][refusal]") {
  // SegSplits of 2 on three levels: about 10^20 stems; refused from the estimate at once.
  const std::string splits = palmWith("splits.json", [](json& j) {
    j["Levels"] = 3;
    j["StemLevels"][1]["SegSplits"] = 2;
    j["StemLevels"][1]["CurveRes"] = 40;
    j["StemLevels"].push_back(j["StemLevels"][1]);
  });
  checkRefused(runBounded("generate " + splits + " --out " + arbor::test::tempPath("s.json")), {"SegSplits", "limit"});
  checkRefused(runBounded("view " + splits + " --offscreen --frames 1 --out " + arbor::test::tempPath("huge-view")), {"limit", "quads"});

  // Pruning with clones: every bisection step walks the clones; a bounded walk ends it.
  const std::string pruned = palmWith("pruned.json", [](json& j) {
    j["Shape"] = 8;
    j["PruneRatio"] = 1;
    j["BaseSplits"] = 3;
    j["Levels"] = 3;
    j["StemLevels"][0]["SegSplits"] = 1.5;
    j["StemLevels"][0]["CurveRes"] = 12;
    j["StemLevels"][1]["SegSplits"] = 1.2;
    j["StemLevels"][1]["CurveRes"] = 12;
    j["StemLevels"].push_back(j["StemLevels"][1]);
  });
  const Result p = runBounded("generate " + pruned + " --out " + arbor::test::tempPath("p.json"));
  INFO(p.output);
  CHECK((p.exitCode == 0 || p.exitCode == 2));

  checkRefused(runBounded("generate palm --max-ring-distance 0.0001 --out " + arbor::test::tempPath("r.obj")),
               {"more than 2500000 quads", "further apart"});
  checkRefused(runBounded("generate black-tupelo --subdivide 6 --out " + arbor::test::tempPath("t.obj")), {"subdivided 6 times", "limit"});
  // Five levels of the oak: its leaves (40 per twig) pass their limit first, its nodes soon after.
  checkRefused(runBounded("generate ca-black-oak --levels 5 --out " + arbor::test::tempPath("o.obj")), {"more than the limit", "level"});
}

TEST_CASE("random species with every field in range grow or are refused, within bounded memory", "[cli][refusal][random]") {
  for (int seed = 1; seed <= 24; ++seed) {
    const std::string file = arbor::test::tempPath("random-" + std::to_string(seed) + ".json");
    REQUIRE(run("species --random " + std::to_string(seed) + " --out " + file).exitCode == 0);
    const Result r = runBounded("generate " + file + " --quiet --out " + arbor::test::tempPath("random.obj"));
    INFO("seed " << seed << "\n" << r.output);
    CHECK((r.exitCode == 0 || r.exitCode == 2));
    if (r.exitCode == 2) CHECK_THAT(r.output, Catch::Contains("more than") && Catch::Contains("lower"));
  }
}

TEST_CASE("camera paths refuse NaN, and a camera looking straight down still sees the tree", "[cli][refusal][render]") {
  const std::string path = writeTemp("nan-path.txt", "0,-10,2,0,0,2\nnan,0,1,0,0,1\n");
  checkRefused(run("view palm --offscreen --camera-path " + path + " --frames 2 --out " + arbor::test::tempPath("nan-view")),
               {"nan-path.txt", "line 2", "finite"});
  const std::string out = arbor::test::tempPath("from-above.png");
  const Result r = run("render palm --size 64x64 --camera 0,0,40,0,0,0,60 --out " + out);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, !Catch::Contains("0 triangles"));
}

TEST_CASE("an interrupted write leaves no partial file behind", "[cli][refusal]") {
  const std::string partial = writeTemp("tree.obj.partial-test", "half a file");
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGTERM, SIG_DFL);  // Catch2's own handler steps aside, as in the arbor program
    arbor::detail::registerPartialForTest(partial);
    std::raise(SIGTERM);
    _exit(0);  // not reached: SIGTERM ends the child
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK_FALSE(fs::exists(partial));
}

TEST_CASE("an OBJ refused while meshing leaves nothing in its folder: no maps, no material, no partial file", "[cli][refusal]") {
  // The maps and the material go beside the OBJ only once the tree is built, the OBJ last.
  const fs::path folder = arbor::test::tempPath("refused-obj");
  fs::remove_all(folder);
  fs::create_directories(folder);
  checkRefused(runBounded("generate palm --max-ring-distance 0.0001 --out " + (folder / "r.obj").string()), {"more than 2500000 quads"});
  std::vector<std::string> left;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) left.push_back(entry.path().filename().string());
  INFO(left.size() << " files left, the first " << (left.empty() ? std::string() : left.front()));
  CHECK(left.empty());
  // Given room, the same command writes the OBJ with its material and three maps.
  REQUIRE(run("generate palm --quiet --out " + (folder / "r.obj").string()).exitCode == 0);
  std::size_t written = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    ++written;
    CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
  }
  CHECK(written == 5);
}
