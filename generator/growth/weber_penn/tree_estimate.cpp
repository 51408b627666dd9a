// The estimate grows a handful of sample stems per level instead of the whole tree: each sample stands for
// many stems (its weight) and meets the same rules as real ones (whole child counts and lengths, children
// shared among the pieces of a split stem, da Vinci radii stepped down at every child and clone split, the
// rule that leaves children of no length out). Pruning and random variations are left out.
#include "tree_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/text_util.hpp"
#include "natural_rules.hpp"
#include "weber_penn_rules.hpp"

namespace arbor {

namespace {

constexpr std::size_t kSamplesPerLevel = 48;

struct Sample {
  double weight = 1;        // stems it stands for (units: a stem with its clones)
  double length = 0;
  double natural = 0;       // natural radius where it starts
  double offset = 0;        // on its parent
  double parentLength = 0, parentLengthChildMax = 0;
};

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, x < 1e6 ? "%.0f" : "%.2g", x);
  return buf;
}

// Consecutive samples along their parents merge into one carrying their weight, so each level keeps a few.
std::vector<Sample> thin(std::vector<Sample> samples) {
  if (samples.size() <= kSamplesPerLevel) return samples;
  std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) {
    return a.offset / std::max(a.parentLength, 1e-12) < b.offset / std::max(b.parentLength, 1e-12);
  });
  std::vector<Sample> out;
  const std::size_t per = (samples.size() + kSamplesPerLevel - 1) / kSamplesPerLevel;
  for (std::size_t i = 0; i < samples.size(); i += per) {
    Sample merged{0, 0, 0, 0, 0, 0};
    const std::size_t end = std::min(samples.size(), i + per);
    for (std::size_t k = i; k < end; ++k) merged.weight += samples[k].weight;
    if (merged.weight <= 0.0) continue;
    for (std::size_t k = i; k < end; ++k) {
      const double f = samples[k].weight / merged.weight;
      merged.length += f * samples[k].length;
      merged.natural += f * samples[k].natural;
      merged.offset += f * samples[k].offset;
      merged.parentLength += f * samples[k].parentLength;
      merged.parentLengthChildMax += f * samples[k].parentLengthChildMax;
    }
    out.push_back(merged);
  }
  return out;
}

}  // namespace

TreeEstimate estimateTree(const SpeciesParams& p, int levels) {
  TreeEstimate e;
  const int n = levels > 0 ? levels : p.levels;
  const double E = p.treeShapeExponent;
  const double scale = p.scale, baseLength = p.baseSize * scale;
  const StemLevelParams& trunk = p.level(0);
  Sample first;
  first.weight = trunk.branches;
  first.length = std::max(1e-6, trunk.length * scale);
  first.natural = first.length * p.ratio * p.trunkScale;
  std::vector<Sample> samples{first};
  double worstStems = -1.0;

  for (int level = 0; level < n && !samples.empty(); ++level) {
    const StemLevelParams& lp = p.level(level);
    const int segments = std::max(1, lp.curveRes);
    // Pieces covering each segment: every joint but the tip splits a piece into 1 + splits (BaseSplits at the
    // trunk's first joint); the last count is the number of stems a unit ends in. The level's split error is
    // shared by all its pieces, so on average each piece splits SegSplits times at each joint.
    std::vector<double> pieces(static_cast<std::size_t>(segments), 1.0), splits(static_cast<std::size_t>(segments), 0.0);
    // A split ends its stem and starts 1 + splits clones: the stems of a unit are its first and every clone.
    double stemsPerUnit = 1.0;
    for (int j = 1; j < segments; ++j) {
      const auto u = static_cast<std::size_t>(j);
      splits[u] = level == 0 && j == 1 && p.baseSplits > 0 ? p.baseSplits : std::max(0.0, lp.segSplits);
      pieces[u] = pieces[u - 1] * (1.0 + splits[u]);
      const double events = pieces[u - 1] * std::min(1.0, splits[u]);  // pieces that split here
      stemsPerUnit += pieces[u] - pieces[u - 1] + events;
    }
    double segmentPieces = 0.0;
    for (double m : pieces) segmentPieces += m;
    double units = 0.0;
    for (const Sample& s : samples) units += s.weight;
    const double stems = units * stemsPerUnit;
    e.stemsPerLevel.push_back(stems);
    e.nodesPerLevel.push_back(units * (segmentPieces + 1.0));
    e.stems += stems;
    e.nodes += e.nodesPerLevel.back();
    if (stems > worstStems) {
      worstStems = stems;
      e.drivers = "level " + std::to_string(level) + ": about " + number(stems) + " stems from Branches " + formatNumber(lp.branches);
      if (lp.segSplits > 0.0) e.drivers += ", SegSplits " + formatNumber(lp.segSplits) + " over CurveRes " + std::to_string(lp.curveRes);
      if (level == 0 && p.baseSplits > 0) e.drivers += ", BaseSplits " + std::to_string(p.baseSplits);
    }

    if (level + 1 == n) {  // the deepest level carries the leaves
      if (level == 0 || p.leaves == 0.0) break;
      for (const Sample& s : samples) {
        const double count = wp::leafCount(p, s.offset, s.parentLength);
        e.leaves += s.weight * (p.leaves < 0.0 ? count * pieces.back() : count * segmentPieces / segments);
      }
      break;
    }

    const StemLevelParams& next = p.level(level + 1);
    const double S = p.branchRatio(level + 1);
    const double Cp = natural::primaryRadiusFactor(S, E), Cs = natural::secondaryRadiusFactor(S, E);
    std::vector<Sample> children;
    for (const Sample& s : samples) {
      double count = next.branches;
      if (level == 1) count = std::floor(wp::childCountOfLevel1(next.branches, s.length, s.parentLength, s.parentLengthChildMax));
      if (level >= 2) count = std::floor(wp::childCountOfDeeper(next.branches, s.offset, s.parentLength));
      const double seg = s.length / segments;
      std::vector<double> cover(static_cast<std::size_t>(segments));
      double covered = 0.0;
      for (int j = 0; j < segments; ++j) {
        const double a = level == 0 ? std::max(j * seg, baseLength) : j * seg;
        cover[static_cast<std::size_t>(j)] = std::max(0.0, (j + 1) * seg - a) / seg;
        covered += cover[static_cast<std::size_t>(j)];
      }
      if (covered <= 0.0 || count <= 0.0) continue;
      double natural = s.natural;
      for (int j = 0; j < segments; ++j) {
        const auto u = static_cast<std::size_t>(j);
        if (splits[u] > 0.0) natural *= std::pow(1.0 + splits[u], -1.0 / E);  // clones share their source's wood
        const double expected = count / covered * cover[u];
        if (expected <= 0.0) continue;
        const int slots = static_cast<int>(std::ceil(std::min(expected, 64.0)));
        const double share = expected / slots;  // each slot stands for this many children per unit
        const double a = (j + 1 - cover[u]) * seg;
        for (int k = 0; k < slots; ++k) {
          const double z = a + (k + 0.5) / slots * cover[u] * seg;
          const double incoming = natural * (level == 0 ? wp::flareFactor(p.flare, z / s.length) : 1.0);
          const double radius = Cs * incoming;
          const double length = level == 0 ? wp::childLengthOfTrunk(p, next.length, s.length, baseLength, z)
                                           : wp::childLengthOfDeeper(next.length, s.length, z);
          if (!wp::childGrows(length, radius)) continue;
          children.push_back(Sample{s.weight * share, length, radius, z, s.length, next.length});
          natural *= std::pow(Cp, share / pieces[u]);  // each piece carries its share of the unit's children
        }
      }
    }
    double grown = 0.0;
    for (const Sample& c : children) grown += c.weight;
    e.nodes += 3.0 * grown;  // the attachment and the two nodes around it (Nystad's 10 % rule)
    samples = thin(std::move(children));
  }
  e.quads = kQuadsPerNode * e.nodes;
  e.lowerNodes = "lower Levels, Branches, SegSplits or CurveRes";
  e.lowerLeaves = "lower Leaves or LeafQuality, or the stems of the deepest level (" + e.drivers + ")";
  return e;
}

}  // namespace arbor
