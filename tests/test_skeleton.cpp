// Skeleton invariants: r^E conservation at every branch point, Murray's angles at every attachment,
// breadth-first level invariance, determinism, exact child and leaf counts, pruning, flare.
#include <catch2/catch.hpp>
#include <cmath>
#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "growth/weber_penn/natural_rules.hpp"
#include "growth/skeleton_checks.hpp"
#include "growth/skeleton_json.hpp"
#include "growth/weber_penn/weber_penn.hpp"
#include "growth/weber_penn/weber_penn_rules.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "test_support.hpp"

using namespace arbor;
using Catch::Matchers::WithinAbs;

namespace {

Skeleton grow(const SpeciesParams& p, std::uint64_t seed, int levels = 0) {
  GrowthOptions o;
  o.seed = seed;
  o.levels = levels;
  return generateSkeleton(p, o);
}

const SkeletonNode& node(const Skeleton& s, int i) { return s.nodes[static_cast<std::size_t>(i)]; }

// The node that continues the parent stem after attachment node a.
int continuationOf(const Skeleton& s, int a) {
  for (std::size_t i = static_cast<std::size_t>(a) + 1; i < s.nodes.size(); ++i) {
    if (s.nodes[i].parent == a && s.nodes[i].stem == node(s, a).stem) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

TEST_CASE("r^E is conserved at every branch point of every preset", "[skeleton]") {
  for (const std::string& name : test::presetNames()) {
    const SpeciesParams p = test::loadPreset(name);
    for (std::uint64_t seed : {1u, 7u}) {
      INFO(name << " seed " << seed);
      const Skeleton s = grow(p, seed);
      CHECK(structuralProblems(s).empty());
      CHECK(worstConservationError(s) < 1e-12);
      CHECK(skeletonStats(s).branchPoints > 0);
    }
  }
}

TEST_CASE("the skeleton is one connected tree", "[skeleton]") {
  SpeciesParams p = test::steadySpecies();
  p.stemLevels[0].branches = 3;  // several trunks meet in a root node
  p.stemLevels[0].downAngle = 20;
  p.stemLevels[0].rotate = 120;
  for (const SpeciesParams& q : {test::steadySpecies(), p}) {
    const Skeleton s = grow(q, 3);
    int roots = 0;
    for (const SkeletonNode& n : s.nodes) roots += n.parent < 0 ? 1 : 0;
    CHECK(roots == 1);
    CHECK(worstConservationError(s) < 1e-12);
  }
}

TEST_CASE("children leave at Murray's angle and deflect their parent by Murray's x", "[skeleton]") {
  for (const std::string& name : test::presetNames()) {
    const SpeciesParams p = test::loadPreset(name);
    const Skeleton s = grow(p, 2);
    const bool natural = p.angleRule == AngleRule::Natural;
    int checked = 0;
    for (const SkeletonStem& st : s.stems) {
      if (st.parentStem < 0 || st.cloneOf >= 0) continue;
      INFO(name << " stem level " << st.level);
      const int a = st.attachNode;
      const int c = continuationOf(s, a);
      REQUIRE(c >= 0);
      const Vec3 at = node(s, a).world.position;
      const Vec3 incoming = node(s, a).world.direction();
      const Vec3 child = node(s, st.firstNode).world.position - at;
      const Vec3 primary = node(s, c).world.position - at;
      // A classic down angle below zero (the palm's 70 - 80 degrees near the crown's base) leans the child the
      // other way round the parent: the angle between them is its size.
      CHECK_THAT(test::angleBetween(incoming, child), WithinAbs(std::abs(st.secondaryAngle), 1e-9));
      CHECK_THAT(test::angleBetween(incoming, primary), WithinAbs(st.primaryDeflection, 1e-9));
      if (natural) {
        // Child and primary on opposite sides of the incoming direction: x + y apart.
        CHECK_THAT(test::angleBetween(child, primary), WithinAbs(st.secondaryAngle + st.primaryDeflection, 1e-9));
        const double Cp = natural::primaryRadiusFactor(st.branchRatio, s.exponent);
        const double Cs = natural::secondaryRadiusFactor(st.branchRatio, s.exponent);
        CHECK_THAT(st.secondaryAngle, WithinAbs(natural::secondaryAngle(1.0, Cp, Cs), 1e-12));
        CHECK_THAT(st.primaryDeflection, WithinAbs(natural::primaryAngle(1.0, Cp, Cs), 1e-12));
      } else {
        CHECK(st.primaryDeflection == 0.0);
      }
      ++checked;
    }
    CHECK(checked > 0);
  }
}

TEST_CASE("one more level keeps the lower levels of the same seed (breadth-first)", "[skeleton]") {
  for (const std::string& name : test::presetNames()) {
    const SpeciesParams p = test::loadPreset(name);
    for (int k = 1; k < p.levels; ++k) {
      INFO(name << ": levels " << k << " -> " << k + 1);
      const Skeleton a = grow(p, 5, k), b = grow(p, 5, k + 1);
      std::map<std::uint64_t, const SkeletonStem*> byKey;
      for (const SkeletonStem& st : b.stems) byKey[st.key] = &st;
      std::size_t rawMismatches = 0, finalMismatches = 0, skeletonMismatches = 0;
      for (const SkeletonStem& st : a.stems) {
        auto it = byKey.find(st.key);
        REQUIRE(it != byKey.end());
        const SkeletonStem& other = *it->second;
        // Raw tree data of every level of the smaller tree: identical bit for bit.
        // (Radii are not raw data: the natural rules apply them, and new children change the deepest level's.)
        const bool rawSame = other.level == st.level && other.length == st.length &&
                             other.rawJoints.size() == st.rawJoints.size() &&
                             std::equal(st.rawJoints.begin(), st.rawJoints.end(), other.rawJoints.begin(),
                                        [](const Transform& x, const Transform& y) {
                                          return x.position == y.position && x.rotation == y.rotation;
                                        });
        rawMismatches += rawSame ? 0 : 1;
        if (st.level < k - 1) {
          // Final skeleton below the deepest level of the smaller tree: identical.
          bool same = st.nodeCount == other.nodeCount;
          for (int i = 0; same && i < st.nodeCount; ++i) {
            const SkeletonNode& x = node(a, st.firstNode + i);
            const SkeletonNode& y = node(b, other.firstNode + i);
            same = x.kind == y.kind && x.offset == y.offset && x.world.position == y.world.position &&
                   x.radius == y.radius && x.startRadius == y.startRadius;
          }
          finalMismatches += same ? 0 : 1;
        } else {
          // The deepest level differs only by the intermediate nodes (and deflections) of its new children.
          std::vector<std::pair<NodeKind, double>> x, y;
          auto structural = [](NodeKind kind) {
            return kind == NodeKind::Joint || kind == NodeKind::Tip || kind == NodeKind::Split || kind == NodeKind::Base;
          };
          for (int i = 0; i < st.nodeCount; ++i) {
            const SkeletonNode& n = node(a, st.firstNode + i);
            if (structural(n.kind)) x.emplace_back(n.kind, n.offset);
          }
          for (int i = 0; i < other.nodeCount; ++i) {
            const SkeletonNode& n = node(b, other.firstNode + i);
            if (structural(n.kind)) y.emplace_back(n.kind, n.offset);
          }
          skeletonMismatches += x == y ? 0 : 1;
        }
      }
      CHECK(rawMismatches == 0);
      CHECK(finalMismatches == 0);
      CHECK(skeletonMismatches == 0);
    }
  }
}

TEST_CASE("the same seed gives byte-identical output, another seed another tree", "[skeleton]") {
  const SpeciesParams p = test::loadPreset("black-tupelo");
  const std::string a = writeSkeletonJson(grow(p, 11)), b = writeSkeletonJson(grow(p, 11));
  CHECK(a == b);
  CHECK(a != writeSkeletonJson(grow(p, 12)));
}

TEST_CASE("child counts follow the formulas exactly when variations are zero", "[skeleton]") {
  const SpeciesParams p = test::steadySpecies();
  const Skeleton s = grow(p, 1);
  std::vector<int> children(s.stems.size(), 0);
  for (const SkeletonStem& st : s.stems) {
    if (st.parentStem >= 0 && st.cloneOf < 0) ++children[static_cast<std::size_t>(st.parentStem)];
  }
  const SkeletonStem& trunk = s.stems[0];
  CHECK(children[0] == 12);
  int levelOne = 0;
  for (std::size_t i = 0; i < s.stems.size(); ++i) {
    const SkeletonStem& st = s.stems[i];
    if (st.level != 1) continue;
    // A whole number of children per stem, as Arbaro counts them (and the level's error shared, so exactly that).
    const double expected = wp::childCountOfLevel1(8, st.length, trunk.length, 0.4);
    CHECK(children[i] == static_cast<int>(std::floor(expected)));
    ++levelOne;
  }
  CHECK(levelOne == 12);
}

TEST_CASE("a level's split error is shared by its stems, and a split stem's children by its pieces", "[skeleton]") {
  SpeciesParams p = test::steadySpecies();
  p.stemLevels[0].segSplits = 0.3;
  p.stemLevels[0].splitAngle = 20;
  p.stemLevels[1].segSplits = 0.2;
  p.stemLevels[1].splitAngle = 20;
  p.stemLevels[1].curveRes = 6;
  const Skeleton s = grow(p, 4, 2);
  std::vector<int> clones(s.stems.size(), 0);
  for (const SkeletonStem& st : s.stems) {
    if (st.cloneOf >= 0) ++clones[static_cast<std::size_t>(st.cloneOf)];
  }
  for (int level : {0, 1}) {
    // Every joint a piece walks past (its tip aside) draws on the level's one error, as Arbaro's LevelParams
    // does: the level splits SegSplits times per joint within half a split, whatever each stem did.
    double joints = 0.0, splits = 0.0;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.level != level) continue;
      const double walked = static_cast<double>(st.rawJoints.size() - 1);
      joints += clones[i] > 0 ? walked : walked - 1.0;
      splits += clones[i] > 0 ? clones[i] - 1 : 0;
    }
    INFO("level " << level << ": " << joints << " joints, " << splits << " splits");
    CHECK(splits > 0.0);
    CHECK(std::abs(splits - p.stemLevels[static_cast<std::size_t>(level)].segSplits * joints) <= 0.5 + 1e-9);
  }
  // The trunk's pieces share its Branches between them: as many children as an unsplit trunk has.
  int trunkChildren = 0;
  for (const SkeletonStem& st : s.stems) trunkChildren += st.level == 1 && st.cloneOf < 0 ? 1 : 0;
  CHECK(trunkChildren == 12);
}

TEST_CASE("children too stubby to draw as tubes grow as Arbaro grows them, marked for the mesh", "[skeleton]") {
  SpeciesParams p = test::steadySpecies();
  p.stemLevels[1].length = 0.004;  // 4 cm children on a 10 m trunk of 20 cm radius end inside it
  const Skeleton s = grow(p, 1, 3);
  int children = 0, stubs = 0;
  for (const SkeletonStem& st : s.stems) {
    if (st.level == 1) {
      ++children;
      stubs += st.stub ? 1 : 0;
    }
    if (st.parentStem >= 0 && s.stems[static_cast<std::size_t>(st.parentStem)].stub) CHECK(st.stub);  // grows from one
  }
  CHECK(children == 12);
  CHECK(stubs == 12);
  CHECK(worstConservationError(s) < 1e-12);
  CHECK(structuralProblems(s).empty());
  for (const SkeletonStem& st : grow(test::steadySpecies(), 1).stems) CHECK_FALSE(st.stub);
}

TEST_CASE("leaf counts follow the formula when variations are zero: within one per stem, exactly for the tree", "[skeleton]") {
  const SpeciesParams p = test::steadySpecies();
  const Skeleton s = grow(p, 1);
  std::vector<int> leaves(s.stems.size(), 0);
  for (const Leaf& l : s.leaves) ++leaves[static_cast<std::size_t>(l.stem)];
  int deepest = 0;
  double total = 0.0;
  for (std::size_t i = 0; i < s.stems.size(); ++i) {
    const SkeletonStem& st = s.stems[i];
    if (st.level != 2) {
      CHECK(leaves[i] == 0);
      continue;
    }
    const double parentLength = s.stems[static_cast<std::size_t>(st.parentStem)].length;
    const double expected = 6.0 * wp::shapeRatio(4, st.offsetOnParent / parentLength);
    // The rounding error is the tree's, carried from stem to stem as in Arbaro: each stem is within one.
    CHECK(std::abs(leaves[i] - expected) < 1.0);
    total += expected;
    ++deepest;
  }
  CHECK(deepest > 50);
  CHECK(std::abs(static_cast<double>(s.leaves.size()) - total) <= 0.5 + 1e-9);
  for (const Leaf& l : s.leaves) {
    CHECK_THAT(glm::length(l.direction), WithinAbs(1.0, 1e-12));
    CHECK_THAT(glm::dot(l.direction, l.normal), WithinAbs(0.0, 1e-12));
    CHECK(l.normal.z >= -1e-12);  // faces the sky
  }
}

TEST_CASE("trunk radius and flare follow Ratio and Flare", "[skeleton]") {
  SpeciesParams p = test::steadySpecies();
  p.flare = 0.8;
  const Skeleton s = grow(p, 1);
  const double trunkRadius = 10.0 * p.ratio;  // length 1 * Scale 10, TrunkScale 1
  CHECK_THAT(s.nodes[0].radius, WithinAbs(trunkRadius * (1.0 + 0.8 * 0.99), 1e-12));
  // Along an unbranched twig of taper 1 the radius falls to zero at the tip.
  for (const SkeletonStem& st : s.stems) {
    if (st.level != 2) continue;
    double previous = st.startRadius;
    for (int i = 0; i < st.nodeCount; ++i) {
      const SkeletonNode& n = node(s, st.firstNode + i);
      CHECK(n.radius <= previous + 1e-15);
      previous = n.radius;
    }
    CHECK_THAT(previous, WithinAbs(0.0, 1e-12));
  }
}

TEST_CASE("pruned stems lie inside the envelope", "[skeleton]") {
  const SpeciesParams p = test::loadPreset("weeping-willow");
  REQUIRE(p.pruneRatio == 1.0);
  const Skeleton s = grow(p, 4);
  std::size_t outside = 0, tested = 0;
  for (const SkeletonStem& st : s.stems) {
    if (st.level == 0) continue;
    for (std::size_t j = 1; j < st.rawJoints.size(); ++j) {
      const Vec3& q = st.rawJoints[j].position;
      outside += wp::insideEnvelope(p, s.treeScale, q.x, q.y, q.z) ? 0 : 1;
      ++tested;
    }
  }
  CHECK(tested > 1000);
  CHECK(outside == 0);
}

TEST_CASE("extra levels beyond the species' reuse its deepest level parameters", "[skeleton]") {
  const SpeciesParams p = test::loadPreset("quaking-aspen");
  const Skeleton s = grow(p, 1, p.levels + 1);
  const SkeletonStats stats = skeletonStats(s);
  REQUIRE(stats.stemsPerLevel.size() == static_cast<std::size_t>(p.levels + 1));
  CHECK(stats.stemsPerLevel.back() > stats.stemsPerLevel[static_cast<std::size_t>(p.levels - 1)]);
  CHECK(worstConservationError(s) < 1e-12);
}

TEST_CASE("too large a tree is refused, not grown until memory runs out", "[skeleton]") {
  SpeciesParams p = test::steadySpecies();
  GrowthOptions o;
  o.limits.nodes = 100;
  CHECK_THROWS_AS(generateSkeleton(p, o), GenerationError);
}

TEST_CASE("the size estimate is close to the grown tree on every preset and refuses hopeless trees at once", "[skeleton][limits]") {
  for (const std::string& name : test::presetNames()) {
    const SpeciesParams p = test::loadPreset(name);
    const TreeEstimate e = estimateTree(p);
    const SkeletonStats stats = skeletonStats(grow(p, 1));
    INFO(name << ": " << e.nodes << " nodes estimated, " << stats.nodes << " grown; " << e.leaves << " leaves estimated, " << stats.leaves);
    // It cannot see pruning, random variation or children left out for their size: high rather than low.
    CHECK(e.nodes >= 0.9 * static_cast<double>(stats.nodes));
    CHECK(e.nodes <= 2.0 * static_cast<double>(stats.nodes));
    CHECK(e.leaves >= 0.7 * static_cast<double>(stats.leaves));
    CHECK(e.leaves <= 2.0 * static_cast<double>(stats.leaves));
    CHECK(e.excess(TreeLimits{}).empty());
  }
  // Two clones at every joint of a 64-segment trunk: 3^63 stems.
  SpeciesParams huge = test::steadySpecies();
  huge.levels = 1;
  huge.stemLevels.resize(1);
  huge.stemLevels[0].segSplits = 2;
  huge.stemLevels[0].curveRes = 64;
  const TreeEstimate e = estimateTree(huge);
  CHECK(e.nodes > 1e29);
  CHECK_THAT(e.excess(TreeLimits{}), Catch::Contains("SegSplits 2 over CurveRes 64") && Catch::Contains("limit"));
  CHECK_THROWS_WITH(generateSkeleton(huge, GrowthOptions{}), Catch::Contains("SegSplits"));
}

TEST_CASE("the node limit holds while clones and pruning walks are made, not after", "[skeleton][limits]") {
  SpeciesParams p = test::steadySpecies();
  p.shape = 8;
  p.pruneRatio = 1;
  p.pruneWidth = 0.3;
  p.leaves = 0;
  for (auto& lp : p.stemLevels) {
    lp.segSplits = 0.5;
    lp.curveRes = 8;
  }
  GrowthOptions unlimited;
  unlimited.limits.nodes = 100'000'000;
  const std::size_t grown = skeletonStats(generateSkeleton(p, unlimited)).nodes;
  GrowthOptions o;
  o.limits.nodes = grown / 2;
  REQUIRE(estimateTree(p).excess(o.limits, 16.0).empty());  // so the limit is met while growing, not from the estimate
  CHECK_THROWS_WITH(generateSkeleton(p, o), Catch::Contains("more than " + std::to_string(grown / 2) + " nodes") &&
                                                Catch::Contains("on level"));
}

TEST_CASE("Arbaro's species files grow the stems per level Arbaro 1.9.9 grows, within 15 %", "[skeleton][real-data][arbaro]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  const auto reference = nlohmann::json::parse(readFile(std::string(TEST_DATA_DIR) + "/arbaro-1.9.9-reference.json"));
  int compared = 0, sizeless = 0;
  for (const auto& tree : reference["trees"]) {
    const std::string file = tree["file"];
    const int seed = tree["seed"];
    INFO(file << " seed " << seed);
    GrowthOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    const Skeleton s = generateSkeleton(loadSpeciesFile(std::string(ARBOR_SPECIES_DIR) + "/" + file), o);
    // Counted as Arbaro counts: a split stem goes on as one of its clones there, so it is one stem fewer.
    std::vector<double> ours(static_cast<std::size_t>(s.levels), 0.0);
    for (const SkeletonStem& st : s.stems) {
      const bool split = s.nodes[static_cast<std::size_t>(st.firstNode + st.nodeCount - 1)].kind == NodeKind::Split;
      ours[static_cast<std::size_t>(st.level)] += split ? 0.0 : 1.0;
    }
    const auto& theirs = tree["stemsPerLevel"];
    REQUIRE(theirs.size() == ours.size());
    // Arbaro drew a tree size below zero (shave-grass: Scale 0.5 ± ScaleV 0.7) and grew only an empty trunk;
    // Arbor keeps every tree at 5 % of Scale or more, so only the trunks compare.
    const std::size_t levels = tree["width"].is_null() ? 1 : ours.size();
    sizeless += tree["width"].is_null() ? 1 : 0;
    for (std::size_t l = 0; l < levels; ++l) {
      INFO("level " << l << ": Arbor " << ours[l] << ", Arbaro " << theirs[l].get<double>());
      CHECK(std::abs(ours[l] - theirs[l].get<double>()) <= 0.15 * theirs[l].get<double>());
    }
    ++compared;
  }
  CHECK(compared == 3 * 16);
  CHECK(sizeless == 1);
}

namespace {

// Level-0 stems as Arbaro counts them: a split stem goes on as one of its clones there.
int arbaroTrunks(const Skeleton& s) {
  int trunks = 0;
  for (const SkeletonStem& st : s.stems) {
    const bool split = s.nodes[static_cast<std::size_t>(st.firstNode + st.nodeCount - 1)].kind == NodeKind::Split;
    trunks += st.level == 0 && !split ? 1 : 0;
  }
  return trunks;
}

// Height and width as Arbaro's Tree.getHeight and getWidth take them: the highest point, and the farther of
// the bounding box's two horizontal corners (min x, min y) and (max x, max y) from the trunk axis.
double arbaroHeightToWidth(const Skeleton& s) {
  double lo[2] = {0, 0}, hi[2] = {0, 0}, height = 0;
  for (const SkeletonNode& n : s.nodes) {
    lo[0] = std::min(lo[0], n.world.position.x), hi[0] = std::max(hi[0], n.world.position.x);
    lo[1] = std::min(lo[1], n.world.position.y), hi[1] = std::max(hi[1], n.world.position.y);
    height = std::max(height, n.world.position.z);
  }
  return height / std::sqrt(std::max(lo[0] * lo[0] + lo[1] * lo[1], hi[0] * hi[0] + hi[1] * hi[1]));
}

}  // namespace

TEST_CASE("every preset has its Arbaro file's trunks and height to width within 15 %", "[skeleton][arbaro]") {
  const std::map<std::string, std::string> arbaroFile = {
      {"black-tupelo", "black_tupelo.xml"}, {"ca-black-oak", "ca_black_oak.xml"}, {"lombardy-poplar", "lombardy_poplar.xml"},
      {"palm", "palm.xml"}, {"quaking-aspen", "quaking_aspen.xml"}, {"weeping-willow", "weeping_willow.xml"}};
  const auto reference = nlohmann::json::parse(readFile(std::string(TEST_DATA_DIR) + "/arbaro-1.9.9-reference.json"));
  const std::vector<std::string> presets = test::presetNames();
  CHECK(presets.size() == arbaroFile.size());
  for (const std::string& preset : presets) {
    INFO(preset);
    REQUIRE(arbaroFile.count(preset) == 1);
    const SpeciesParams p = test::loadPreset(preset);
    // Arbaro's height to width averaged over seeds 1 to 3 (its trees of one file vary in size, less in shape).
    std::map<int, int> theirTrunks;
    double theirRatio = 0;
    for (const auto& tree : reference["trees"]) {
      if (tree["file"] != arbaroFile.at(preset)) continue;
      theirTrunks[tree["seed"].get<int>()] = tree["stemsPerLevel"][0].get<int>();
      theirRatio += tree["height"].get<double>() / tree["width"].get<double>() / 3.0;
    }
    REQUIRE(theirTrunks.size() == 3);
    for (int seed = 1; seed <= 3; ++seed) {
      const Skeleton s = grow(p, static_cast<std::uint64_t>(seed));
      const double ours = arbaroHeightToWidth(s);
      INFO("seed " << seed << ": height to width " << ours << ", Arbaro's " << theirRatio);
      CHECK(arbaroTrunks(s) == theirTrunks.at(seed));
      CHECK(std::abs(ours / theirRatio - 1.0) <= 0.15);
    }
  }
}
