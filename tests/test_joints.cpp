// Joints where the skeleton puts them: every child's first ring within 1.5 parent radii of its attachment
// along the parent, and no stem's tip ring past its skeleton tip by more than the tip radius.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/connection.hpp"
#include "mesh/joint_checks.hpp"
#include "mesh/tree_mesh.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "test_support.hpp"

using namespace arbor;

namespace {

struct JointStats {
  std::size_t children = 0, before = 0, far = 0, tips = 0, past = 0;
  // Twigs (no meshed child, nor their clones), and branches two levels or more from the trunk bearing only twigs,
  // attached before the tube and past 1.5 radii.
  std::size_t beforeFarTwigs = 0;
  double worstOffset = 0, worstPast = 0;  // worstPast in stem lengths
  double worstOnTrunkClone = 0;  // of the limbs attached before a trunk clone's tube begins
  double worstBefore = 0;        // of every child attached before its parent's tube begins
};

// Children attached before their parent's tube begins (inside or against the grandparent, where the parent
// has no surface) join its first slab and are counted apart; every other child is held to 1.5 parent radii.
JointStats jointStats(const SpeciesParams& p, std::uint64_t seed, const MeshOptions& options = {}) {
  GrowthOptions o;
  o.seed = seed;
  const Skeleton s = generateSkeleton(p, o);
  const TreeMesh tree = buildTreeMesh(s, options);
  JointStats j;
  const std::vector<ChildPlacement> placements = childPlacements(s, tree);
  // A stem with a meshed child, and every stem it is a clone of, is a branch; the rest are twigs. A branch with a
  // meshed child that is a branch (through its clones too) bears more than twigs.
  std::vector<bool> branching(s.stems.size(), false), deep(s.stems.size(), false);
  auto mark = [&](std::vector<bool>& flag, int from) {
    for (int x = from; x >= 0 && !flag[static_cast<std::size_t>(x)]; x = s.stems[static_cast<std::size_t>(x)].cloneOf) flag[static_cast<std::size_t>(x)] = true;
  };
  for (const ChildPlacement& c : placements) mark(branching, c.parentStem);
  for (const ChildPlacement& c : placements)
    if (branching[static_cast<std::size_t>(c.stem)]) mark(deep, c.parentStem);
  // What the mesher fakes when it cannot join it near its attachment: a twig, or a branch two or more levels from
  // its trunk that bears only twigs.
  auto fakeable = [&](int stem) {
    const auto i = static_cast<std::size_t>(stem);
    return !branching[i] || (s.stems[i].level >= 2 && !deep[i]);
  };
  for (const ChildPlacement& c : placements) {
    ++j.children;
    if (c.beforeTube) {
      ++j.before;
      j.beforeFarTwigs += c.offset > 1.5 && fakeable(c.stem) ? 1 : 0;
      j.worstBefore = std::max(j.worstBefore, c.offset);
      const SkeletonStem& parent = s.stems[static_cast<std::size_t>(c.parentStem)];
      if (parent.cloneOf >= 0 && parent.level == 0) j.worstOnTrunkClone = std::max(j.worstOnTrunkClone, c.offset);
      continue;
    }
    j.worstOffset = std::max(j.worstOffset, c.offset);
    j.far += c.offset > 1.5 ? 1 : 0;
  }
  for (const TipOvershoot& t : tipOvershoots(s, tree)) {
    ++j.tips;
    // A tip ring may sit a hair past a skeleton tapering to nothing, on stems so short that their collar
    // nearly reaches the tip: half a percent of the stem, or a tenth of its start radius, at most.
    if (t.beyond > std::max({t.tipRadius, 5e-3 * t.length, 0.1 * t.startRadius})) {
      ++j.past;
      j.worstPast = std::max(j.worstPast, t.beyond / std::max(t.length, 1e-12));
    }
  }
  return j;
}

std::string describe(const std::string& name, std::uint64_t seed, const JointStats& j) {
  char line[300];
  std::snprintf(line, sizeof line, "%s seed %llu: %zu children (%zu before the tube, worst %.2f, %zu of them fakeable beyond 1.5 radii), %zu beyond 1.5 radii (worst %.2f); %zu tips, %zu past (worst %.3f lengths)",
                name.c_str(), static_cast<unsigned long long>(seed), j.children, j.before, j.worstBefore, j.beforeFarTwigs, j.far, j.worstOffset, j.tips, j.past, j.worstPast);
  return line;
}

}  // namespace

TEST_CASE("every preset's children connect within 1.5 parent radii of their attachment and no stem outgrows its skeleton", "[mesh][joints]") {
  for (const std::string& name : test::presetNames()) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const JointStats j = jointStats(test::loadPreset(name), seed);
      INFO(describe(name, seed, j));
      CHECK(j.children > 0);
      CHECK(j.far == 0);
      CHECK(j.past == 0);
      // Measured 2026-12-02: 0 (palm) to 14 % (Lombardy poplar) attach before their parent's tube begins.
      CHECK(j.before * 100 <= j.children * 16);
      // A twig (or a twig-bearing branch off a limb) the first slab would hold more than half a parent radius from its
      // attachment is a fake branch instead: what is left so far along is a trunk's limb.
      CHECK(j.beforeFarTwigs == 0);
      // Children attached before their parent's tube too: the willow's limb on its trunk clone at seed 3 was 1.69
      // clone radii along (the clone's collar 0.67 m off its skeleton) until its inset stood at the place in the
      // slab's side nearest along the clone; 2.59 before that clone's first slab started at its collar.
      CHECK(j.worstBefore <= 1.5);
    }
  }
}

TEST_CASE("a trunk clone bearing a limb near its split has its collar nearer its port: the limb's slab is at its attachment", "[mesh][joints]") {
  // The CA black oak preset splits its trunk in three, and each clone bears a limb 3.2 of its radii past the split,
  // before its tube begins: with the collar where any clone's stands, that limb's slab (the clone's first) sat 2.6
  // clone radii along from it at every seed.
  MeshOptions usual;
  usual.nearEarlyCloneCollars = false;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const JointStats near = jointStats(test::loadPreset("ca-black-oak"), seed), far = jointStats(test::loadPreset("ca-black-oak"), seed, usual);
    INFO(describe("ca-black-oak", seed, near) << "; " << describe("usual collars", seed, far));
    CHECK(near.worstOnTrunkClone <= 1.5);
    CHECK(near.worstBefore <= 1.5);
    CHECK(far.worstOnTrunkClone > 2.0);
  }
}

TEST_CASE("children heading straight for a corner of their parent take its two sides in turn", "[mesh][joints]") {
  // A cross section with corners on +x, +y, -x, -y: side k lies between corners k and k + 1.
  const double h = std::sqrt(0.5);
  const std::array<Vec3, 4> normals{Vec3(h, h, 0), Vec3(-h, h, 0), Vec3(-h, -h, 0), Vec3(h, -h, 0)};
  const Vec3 axis(0, 0, 1);
  const std::array<bool, 4> all{true, true, true, true};
  auto sideOf = [&](const Vec3& direction, CornerTurns* turns, const std::array<bool, 4>& allowed) {
    const PortAssignment a = assignPorts(normals, axis, {PortRequest{glm::normalize(direction), 0.1}}, allowed, false, turns);
    for (int k = 0; k < 4; ++k)
      if (!a.sides[static_cast<std::size_t>(k)].empty()) return k;
    return -1;
  };
  const Vec3 towardsMinusX(-0.342, 0, 0.94);  // a planar plant's limbs, each a slab of its own
  CornerTurns turns = kNoCornerTurns;
  CHECK(sideOf(towardsMinusX, &turns, all) == 1);
  CHECK(turns[2] == 1);
  CHECK(sideOf(towardsMinusX, &turns, all) == 2);
  CHECK(sideOf(towardsMinusX, &turns, all) == 1);
  // Without the parent's record, always the first of the two.
  CHECK(sideOf(towardsMinusX, nullptr, all) == 1);
  CHECK(sideOf(towardsMinusX, nullptr, all) == 1);
  // A child a little off the corner takes its side and leaves the record as it was.
  CornerTurns off = kNoCornerTurns;
  CHECK(sideOf(Vec3(-0.342, -0.01, 0.94), &off, all) == 2);
  CHECK(off == kNoCornerTurns);
  // The other side not allowed (its corners in two ports already): the first, whatever the record says.
  CornerTurns blocked{-1, -1, 1, -1};
  CHECK(sideOf(towardsMinusX, &blocked, {true, true, false, true}) == 1);
}

TEST_CASE("every Arbaro species file's children connect at their attachment and no stem outgrows its skeleton", "[mesh][joints][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  for (const std::string& file : files) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const JointStats j = jointStats(loadSpeciesFile(file), seed);
      INFO(describe(file, seed, j));
      CHECK(j.past == 0);
      // Every child attached where its parent has its tube sits within the floor (a child leaving a sub-box of a
      // crowded slab sat up to 2.6 parent radii along on 4 of the 16 files until 2026-12-04).
      CHECK(j.far == 0);
      CHECK(j.worstOffset <= 1.5);
      // Twigs (and twig-bearing branches off limbs) attached before their parent's tube: faked where their slab lies
      // more than half a parent radius away, and where a pass left their first ring past 1.5 radii anyway (a neck
      // port or a crowded sub-box: 0 to 2 per tree on the aspen and cottonwood files before that rule).
      CHECK(j.beforeFarTwigs == 0);
      // A trunk clone split off at a few degrees (the willow file's, at 3) begins its tube where it has passed its
      // first cross section, not metres up where it clears its source's axis: its limbs leave up to 4 of its radii
      // from their attachment, not 7.9 (and the CA black oak file's 1.9, not 4.9).
      CHECK(j.worstOnTrunkClone < 4.5);
      // Every child attached before its parent's tube begins within 1.5 too. Limb 287 on the willow file's trunk
      // clone 4 was 1.72 clone radii along at seeds 1 and 2 until that clone's slab for it started at the collar and
      // its inset stood where the slab's side is nearest its attachment, and 1.62 at seed 3 (2.58 before) until the
      // inset stood at the place in the side nearest along the clone.
      CHECK(j.worstBefore <= 1.5);
    }
  }
}
