#pragma once
// The raw tree of the Weber-Penn stage (Nystad 5.2): stems with undeflected segment frames and the
// events (children, leaves) found along them. The skeleton builder turns it into nodes.
#include <cstdint>
#include <vector>

#include "growth/math.hpp"
#include "stem_profile.hpp"

namespace arbor {

// A child attached to a stem.
struct RawAttachment {
  double z = 0;              // arc length on the stem (unit) where the child grows
  int child = -1;            // raw stem index of the child
  double azimuth = 0;        // radians around the parent axis, in the segment frame
  double incomingRadius = 0; // parent radius arriving at the branch point
  double primaryFactor = 1;  // C_p: the parent continues with this times incomingRadius
  double deflection = 0;     // Murray's x (radians) the parent turns away; 0 with the classic rule
};

struct RawLeaf {
  int stem = -1;
  double z = 0;
  Quat rotation{1, 0, 0, 0};  // blade frame relative to the segment frame at z (z axis along the blade)
  double length = 0, width = 0;
  double stemLength = 0;      // petiole length
};

struct RawStem {
  std::uint64_t key = 0;
  int level = 0;
  int parent = -1;          // raw stem it grows from
  int cloneOf = -1;         // raw stem it split from
  double length = 0;        // of the whole stem unit (clones share it)
  int curveRes = 1;
  int firstSegment = 0;     // clones begin after their split joint
  double offsetOnParent = 0;
  double parentLength = 0;
  double parentLengthChildMax = 0;
  Transform base;                  // undeflected frame where this stem starts (outgoing direction)
  std::vector<Transform> joints;   // undeflected frame at the end of each own segment (outgoing, tip: incoming)
  bool endsInSplit = false;
  std::vector<int> clones;

  // Natural radius (untapered) where this stem starts, and the taper/flare shape of its unit.
  double naturalStart = 0;
  StemProfile profile;
  double startRadius = 0;       // radius leaving the attach/split node
  double parentRadius = 0;      // parent's radius arriving at the attachment (children only)
  double branchRatio = 0, secondaryAngle = 0, deflection = 0;
  bool stub = false;            // wp::stubby, or on a stub: the mesh may leave it out

  std::vector<RawAttachment> attachments;  // in z order

  // State carried from a stem to its clones (child and leaf rates, rotation).
  double lengthChildMax = 0;
  double childRate = 0, childAzimuth = 0, childSide = 1;
  double leafRate = 0, leafAzimuth = 0, leafSide = 1;
  double naturalEnd = 0;        // natural radius after the last attachment
  std::uint64_t childSlots = 0; // children considered so far (keys stay stable when some are skipped)

  double segmentLength() const { return length / curveRes; }
  double startZ() const { return firstSegment * segmentLength(); }
  int lastSegment() const { return firstSegment + static_cast<int>(joints.size()) - 1; }
  // Undeflected frame of segment s at arc length z within it.
  Transform frameAt(int segment, double z) const {
    const Transform& start = segment == firstSegment ? base : joints[static_cast<std::size_t>(segment - firstSegment - 1)];
    const double along = z - segment * segmentLength();
    return Transform{start.position + start.direction() * along, start.rotation};
  }
  int segmentOf(double z) const;
};

struct RawTree {
  double treeScale = 0;
  double baseLength = 0;
  std::vector<RawStem> stems;
  std::vector<RawLeaf> leaves;
};

}  // namespace arbor
