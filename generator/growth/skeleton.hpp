#pragma once
// The skeleton: what a growth model hands to the mesh stage. Nodes carry relative transforms (so a
// deflection propagates to descendants) and the object-space result; z is up, the trunk base at the origin.
#include <cstdint>
#include <string>
#include <vector>

#include "math.hpp"

namespace arbor {

enum class NodeKind : std::uint8_t {
  Root,        // common base of several trunks
  Base,        // bottom of a trunk
  Joint,       // end of a stem segment (curvature changes here)
  Attachment,  // a child grows from here (branch point)
  Split,       // the stem ends in equal clones here (branch point)
  Before,      // intermediate node before an attachment (Nystad 4.2.2)
  After,       // intermediate node after an attachment or at the start of a child or clone
  Tip,         // end of a stem
};
const char* nodeKindName(NodeKind kind);

struct SkeletonNode {
  std::int32_t parent = -1;  // parent node index; -1 for the root
  std::int32_t stem = -1;    // stem this node belongs to
  std::int16_t level = 0;
  NodeKind kind = NodeKind::Joint;
  double offset = 0;         // arc length from the base of the stem (clones continue their source's)
  Transform local;           // relative to the parent node's frame (deflections live here)
  Transform world;           // object space; world.rotation * +z = the stem's direction leaving this node
  double radius = 0;         // cross-section radius here (the arriving side at branch points)
  double startRadius = 0;    // radius at which the edge from the parent node leaves that node
};

struct SkeletonStem {
  std::uint64_t key = 0;      // identity of this stem for the same seed (independent of other levels)
  std::int16_t level = 0;
  std::int32_t parentStem = -1;   // stem this one grows from (-1: a trunk)
  std::int32_t cloneOf = -1;      // stem this clone split from (-1: not a clone)
  std::int32_t attachNode = -1;   // node this stem's first edge leaves from (-1: trunk base is its own)
  std::int32_t firstNode = -1;    // this stem's own nodes are [firstNode, firstNode + nodeCount)
  std::int32_t nodeCount = 0;
  double length = 0;              // full length of the stem (clones share their source's)
  double startOffset = 0;         // where along the stem this one starts (clones: at their split)
  double offsetOnParent = 0;      // arc length on the parent stem where it attaches
  double startRadius = 0;         // radius leaving the attach node
  double branchRatio = 0;         // S used at the attachment (natural rules); 0 for trunks and clones
  double secondaryAngle = 0;      // radians from the parent's direction at the attachment
  double primaryDeflection = 0;   // radians the parent turned away at the attachment
  int firstSegment = 0;           // segment index where this stem starts (clones: after the split)
  bool stub = false;              // too short, stubby or slender for a tube (wp::stubby), or grows from one; clones share it
  std::vector<Transform> rawJoints;  // undeflected base frame then each segment end: the raw tree data
};

struct Leaf {
  std::int32_t stem = -1;
  std::int32_t node = -1;   // node the leaf hangs from (it follows that node's deflections)
  Vec3 position{};          // object space: base of the blade
  Vec3 direction{};         // along the blade, from base to tip
  Vec3 normal{};            // face normal of the blade
  double length = 0, width = 0;
  std::uint8_t kind = 0;    // LeafKind
};

struct Skeleton {
  std::string species;
  std::uint64_t seed = 0;
  int levels = 0;
  double treeScale = 0;       // Scale +- ScaleV as drawn
  double exponent = 2.49;     // E of the natural rules used
  int lobes = 0;              // trunk lobes, for the renderer's displacement
  double lobeDepth = 0;
  std::vector<SkeletonNode> nodes;
  std::vector<SkeletonStem> stems;
  std::vector<Leaf> leaves;
};

// The stem a stem grows from: the one a clone split from, else its parent (-1: a trunk).
inline int grownFrom(const Skeleton& skeleton, int stem) {
  const SkeletonStem& s = skeleton.stems[static_cast<std::size_t>(stem)];
  return s.cloneOf >= 0 ? s.cloneOf : s.parentStem;
}

}  // namespace arbor
