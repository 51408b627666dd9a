#pragma once
// Species parameters: the full Weber-Penn set as extended by Nystad (app. A), as one value type.
#include <string>
#include <vector>

namespace arbor {

// How deviation angles at branch points are chosen.
enum class AngleRule {
  Natural,  // Murray's equilibrium from the radii (Nystad ch. 3); DownAngle/SplitAngle unused
  Classic,  // DownAngle/SplitAngle from the file, as Weber and Penn did
};

// Leaf kinds of the leaf atlas; Arbaro's LeafShape names map onto these.
enum class LeafKind { Broad = 0, Narrow = 1, Frond = 2, Needle = 3 };

// Parameters that Weber-Penn give per stem level ("0Length", "1Length", ...).
struct StemLevelParams {
  double branches = 0;      // children of each parent stem (level 0: number of trunks)
  double length = 0;        // length relative to the parent (level 0: relative to Scale)
  double lengthV = 0;
  double taper = 0;         // 0 cylinder, 1 cone, 2 hemispherical tip, >2 periodic spheres
  double segSplits = 0;     // clone splits per segment joint (fractions carry over)
  double splitAngle = 0;    // classic rule only
  double splitAngleV = 0;
  int curveRes = 1;         // segments per stem
  double curve = 0;         // degrees of bend over the stem
  double curveBack = 0;     // bend of the second half (S-shaped stems) when non-zero
  double curveV = 0;
  double downAngle = 0;     // classic rule only (branches); leaves always use their own
  double downAngleV = 0;
  double rotate = 0;        // azimuth step between successive children; negative alternates
  double rotateV = 0;
  double branchRatio = 0;   // S = r_secondary / r_primary at the branch point (natural rules)
  bool branchRatioGiven = false;  // false: derived from Length^RatioPower (documented)
};

struct SpeciesParams {
  std::string name;
  std::string source;  // file it came from, for error messages and summaries

  int shape = 0;       // 0..8, 8 = pruning envelope
  int levels = 1;      // stem levels, trunk included
  double scale = 1, scaleV = 0;
  double baseSize = 0;
  int baseSplits = 0;
  double ratio = 0.02, ratioPower = 1;
  double flare = 0;
  int lobes = 0;
  double lobeDepth = 0;
  double attractionUp = 0;
  double treeShapeExponent = 2.49;  // E in r^E = r_p^E + r_s^E
  AngleRule angleRule = AngleRule::Natural;
  double trunkScale = 1, trunkScaleV = 0;  // Weber-Penn 0Scale/0ScaleV

  double pruneRatio = 0, pruneWidth = 0.5, pruneWidthPeak = 0.5;
  double prunePowerLow = 0.5, prunePowerHigh = 0.5;

  double leaves = 0;   // per deepest-level stem; negative: a fan of |Leaves| at the stem tip
  LeafKind leafShape = LeafKind::Broad;
  double leafScale = 0.2, leafScaleX = 0.5;
  double leafQuality = 1;   // leaf density: count * Q, size / sqrt(Q)
  double leafStemLen = 0;   // petiole length relative to the leaf length
  double leafBend = 0;      // 0..1: turn leaf faces towards the sky
  int leafDistrib = 4;      // shape ratio used to distribute leaves along their parent
  double leafDownAngle = 45, leafDownAngleV = 0, leafRotate = 137.5, leafRotateV = 0;

  std::vector<StemLevelParams> stemLevels;  // [0] = trunk; deeper levels reuse the last entry

  // Parameters of level n, reusing the deepest given entry beyond the end (impostor levels).
  const StemLevelParams& level(int n) const;
  // S of level n: the given BranchRatio or Length^RatioPower clamped to [0.05, 1].
  double branchRatio(int n) const;
};

}  // namespace arbor
