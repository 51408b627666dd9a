// L-systems (ABOP ch. 1-2): derivation, contexts, stochastic and parametric productions, the 3D turtle,
// refusals, and every preset through the model to a closed quad mesh.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "growth/lsystem/derivation.hpp"
#include "growth/lsystem/lsystem_model.hpp"
#include "growth/lsystem/lsystem_svg.hpp"
#include "growth/lsystem/turtle.hpp"
#include "mesh/joint_checks.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/stem_capsules.hpp"
#include "mesh/stem_polyline.hpp"
#include "mesh/tree_mesh.hpp"
#include "manifold_checks.hpp"
#include "test_support.hpp"

using namespace arbor;
using namespace arbor::lsys;

namespace {

// L(0) .. L(steps) as text.
std::vector<std::string> derivations(const std::string& grammar, int steps) {
  const Lsystem system = parseLsystem(grammar, "test.lsys");
  std::mt19937_64 random(system.seed);
  ModuleString s = axiomString(system);
  std::vector<std::string> out{s.text()};
  for (int step = 1; step <= steps; ++step) {
    s = deriveStep(system, s, random, step, 1'000'000);
    out.push_back(s.text());
  }
  return out;
}

std::string derived(const std::string& grammar) { return derive(parseLsystem(grammar, "test.lsys")).text(); }

std::vector<std::filesystem::path> presetFiles() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ARBOR_ASSET_DIR) + "/lsystems"))
    if (e.path().extension() == ".lsys") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// An ABOP plant among the presets, grown at the default seed.
Skeleton growPlant(const std::string& name) {
  const std::string file = std::string(ARBOR_ASSET_DIR) + "/lsystems/" + name + ".lsys";
  return readLsystemModel(readFile(file), file).grow({});
}

bool frameIsOrthonormal(const TurtleState& t, double tolerance) {
  return std::abs(glm::length(t.heading) - 1) < tolerance && std::abs(glm::length(t.left) - 1) < tolerance &&
         std::abs(glm::length(t.up) - 1) < tolerance && std::abs(glm::dot(t.heading, t.left)) < tolerance &&
         std::abs(glm::dot(t.heading, t.up)) < tolerance && std::abs(glm::dot(t.left, t.up)) < tolerance &&
         glm::length(glm::cross(t.heading, t.left) - t.up) < tolerance;
}

// The fraction of a string's characters that are `c`.
double share(const std::string& s, char c) {
  return static_cast<double>(std::count(s.begin(), s.end(), c)) / static_cast<double>(s.size());
}

bool sameBits(const TurtleState& a, const TurtleState& b) {
  return a.position == b.position && a.heading == b.heading && a.left == b.left && a.up == b.up && a.width == b.width &&
         a.colour == b.colour && a.node == b.node;
}

}  // namespace

TEST_CASE("a context-sensitive bracketed system reproduces ABOP's derivation", "[lsystem]") {
  // The listed derivation needs the boundary (string and branch ends) to read as '1', Hogeweg and Hesper's
  // environment; without it an isolated 1 has no production and L(1) would stay "1".
  const std::string grammar = R"(#ignore + -
environment: 1
n: 10
axiom: 1
0<0>0->0
0<0>1->1[1]
0<1>0->1
0<1>1->1
1<0>0->0
1<0>1->11
1<1>0->1
1<1>1->0
)";
  const std::vector<std::string> expected{"1", "0", "11", "00", "01[1]", "111[0]", "000[11]", "001[1][10]",
                                          "01[1]1[0][111]", "111[0]0[11][000]", "001[11]11[10][001[1]]"};
  CHECK(derivations(grammar, 10) == expected);
}

TEST_CASE("the Fibonacci system grows as ABOP's algae", "[lsystem]") {
  CHECK(derivations("n: 5\naxiom: b\na -> ab\nb -> a\n", 5) ==
        std::vector<std::string>{"b", "a", "ab", "aba", "abaab", "abaababa"});
}

TEST_CASE("contexts skip closed branches, enter parents and match bracketed right contexts", "[lsystem]") {
  CHECK(derived("n: 1\naxiom: B[D]C\nB < C -> Y\n") == "B[D]Y");     // the closed branch [D] is skipped
  CHECK(derived("n: 1\naxiom: B[D]C\nD < C -> Y\n") == "B[D]C");     // a closed branch is no left context
  CHECK(derived("n: 1\naxiom: A[B]\nA < B -> Y\n") == "A[Y]");       // a branch's left context is its parent
  CHECK(derived("n: 1\naxiom: A[B]C\nA > C -> Y\n") == "Y[B]C");     // sub-branches are skipped to the right
  CHECK(derived("n: 1\naxiom: A[B]C\nA > [B]C -> Y\n") == "Y[B]C");  // or matched, as ABOP's bracketed contexts
  CHECK(derived("n: 1\naxiom: A[D]C\nA > [B]C -> Y\n") == "A[D]C");
  CHECK(derived("n: 1\naxiom: A]B\nA > B -> Y\n") == "A]B");         // the axis ends at ']'
  CHECK(derived("n: 1\naxiom: 000\n0 < 0 > 0 -> 1\n") == "010");     // invisible boundaries at both ends
  CHECK(derived("n: 1\nenvironment: 0\naxiom: 000\n0 < 0 > 0 -> 1\n") == "111");  // unless they read as a module
  CHECK(derived("n: 1\nenvironment: 0\naxiom: A[0]0\nA < 0 > 0 -> 1\n") == "A[1]1");  // branch ends too
  CHECK(derived("n: 1\n#ignore +\naxiom: A+B\nA < B -> Y\n") == "A+Y");
  CHECK(derived("n: 1\naxiom: AB\nA < B -> X\nB -> Z\n") == "AX");     // the first matching production applies
}

TEST_CASE("parametric productions evaluate their conditions and expressions as written", "[lsystem]") {
  // ABOP p. 43.
  CHECK(derivations(R"(n: 4
axiom: B(2)A(4,4)
A(x,y) : y <= 3 -> A(x*2,x+y)
A(x,y) : y > 3 -> B(x)A(x/y,0)
B(x) : x < 1 -> C
B(x) : x >= 1 -> B(x-1)
)", 4) == std::vector<std::string>{"B(2)A(4,4)", "B(1)B(4)A(1,0)", "B(0)B(3)A(2,1)", "CB(2)A(4,3)", "CB(1)A(8,7)"});
  CHECK(derived("#define k 3\nn: 1\naxiom: A(2, k)\nA(x,y) : * -> B(x^y, -x^2, (x+1)*y, max(x,y), sqrt(16), cos(180))\n") ==
        "B(8,-4,9,3,4,-1)");
  CHECK(derived("n: 1\naxiom: A(1)A(2)A(3)\nA(x) : x == 2 || !(x < 3) && x != 1 -> B\n") == "A(1)BB");
  CHECK(derived("n: 1\naxiom: A(1)A(1,2)\nA(x) -> B(x)\n") == "B(1)A(1,2)");  // arity must match
  CHECK(derived("n: 1\naxiom: A(1)B(5)\nA(x) < B(y) -> B(x+y)\n") == "A(1)B(6)");
}

TEST_CASE("stochastic productions are chosen with their probabilities from the seed", "[lsystem]") {
  const std::string grammar = "n: 1\nseed: 7\naxiom: " + std::string(10000, 'X') +
                              "\nX -> (0.2) a\nX -> (0.3) b\nX -> (0.5) c\n";
  const std::string s = derived(grammar);
  CHECK(std::abs(share(s, 'a') - 0.2) < 0.02);
  CHECK(std::abs(share(s, 'b') - 0.3) < 0.02);
  CHECK(std::abs(share(s, 'c') - 0.5) < 0.02);
  const std::string plant = readFile(std::string(ARBOR_ASSET_DIR) + "/lsystems/fig-1-27.lsys");
  const Lsystem system = parseLsystem(plant, "fig-1-27.lsys");
  CHECK(derive(system).text() == derive(system).text());
  DeriveOptions other;
  other.seed = 2;
  CHECK(derive(system).text() != derive(system, other).text());
}

TEST_CASE("the turtle moves, turns left with '+' and draws only F", "[lsystem]") {
  TurtleSettings settings;
  settings.angle = 90;
  settings.step = 1;
  settings.start.heading = Vec3(1, 0, 0);
  settings.start.left = Vec3(0, 1, 0);
  settings.start.up = Vec3(0, 0, 1);
  const Lsystem system = parseLsystem("n: 0\naxiom: F+F-f\n", "t.lsys");
  const Interpretation r = interpret(derive(system), settings);
  CHECK(glm::length(r.last.position - Vec3(2, 1, 0)) < 1e-12);
  CHECK(r.segments == 2);
  CHECK(r.graph.nodes.size() == 3);
}

TEST_CASE("a line the turtle draws twice is one internode", "[lsystem]") {
  // F[F]F: the branch and the axis after it draw the same line from the same node.
  const Interpretation r = interpret(derive(parseLsystem("n: 0\naxiom: F[F]F[+F]\n", "t.lsys")), turtleSettings(parseLsystem("n: 0\naxiom: F\n", "t.lsys")));
  CHECK(r.segments == 3);
  CHECK(r.graph.nodes.size() == 4);
  // ABOP 1.24b and c derive whole subtrees twice (a branch leaving where, and as, its mother axis goes on); every
  // preset then has no two internodes from one node to one point.
  std::size_t merged = 0;
  for (const auto& path : presetFiles()) {
    INFO(path.filename().string());
    const Lsystem system = parseLsystem(readFile(path.string()), path.string());
    const ModuleString str = derive(system);
    const Interpretation drawn = interpret(str, turtleSettings(system));
    std::map<std::pair<std::int32_t, std::array<double, 3>>, int> seen;
    for (const BranchNode& n : drawn.graph.nodes) {
      if (n.parent < 0) continue;
      // Rounded far coarser than the merge's tolerance, so near misses would show as repeats too.
      const double unit = 1e-6 * glm::length(n.position - drawn.graph.nodes[static_cast<std::size_t>(n.parent)].position);
      const std::array<double, 3> key{std::round(n.position.x / unit), std::round(n.position.y / unit), std::round(n.position.z / unit)};
      CHECK(++seen[{n.parent, key}] == 1);
    }
    std::size_t fs = 0;
    for (std::size_t i = 0; i < str.size(); ++i) fs += str.modules[i].symbol == 'F' ? 1 : 0;
    if (path.filename() == "fig-1-24c.lsys" || path.filename() == "fig-1-24b.lsys") CHECK(drawn.segments < fs);
    merged += fs - std::min(fs, drawn.segments);
  }
  CHECK(merged > 1000);
}

TEST_CASE("turtle rotations keep the frame orthonormal and right-handed and undo one another", "[lsystem]") {
  TurtleState t;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> angle(-3.2, 3.2);
  for (int i = 0; i < 100000; ++i) {
    switch (random() % 5) {
      case 0: turn(t, angle(random)); break;
      case 1: pitch(t, angle(random)); break;
      case 2: roll(t, angle(random)); break;
      case 3: turnAround(t); break;
      default: rollHorizontal(t, Vec3(0, 0, 1)); break;
    }
  }
  CHECK(frameIsOrthonormal(t, 1e-6));

  TurtleSettings settings;
  settings.angle = 37;
  settings.start = t;
  const auto after = [&](const std::string& axiom) {
    return interpret(derive(parseLsystem("n: 0\naxiom: " + axiom + "\n", "t.lsys")), settings).last;
  };
  for (const std::string pair : {"&^", "^&", "+-", "-+", "\\/", "/\\", "||"}) {
    const TurtleState u = after(pair);
    INFO(pair);
    CHECK(glm::length(u.heading - t.heading) < 1e-12);
    CHECK(glm::length(u.left - t.left) < 1e-12);
    CHECK(glm::length(u.up - t.up) < 1e-12);
  }
  const TurtleState flipped = after("|");
  CHECK(flipped.heading == -t.heading);
  CHECK(flipped.left == -t.left);
  CHECK(flipped.up == t.up);
  CHECK(sameBits(after("[F&(13)+F!(0.3)'/(71)F]"), t));
  const TurtleState down = after("&(90)");
  CHECK(glm::length(down.heading + t.up) < 1e-12);  // '&' pitches down, toward -U
}

TEST_CASE("tropism bends the heading toward T by e |H x T|", "[lsystem]") {
  TurtleState t;
  t.heading = Vec3(1, 0, 0);
  t.left = Vec3(0, 1, 0);
  t.up = Vec3(0, 0, 1);
  bend(t, Vec3(0, 0, -1), 0.5);
  CHECK(std::abs(std::acos(glm::dot(t.heading, Vec3(1, 0, 0))) - 0.5) < 1e-12);
  CHECK(t.heading.z < 0);
  CHECK(frameIsOrthonormal(t, 1e-12));
}

TEST_CASE("polygons become leaves, widths radii and '%' cuts a branch", "[lsystem]") {
  const Lsystem system = parseLsystem("n: 0\ndelta: 90\nwidth: 0.4\naxiom: F!(0.2)F[+F%F]{.f+f+f}\n", "t.lsys");
  const Interpretation r = interpret(derive(system), turtleSettings(system));
  REQUIRE(r.graph.nodes.size() == 4);  // root, two F and the branch's first F (the second is cut)
  CHECK(r.graph.nodes[1].radius == Approx(0.2));
  CHECK(r.graph.nodes[2].radius == Approx(0.1));
  REQUIRE(r.graph.leaves.size() == 1);
  CHECK(r.graph.leaves[0].node == 2);
  CHECK(r.graph.leaves[0].length == Approx(std::sqrt(2.0)));
  CHECK(r.graph.leaves[0].width > 0);
}

TEST_CASE("bad grammars are refused with file, line and column", "[lsystem]") {
  const auto parse = [](const std::string& text) { return test::refusal([&] { parseLsystem(text, "bad.lsys"); }); };
  CHECK_THAT(parse("n: 1\naxiom: F\nF -> F(1,\n"), Catch::Contains("bad.lsys: field 'line 3, column 10'"));
  CHECK_THAT(parse("n: 1\naxiom: A(1)\nA(x) -> B(y)\n"), Catch::Contains("line 3, column 11") && Catch::Contains("undefined name 'y'"));
  CHECK_THAT(parse("n: 1\naxiom: F\nF -> (0.5) F\nF -> (0.4) FF\n"), Catch::Contains("line 3") && Catch::Contains("sum to 0.9, not 1"));
  CHECK_THAT(parse("n: 1\naxiom: F\nF -> F\nF -> FF\n"), Catch::Contains("line 4") && Catch::Contains("same predecessor"));
  CHECK_THAT(parse("n: 1\naxiom: F\nFG -> F\n"), Catch::Contains("line 3, column 1") && Catch::Contains("exactly one module"));
  CHECK_THAT(parse("n: 1\nF -> F\n"), Catch::Contains("axiom"));
  CHECK_THAT(parse("axiom: F\n"), Catch::Contains("field 'n'"));
  CHECK_THAT(parse("n: 1\naxiom: F\ndleta: 3\n"), Catch::Contains("did you mean 'delta:'"));
  CHECK_THAT(parse("n: 1.5\naxiom: F\n"), Catch::Contains("line 1, column 4") && Catch::Contains("whole number"));
  CHECK_THAT(parse("n: 1\nsize: 1e9\naxiom: F\n"), Catch::Contains("line 2, column 7") && Catch::Contains("at most 100000 m"));
  CHECK_THAT(parse("n: 1\naxiom: F\nA -> B(sin(1,2))\n"), Catch::Contains("line 3"));
  CHECK_THAT(parse("n: 1\naxiom: F\nA -> B(" + std::string(300, '(') + "1" + std::string(300, ')') + ")\n"),
             Catch::Contains("deeper than 100"));
  const auto run = [](const std::string& text) { return test::refusal([&] { derive(parseLsystem(text, "bad.lsys")); }); };
  CHECK(run("n: 3\naxiom: A(2)\nA(x) -> A(x-1)\nA(x) : x < 5 -> A(1/x)\n") == "");  // the first production applies: no division
  CHECK_THAT(run("n: 3\naxiom: A(2)\nA(x) -> A(1/(x-1))\n"),
             Catch::Contains("field 'line 3'") && Catch::Contains("derivation step 2") && Catch::Contains("division by zero"));
  const Lsystem big = parseLsystem("n: 30\nlimit: 1000\naxiom: F\nF -> FF\n", "big.lsys");
  try {
    derive(big);
    FAIL("no LimitError");
  } catch (const LimitError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("derivation step 10") && Catch::Contains("1000 modules"));
  }
}

TEST_CASE("a grammar whose turtle walks out of the mesh's reach is refused, not meshed into NaN", "[lsystem]") {
  // Unscaled (no size:), each F a million kilometres: the nodes pass kMaxCoordinate, which every model's growth checks.
  const TreeModel far = readLsystemModel("name: far\nn: 1\nd: 1e9\naxiom: F\nF -> FFF\n", "far.lsys");
  try {
    far.grow({});
    FAIL("no GenerationError");
  } catch (const GenerationError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("far: a node on axis") && Catch::Contains("within 100000 m"));
  }
  CHECK(readLsystemModel("name: near\nn: 1\nd: 1000\naxiom: F\nF -> FFF\n", "near.lsys").grow({}).nodes.size() > 1);
}

TEST_CASE("every preset parses, derives, draws and meshes to a closed quad manifold", "[lsystem]") {
  const auto files = presetFiles();
  REQUIRE(files.size() >= 12);
  for (const auto& path : files) {
    INFO(path.filename().string());
    const std::string text = readFile(path.string());
    const TreeModel model = readLsystemModel(text, path.string());
    CHECK(model.model() == std::string("l-system"));
    CHECK(model.name().rfind("ABOP", 0) == 0);
    const Skeleton s = model.grow({});
    CHECK(s.nodes.size() >= 2);
    const TreeMesh tree = buildTreeMesh(s);
    test::checkClosedManifold(tree.mesh);
    const Lsystem& system = *lsystemOf(model);
    const bool planar = path.filename().string().rfind("fig-1-2", 0) == 0 || path.filename().string().rfind("fig-1-3", 0) == 0;
    if (planar && path.filename() != "fig-1-25.lsys") {
      const std::string svg = writeLsystemSvg(system);
      CHECK(svg.rfind("<svg", 0) == 0);
      CHECK(svg.find("<path") != std::string::npos);
    } else {
      CHECK_THAT(test::refusal([&] { writeLsystemSvg(system); }), Catch::Contains("out of the plane"));
    }
  }
}

TEST_CASE("a meshed stem with no meshed child clears its parent's wood before it ends", "[lsystem][mesh]") {
  // ABOP's plants have trunks far thicker than their short branches: a branch inside its trunk to its end whose own
  // branches are all fake branches is one too (meshed, a collar far up the trunk and a tube folding back down).
  std::size_t twigs = 0, buried = 0;
  for (const auto& path : presetFiles()) {
    INFO(path.filename().string());
    const TreeModel model = readLsystemModel(readFile(path.string()), path.string());
    const Skeleton s = model.grow({});
    const TreeMesh tree = buildTreeMesh(s);
    std::vector<bool> faked(s.stems.size(), false), bears(s.stems.size(), false);
    for (int f : tree.fakedStems) faked[static_cast<std::size_t>(f)] = true;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (faked[i] || st.stub || st.cloneOf >= 0) continue;
      for (int x = st.parentStem; x >= 0; x = s.stems[static_cast<std::size_t>(x)].cloneOf) bears[static_cast<std::size_t>(x)] = true;
    }
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.parentStem < 0 || st.cloneOf >= 0 || st.stub || bears[i]) continue;
      const bool inside = parentClearance(s, static_cast<int>(i)) >= StemPolyline(s, static_cast<int>(i)).length();
      buried += inside ? 1 : 0;
      if (faked[i]) continue;
      ++twigs;
      CHECK_FALSE(inside);
    }
  }
  CHECK(twigs > 100);
  CHECK(buried > 100);  // the rule has work to do on these plants
}

TEST_CASE("a tube passes its stem's branch points within their radius where their children are fake branches", "[lsystem][mesh]") {
  // ABOP 1.24c turns at every node: a tube straight across a run of such branch points cut the corner through its
  // parent and neighbours. Checked between consecutive cross sections on the skeleton.
  for (const char* name : {"fig-1-24c", "fig-1-24f", "fig-1-31a"}) {
    INFO(name);
    const Skeleton s = growPlant(name);
    const TreeMesh tree = buildTreeMesh(s);
    std::vector<bool> meshed(s.stems.size(), false);
    for (int stem : tree.quadStem)
      if (stem >= 0) meshed[static_cast<std::size_t>(stem)] = true;
    std::vector<bool> bearing(s.nodes.size(), false);  // a meshed stem leaves the node
    for (std::size_t i = 0; i < s.stems.size(); ++i)
      if (meshed[i] && s.stems[i].attachNode >= 0) bearing[static_cast<std::size_t>(s.stems[i].attachNode)] = true;
    std::vector<std::vector<const MeshRing*>> rings(s.stems.size());
    for (const MeshRing& r : tree.rings)
      if (r.stem >= 0 && r.arc >= 0) rings[static_cast<std::size_t>(r.stem)].push_back(&r);
    std::size_t passed = 0;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      if (!meshed[i]) continue;
      const StemPolyline poly(s, static_cast<int>(i));
      const auto& own = rings[i];
      for (std::size_t k = 1; k < own.size(); ++k) {
        for (int j = 0; j < poly.pointCount(); ++j) {
          const double arc = poly.arcLength(j);
          const SkeletonNode& n = s.nodes[static_cast<std::size_t>(poly.node(j))];
          if (arc <= own[k - 1]->arc || arc >= own[k]->arc || n.kind != NodeKind::Attachment || bearing[static_cast<std::size_t>(poly.node(j))]) continue;
          const Vec3 p = poly.position(arc);
          CHECK(segmentDistance(p, p, own[k - 1]->center, own[k]->center) <= poly.radius(arc) * 1.0001);
          ++passed;
        }
      }
    }
    CHECK(passed > 20);
  }
}

TEST_CASE("the ABOP plants have no mesh-made pair, and their folds and neck crossings stay at their measured counts", "[lsystem][mesh][self-intersection]") {
  // Mesh-made pairs are issue 13's floor of zero on every preset since 2026-12-06: fig-1-24d kept 2 until a neck still
  // crossing another stem from its nearer collar also leaned along its stem. The other counts are those of 2026-12-06
  // (docs/mesh.md, seed 1) plus a tenth, so that a change to the mesher or the turtle that makes more fails here; a
  // zero stays zero. fig-1-24c's necks through the trunk are skeleton-made (its limbs run inside the trunk's wood and
  // turn back into it), and so are, since 2026-12-06, its 2 pairs of a twig's collar on such a limb across the trunk.
  struct Measured {
    const char* plant;
    std::size_t folds, necks, throughParent;
  };
  for (const Measured& m : {Measured{"fig-1-24a", 0, 0, 0}, Measured{"fig-1-24b", 0, 0, 0}, Measured{"fig-1-24c", 0, 181, 31},
                            Measured{"fig-1-24d", 0, 12, 0}, Measured{"fig-1-24e", 0, 0, 0}, Measured{"fig-1-24f", 0, 86, 0},
                            Measured{"fig-1-25", 0, 0, 0}, Measured{"fig-1-27", 0, 10, 0}, Measured{"fig-1-31a", 0, 0, 0},
                            Measured{"fig-2-6a", 0, 0, 0}, Measured{"fig-2-7a", 0, 0, 0}, Measured{"fig-2-8a", 0, 0, 0}}) {
    INFO(m.plant);
    const Skeleton s = growPlant(m.plant);
    const SelfIntersectionReport r = checkSelfIntersections(buildTreeMesh(s), s);
    CHECK(r.meshMade == 0);
    CHECK(r.folds * 10 <= m.folds * 11);
    CHECK(r.neckCrossings * 10 <= m.necks * 11);
    CHECK(r.necksThroughParent * 10 <= m.throughParent * 11);
  }
}

TEST_CASE("children attached along a parent's neck leave it within the joint floor", "[lsystem][mesh]") {
  // A stem whose wood runs along its own parent has a long neck; its children attached there leave through slabs cut
  // out of that neck from six of its radii on (eight before), their collars near as the floor measures it. ABOP
  // fig. 1.24d's limbs 13, 33 and 113 sat 1.50, 1.79 and 4.15 parent radii along, fig-1-27's limb 82 at seed 3 1.80.
  // Left past the floor: fig-1-24d's limb 73 (2.22), on a neck whose line runs off its parent's skeleton, and
  // fig-1-31a's 92 and 105, attached where their parent still runs inside the trunk's wood.
  struct Plant {
    const char* name;
    std::uint64_t seed;
    std::vector<int> past;  // children left past 1.5 parent radii
  };
  for (const Plant& p : {Plant{"fig-1-24d", 1, {73}}, Plant{"fig-1-27", 3, {}}, Plant{"fig-1-24c", 1, {}}, Plant{"fig-1-25", 1, {}}}) {
    INFO(p.name << " at seed " << p.seed);
    const std::string file = std::string(ARBOR_ASSET_DIR) + "/lsystems/" + p.name + ".lsys";
    GrowthOptions growth;
    growth.seed = p.seed;
    const Skeleton s = readLsystemModel(readFile(file), file).grow(growth);
    const TreeMesh tree = buildTreeMesh(s);
    std::vector<int> past;
    for (const ChildPlacement& c : childPlacements(s, tree)) {
      if (c.offset > 1.5) past.push_back(c.stem);
    }
    CHECK(past == p.past);
    CHECK(checkTopology(tree.mesh).boundaryEdges == 0);
    CHECK(meshMadeIntersections(tree, s) == 0);
  }
}

TEST_CASE("a plant whose one trunk grows from a root node stands on the ground, its lowest limbs where they attach", "[lsystem][mesh]") {
  // ABOP 1.24a, 1.24b and 1.27 branch within a trunk radius of the ground, so their skeletons have a Root node under
  // the one trunk. A hub there (three trunk radii tall) held fig-1-24b's limb 12 2.20 trunk radii up from where it
  // attaches; standing on the ground, every child's first ring is within the joint floor of 1.5 parent radii.
  for (const char* plant : {"fig-1-24a", "fig-1-24b", "fig-1-27"}) {
    INFO(plant);
    const Skeleton s = growPlant(plant);
    REQUIRE(s.nodes.front().kind == NodeKind::Root);
    const TreeMesh tree = buildTreeMesh(s);
    double worst = 0.0;
    for (const ChildPlacement& c : childPlacements(s, tree)) worst = std::max(worst, c.offset);
    CHECK(worst <= 1.5);
    CHECK(checkTopology(tree.mesh).boundaryEdges == 0);
    CHECK(meshMadeIntersections(tree, s) == 0);
  }
}

TEST_CASE("the l-system model's parameters edit the grammar and re-derive", "[lsystem]") {
  const std::string text = readFile(std::string(ARBOR_ASSET_DIR) + "/lsystems/fig-2-6a.lsys");
  TreeModel model = readLsystemModel(text, "fig-2-6a.lsys");
  const auto params = model.parameters();
  REQUIRE(params.size() == 5 + 6);
  CHECK(params[0].key == "n");
  CHECK(params[5].key == "r1");
  CHECK(model.value(0) == 10);
  CHECK(model.value(5) == 0.9);
  const TreeModel before = model;
  model.setValue(0, 6);
  model.setValue(5, 0.8);
  CHECK(before.value(0) == 10);  // copies are independent
  const Skeleton small = model.grow({}), large = before.grow({});
  CHECK(small.nodes.size() < large.nodes.size());
  const TreeModel reread = readLsystemModel(model.toJson(), "fig-2-6a.lsys");
  CHECK(reread.value(0) == 6);
  CHECK(reread.value(5) == 0.8);
  CHECK(reread.name() == model.name());
  const TreeEstimate e = model.estimate(0);
  CHECK(e.nodes > 30);
  CHECK(e.nodes < 200);
  CHECK_THAT(test::refusal([&] {
               ModelReadOptions o;
               o.naturalAngles = true;
               readLsystemModel(text, "x.lsys", o);
             }),
             Catch::Contains("no angle rules"));
  GrowthOptions tiny;
  tiny.limits.nodes = 5;
  CHECK_THROWS_AS(model.grow(tiny), GenerationError);  // counted before the turtle runs
  GrowthOptions seeded;
  seeded.seed = 3;
  const std::string stochastic = readFile(std::string(ARBOR_ASSET_DIR) + "/lsystems/fig-1-27.lsys");
  const TreeModel plant = readLsystemModel(stochastic, "fig-1-27.lsys");
  CHECK(plant.grow({}).nodes.size() > 0);
  CHECK(plant.grow(seeded).nodes.size() == plant.grow(seeded).nodes.size());
}

TEST_CASE("ten million modules derived and interpreted", "[.bench]") {
  // Node rewriting with brackets (ABOP 1.24d); three axioms so that L(12) holds about 10^7 modules.
  const Lsystem system = parseLsystem("n: 12\ndelta: 20\naxiom: XXX\nX -> F[+X]F[-X]+X\nF -> FF\n", "bench.lsys");
  const auto t0 = std::chrono::steady_clock::now();
  const ModuleString s = derive(system);
  const auto t1 = std::chrono::steady_clock::now();
  const Interpretation r = interpret(s, turtleSettings(system));
  const auto t2 = std::chrono::steady_clock::now();
  const double derivation = std::chrono::duration<double>(t1 - t0).count(), turtle = std::chrono::duration<double>(t2 - t1).count();
  WARN(s.size() << " modules, " << r.segments << " internodes: derivation " << derivation << " s, interpretation " << turtle
                << " s, " << static_cast<double>(s.size()) / (derivation + turtle) / 1e6 << " million modules per second");
  CHECK(s.size() > 9'000'000);
  CHECK(derivation + turtle < 2.0);
}
