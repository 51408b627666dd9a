// Joints where the skeleton puts them: every child's first ring within 1.5 parent radii of its attachment
// along the parent, and no stem's tip ring past its skeleton tip by more than the tip radius.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "growth/weber_penn.hpp"
#include "mesh/joint_checks.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/stem_polyline.hpp"
#include "mesh/tree_mesh.hpp"
#include "species/species_io.hpp"
#include "test_support.hpp"

using namespace arbor;

namespace {

struct JointStats {
  std::size_t children = 0, before = 0, far = 0, tips = 0, past = 0;
  double worstOffset = 0, worstPast = 0;  // worstPast in stem lengths
};

// Children attached before their parent's tube begins (inside or against the grandparent, where the parent
// has no surface) join its first slab and are counted apart; every other child is held to 1.5 parent radii.
JointStats jointStats(const SpeciesParams& p, std::uint64_t seed) {
  GrowthOptions o;
  o.seed = seed;
  const Skeleton s = generateSkeleton(p, o);
  const TreeMesh tree = buildTreeMesh(s);
  JointStats j;
  for (const ChildPlacement& c : childPlacements(s, tree)) {
    ++j.children;
    if (c.beforeTube) {
      ++j.before;
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
  std::snprintf(line, sizeof line, "%s seed %llu: %zu children (%zu before the tube), %zu beyond 1.5 radii (worst %.2f); %zu tips, %zu past (worst %.3f lengths)",
                name.c_str(), static_cast<unsigned long long>(seed), j.children, j.before, j.far, j.worstOffset, j.tips, j.past, j.worstPast);
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
    }
  }
}

TEST_CASE("every Arbaro species file's children connect at their attachment and no stem outgrows its skeleton", "[mesh][joints][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) {
    WARN("Arbaro's species files are not beside this checkout (" << ARBOR_SPECIES_DIR << "); skipped");
    return;
  }
  for (const std::string& file : files) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const JointStats j = jointStats(loadSpeciesFile(file), seed);
      INFO(describe(file, seed, j));
      CHECK(j.past == 0);
      // Known limit (docs/mesh.md): a child leaving a sub-box of a crowded slab can sit up to 2.6 parent radii
      // along (1 to 3 children per tree on 4 of the 16 files, 1 in 470 at most); anything more is a regression.
      CHECK(j.far * 400 <= j.children);
      CHECK(j.worstOffset < 3.0);
    }
  }
}

TEST_CASE("measure: where offsets happen", "[.measure-why]") {
  const char* which = std::getenv("ARBOR_PRESET");
  const std::string w = which ? which : "quaking-aspen";
  const SpeciesParams p = w.find('/') != std::string::npos ? loadSpeciesFile(w) : test::loadPreset(w);
  GrowthOptions o;
  o.seed = 1;
  const Skeleton s = generateSkeleton(p, o);
  const TreeMesh tree = buildTreeMesh(s);
  std::vector<int> firstRing(s.stems.size(), -1);
  for (std::size_t i = 0; i < tree.rings.size(); ++i)
    if (tree.rings[i].stem >= 0 && firstRing[static_cast<std::size_t>(tree.rings[i].stem)] < 0) firstRing[static_cast<std::size_t>(tree.rings[i].stem)] = static_cast<int>(i);
  for (const ChildPlacement& c : childPlacements(s, tree)) {
    if (c.offset <= 1.5 && !(c.beforeTube && std::getenv("ARBOR_BEFORE"))) continue;
    const SkeletonStem& parent = s.stems[static_cast<std::size_t>(c.parentStem)];
    const int fr = firstRing[static_cast<std::size_t>(c.parentStem)];
    const double tubeStart = parent.parentStem < 0 ? 0.0 : glm::distance(tree.rings[static_cast<std::size_t>(fr + 1)].center, s.nodes[static_cast<std::size_t>(parent.attachNode)].world.position);
    if (c.beforeTube) continue;
    std::printf("child %d level %d parent %d: offset %.2f radii, attach at %.3f (%.2f radii), parent tube from %.3f (%.2f radii), parent length %.3f\n", c.stem,
                s.stems[static_cast<std::size_t>(c.stem)].level, c.parentStem, c.offset, c.attachArc, c.attachArc / c.parentRadius, tubeStart,
                tubeStart / c.parentRadius, parent.length);
  }
}

TEST_CASE("measure: where the mesh-made crossings are", "[.measure-cross]") {
  const char* which = std::getenv("ARBOR_PRESET");
  const std::string w = which ? which : "quaking-aspen";
  const SpeciesParams p = w.find('/') != std::string::npos ? loadSpeciesFile(w) : test::loadPreset(w);
  GrowthOptions o;
  o.seed = 1;
  const Skeleton s = generateSkeleton(p, o);
  const TreeMesh tree = buildTreeMesh(s);
  std::map<int, std::uint32_t> firstQuad;
  for (std::uint32_t f = 0; f < tree.quadStem.size(); ++f) firstQuad.emplace(tree.quadStem[f], f);
  std::vector<bool> moved(s.stems.size(), false);
  for (const ChildPlacement& c : childPlacements(s, tree)) moved[static_cast<std::size_t>(c.stem)] = c.beforeTube;
  std::map<std::string, int> hist;
  const SelfIntersectionReport r = checkSelfIntersections(tree, s);
  for (const QuadPairHit& h : r.hits) {
    if (h.origin != PairOrigin::Mesh) continue;
    auto band = [&](std::uint32_t q, int stem) {
      if (stem < 0) return std::string("hub");
      const std::uint32_t b = (q - firstQuad[stem]) / 4;
      return std::string(moved[static_cast<std::size_t>(stem)] ? "moved:" : "") + (b == 0 ? "neck" : b == 1 ? "band1" : b == 2 ? "band2" : "later");
    };
    std::string a = band(h.a, h.stemA), b = band(h.b, h.stemB);
    if (b < a) std::swap(a, b);
    std::string gapClass = "";
    if (std::getenv("ARBOR_GAP") && h.stemA >= 0 && h.stemB >= 0) {
      const StemPolyline pa(s, h.stemA), pb(s, h.stemB);
      double best = 1e30;
      for (int i = 0; i <= 60; ++i)
        for (int k = 0; k <= 60; ++k) {
          const double sa = pa.length() * i / 60.0, sb = pb.length() * k / 60.0;
          best = std::min(best, glm::distance(pa.position(sa), pb.position(sb)) / (pa.radius(sa) + pb.radius(sb) + 1e-12));
        }
      gapClass = best < 1 ? " gap<1" : best < 2 ? " gap1-2" : best < 4 ? " gap2-4" : " gap>4";
    }
    ++hist[std::string(stemRelationName(h.relation)) + " " + a + " x " + b + gapClass];
    if (std::getenv("ARBOR_SHOW") && (a + " x " + b) == std::getenv("ARBOR_SHOW")) {
      auto info = [&](int stem) {
        const SkeletonStem& st = s.stems[static_cast<std::size_t>(stem)];
        return "stem " + std::to_string(stem) + " L" + std::to_string(st.level) + " parent " + std::to_string(st.parentStem) + " at " + std::to_string(st.offsetOnParent);
      };
      const auto dirOf = [&](int stem) { const SkeletonStem& st = s.stems[static_cast<std::size_t>(stem)]; return glm::normalize(s.nodes[static_cast<std::size_t>(st.firstNode)].world.position - s.nodes[static_cast<std::size_t>(st.attachNode)].world.position); };
      const double angle = std::acos(std::clamp(glm::dot(dirOf(h.stemA), dirOf(h.stemB)), -1.0, 1.0)) * 57.3;
      std::printf("   %u (%s) x %u (%s) at (%.3f %.3f %.3f) angle %.0f\n", h.a, info(h.stemA).c_str(), h.b, info(h.stemB).c_str(), h.point.x, h.point.y, h.point.z, angle);
    }
  }
  for (const auto& [k, n] : hist) std::printf("%6d  %s\n", n, k.c_str());
}
