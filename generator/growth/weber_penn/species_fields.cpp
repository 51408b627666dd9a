#include "species_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace arbor {

namespace {

using S = SpeciesParams;
using L = StemLevelParams;

constexpr double kNone = 0.0;

// Order here is the order of the written JSON and of the documentation.
const std::array kTreeFields = {
    TreeField{"Name", nullptr, FieldType::Text, 0, 0, true, kNone, "Species name shown in summaries: 1 to 200 bytes of printable UTF-8."},
    TreeField{"Shape", "Shape", FieldType::Integer, 0, 8, true, kNone,
              "Crown shape for level-1 lengths: 0 conical, 1 spherical, 2 hemispherical, 3 cylindrical, "
              "4 tapered cylindrical, 5 flame, 6 inverse conical, 7 tend flame, 8 pruning envelope.",
              nullptr, &S::shape},
    TreeField{"Levels", "Levels", FieldType::Integer, 1, 6, true, kNone,
              "Stem levels including the trunk; leaves grow on the deepest level.", nullptr, &S::levels},
    TreeField{"Scale", "Scale", FieldType::Real, 0.01, 1000, true, kNone, "Tree size in metres.", &S::scale},
    TreeField{"ScaleV", "ScaleV", FieldType::Real, 0, 1000, true, kNone,
              "Random variation of Scale; a drawn size never falls below 5 % of Scale.", &S::scaleV},
    TreeField{"BaseSize", "BaseSize", FieldType::Real, 0, 0.99, true, kNone,
              "Bare fraction of the trunk below the first branch.", &S::baseSize},
    TreeField{"BaseSplits", "0BaseSplits", FieldType::Integer, 0, 10, false, 0,
              "Clone splits at the end of the first trunk segment.", nullptr, &S::baseSplits},
    TreeField{"Ratio", "Ratio", FieldType::Real, 0.0001, 0.5, true, kNone,
              "Trunk base radius relative to the trunk length.", &S::ratio},
    TreeField{"RatioPower", "RatioPower", FieldType::Real, 0, 5, true, kNone,
              "Weber-Penn radius reduction; derives BranchRatio where a level does not give one.",
              &S::ratioPower},
    TreeField{"Flare", "Flare", FieldType::Real, 0, 10, true, kNone,
              "Trunk base widening: radius * (1 + Flare (100^y - 1) / 100), y = max(0, 1 - 8 z).", &S::flare},
    TreeField{"Lobes", "Lobes", FieldType::Integer, 0, 32, false, 0,
              "Lobes around the trunk (applied by the renderer's displacement).", nullptr, &S::lobes},
    TreeField{"LobeDepth", "LobeDepth", FieldType::Real, 0, 1, false, 0,
              "Relative depth of the trunk lobes.", &S::lobeDepth},
    TreeField{"AttractionUp", "AttractionUp", FieldType::Real, -10, 10, true, kNone,
              "Bend of level >= 2 stems towards the sky (negative: towards the ground).", &S::attractionUp},
    TreeField{"TreeShapeExponent", nullptr, FieldType::Real, 1.5, 4, false, 2.49,
              "E of the natural rules: r^E = r_p^E + r_s^E at every branch point.", &S::treeShapeExponent},
    TreeField{"AngleRule", nullptr, FieldType::AngleRule, 0, 0, false, kNone,
              "\"natural\": deviation angles from Murray's equilibrium; \"classic\": DownAngle and "
              "SplitAngle from this file (the default of an Arbaro XML import)."},
    TreeField{"TrunkScale", "0Scale", FieldType::Real, 0.01, 100, false, 1,
              "Extra scale of the trunk radius.", &S::trunkScale},
    TreeField{"TrunkScaleV", "0ScaleV", FieldType::Real, 0, 100, false, 0,
              "Random variation of TrunkScale; a drawn value never falls below 5 % of TrunkScale.", &S::trunkScaleV},
    TreeField{"PruneRatio", "PruneRatio", FieldType::Real, 0, 1, false, 0,
              "0: no pruning; 1: stems are shortened until they fit the envelope.", &S::pruneRatio},
    TreeField{"PruneWidth", "PruneWidth", FieldType::Real, 0.01, 10, false, 0.5,
              "Envelope width relative to the tree height.", &S::pruneWidth},
    TreeField{"PruneWidthPeak", "PruneWidthPeak", FieldType::Real, 0, 1, false, 0.5,
              "Relative height of the envelope's widest point.", &S::pruneWidthPeak},
    TreeField{"PrunePowerLow", "PrunePowerLow", FieldType::Real, 0, 10, false, 0.5,
              "Envelope curvature below the peak.", &S::prunePowerLow},
    TreeField{"PrunePowerHigh", "PrunePowerHigh", FieldType::Real, 0, 10, false, 0.5,
              "Envelope curvature above the peak.", &S::prunePowerHigh},
    TreeField{"Leaves", "Leaves", FieldType::Real, -1000, 1000, true, kNone,
              "Leaves per deepest-level stem; negative: a fan of |Leaves| at the stem tip.", &S::leaves},
    TreeField{"LeafShape", "LeafShape", FieldType::LeafShape, 0, 0, false, kNone,
              "Leaf kind in the atlas: \"broad\", \"narrow\", \"frond\" or \"needle\"."},
    TreeField{"LeafScale", "LeafScale", FieldType::Real, 0.0001, 100, true, kNone, "Leaf length in metres.",
              &S::leafScale},
    TreeField{"LeafScaleX", "LeafScaleX", FieldType::Real, 0.01, 10, true, kNone,
              "Leaf width relative to its length.", &S::leafScaleX},
    TreeField{"LeafQuality", "LeafQuality", FieldType::Real, 0.01, 100, false, 1,
              "Leaf density: Q times as many leaves, each 1/sqrt(Q) as large.", &S::leafQuality},
    TreeField{"LeafStemLen", "LeafStemLen", FieldType::Real, -20, 20, false, 0,
              "Petiole length relative to the leaf length; negative moves the blade back along itself "
              "(Arbaro's grasses).",
              &S::leafStemLen},
    TreeField{"LeafBend", "LeafBend", FieldType::Real, 0, 1, false, 0,
              "How far leaf faces turn towards the sky.", &S::leafBend},
    TreeField{"LeafDistrib", "LeafDistrib", FieldType::Integer, 0, 8, false, 4,
              "Shape ratio (as Shape) that spreads leaves along their parent.", nullptr, &S::leafDistrib},
    TreeField{"LeafDownAngle", nullptr, FieldType::Real, -180, 180, false, 45,
              "Angle between a leaf and its stem; Arbaro files give it as <Levels>DownAngle.",
              &S::leafDownAngle},
    TreeField{"LeafDownAngleV", nullptr, FieldType::Real, -180, 180, false, 0,
              "Variation of LeafDownAngle (negative: varies along the stem).", &S::leafDownAngleV},
    TreeField{"LeafRotate", nullptr, FieldType::Real, -360, 360, false, 137.5,
              "Azimuth step between successive leaves (negative alternates sides).", &S::leafRotate},
    TreeField{"LeafRotateV", nullptr, FieldType::Real, 0, 360, false, 0, "Variation of LeafRotate.",
              &S::leafRotateV},
};

const std::array kLevelFields = {
    LevelField{"Branches", FieldType::Real, 0, 1000, true,
               "Children per parent stem (level 0: number of trunks, 1 to 64).", &L::branches},
    LevelField{"Length", FieldType::Real, 0, 50, true,
               "Length relative to the parent (level 0: relative to Scale).", &L::length},
    LevelField{"LengthV", FieldType::Real, 0, 50, true, "Random variation of Length.", &L::lengthV},
    LevelField{"Taper", FieldType::Real, 0, 3, true,
               "0 cylinder, 1 cone, 1..2 rounded tip, 2 hemispherical tip, >2 periodic spheres.", &L::taper},
    LevelField{"SegSplits", FieldType::Real, 0, 2, true,
               "Clone splits per segment joint; fractions carry to the next joint.", &L::segSplits},
    LevelField{"SplitAngle", FieldType::Real, 0, 180, true,
               "Angle of each clone from the stem (classic rule).", &L::splitAngle},
    LevelField{"SplitAngleV", FieldType::Real, 0, 180, true, "Variation of SplitAngle.", &L::splitAngleV},
    LevelField{"CurveRes", FieldType::Integer, 1, 64, true, "Segments per stem.", nullptr, &L::curveRes},
    LevelField{"Curve", FieldType::Real, -720, 720, true, "Bend over the stem in degrees.", &L::curve},
    LevelField{"CurveBack", FieldType::Real, -720, 720, true,
               "Bend of the second half when non-zero (S-shaped stems).", &L::curveBack},
    LevelField{"CurveV", FieldType::Real, 0, 1440, true,
               "Random bend variation (helical stems, CurveV < 0, are not supported).", &L::curveV},
    LevelField{"DownAngle", FieldType::Real, -180, 180, true,
               "Angle from the parent (classic rule; level 0: tilt of multiple trunks).", &L::downAngle},
    LevelField{"DownAngleV", FieldType::Real, -180, 180, true,
               "Variation of DownAngle (negative: varies along the parent).", &L::downAngleV},
    LevelField{"Rotate", FieldType::Real, -360, 360, true,
               "Azimuth step between successive children (negative alternates sides).", &L::rotate},
    LevelField{"RotateV", FieldType::Real, 0, 360, true, "Variation of Rotate.", &L::rotateV},
    LevelField{"BranchRatio", FieldType::Real, 0.01, 1, false,
               "S = child radius / continuing parent radius at the branch point (natural rules); "
               "default Length^RatioPower clamped to [0.05, 1].",
               &L::branchRatio},
};

}  // namespace

std::span<const TreeField> treeFields() { return kTreeFields; }
std::span<const LevelField> levelFields() { return kLevelFields; }

const char* angleRuleName(AngleRule rule) { return rule == AngleRule::Natural ? "natural" : "classic"; }

const char* leafKindName(LeafKind kind) {
  switch (kind) {
    case LeafKind::Broad: return "broad";
    case LeafKind::Narrow: return "narrow";
    case LeafKind::Frond: return "frond";
    case LeafKind::Needle: return "needle";
  }
  return "broad";
}

bool parseAngleRule(const std::string& text, AngleRule& out) {
  if (text == "natural") { out = AngleRule::Natural; return true; }
  if (text == "classic") { out = AngleRule::Classic; return true; }
  return false;
}

bool parseLeafKind(const std::string& text, LeafKind& out) {
  for (LeafKind k : {LeafKind::Broad, LeafKind::Narrow, LeafKind::Frond, LeafKind::Needle}) {
    if (text == leafKindName(k)) { out = k; return true; }
  }
  return false;
}

std::string rangeText(FieldType type, double min, double max) {
  char buf[96];
  if (type == FieldType::Integer) {
    std::snprintf(buf, sizeof buf, "integer in [%.0f, %.0f]", min, max);
  } else {
    std::snprintf(buf, sizeof buf, "number in [%g, %g]", min, max);
  }
  return buf;
}

// Level parameters beyond the given ones reuse the deepest entry (extra impostor levels).
const StemLevelParams& SpeciesParams::level(int n) const {
  const auto last = static_cast<int>(stemLevels.size()) - 1;
  return stemLevels[static_cast<std::size_t>(std::clamp(n, 0, last))];
}

double SpeciesParams::branchRatio(int n) const {
  const StemLevelParams& lp = level(n);
  if (lp.branchRatioGiven) return lp.branchRatio;
  return std::clamp(std::pow(lp.length, ratioPower), 0.05, 1.0);
}

}  // namespace arbor
