#pragma once
// Each stem of a skeleton as a chain of tapered capsules (one per skeleton edge, with its nodes' radii):
// where the skeleton itself says a stem's wood is, to tell crossings Weber-Penn made from the mesher's.
#include <vector>

#include "growth/skeleton.hpp"

namespace arbor {

struct Capsule {
  Vec3 a{0.0}, b{0.0};
  double ra = 0, rb = 0;   // radius at a and at b
  bool flatStart = false;  // cut off square at a (a stem's start inside its parent), not rounded
};

// Where a child's (or clone's) capsules start along its axis.
enum class StemStart {
  // Its wood has cleared the parent's (the parent's radius and its own, over the sine of the angle between
  // them): against its own parent, the two overlap by construction and the mesh there is the neck's doing.
  ClearOfParent,
  // Its axis has left the parent's wood: against any other stem, its wood from there on is its own.
  OutOfParentWood,
};

// How far along a child's axis its wood clears its parent's (the start of its ClearOfParent capsules): the two
// radii over the sine of the angle between them, with the surface's reach; 0 for trunks and clones.
double parentClearance(const Skeleton& skeleton, int stem);

// Whether a child leaves its parent at under 34 degrees (tan 34 = 1 / 1.5): its skeleton stays inside the parent's
// radius for more than 1.5 parent radii along it, farther than issue 13's joint floor lets its first cross section
// stand, so its neck and first band must leave the skeleton. False for trunks, clones and backward children.
bool shallowJoint(const Skeleton& skeleton, int stem);

// Per stem, its edges as capsules, a child's or clone's starting as `start` says.
std::vector<std::vector<Capsule>> stemCapsules(const Skeleton& skeleton, StemStart start = StemStart::ClearOfParent);
// The same for one stem (what a check of a few stems' quads needs, without the whole tree's).
std::vector<Capsule> stemCapsulesOf(const Skeleton& skeleton, int stem, StemStart start = StemStart::ClearOfParent);

// A stem's capsules from where its axis leaves another stem's wood on (none if it never does): two clones of one
// split as seen against each other, their overlap at the split left out.
std::vector<Capsule> capsulesOutOf(const Skeleton& skeleton, int stem, int other);

// Distance from x to the capsule's axis over its radius there (at least minRadius: the mesh keeps tips
// thicker than the skeleton's, which tapers to 0): <= 1 inside; infinite before a flat start.
double capsuleReach(const Capsule& c, const Vec3& x, double minRadius = 0.0);

// The smallest reach of x over a stem's capsules (infinite for a stem without any).
double stemReach(const std::vector<Capsule>& stem, const Vec3& x, double minRadius = 0.0);

// Distance between segments p0-p1 and q0-q1.
double segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

// Where two stems' wood meets: over every pair of their capsules, each radius times `inflate`, that overlap
// at their axes' closest points, the smallest distance from x to the middle of the overlap (half-way between the
// closest points; for near-parallel axes, half-way between them along the length where they stay within reach),
// in units of the two inflated radii at the closest points (infinite when the stems' capsules never overlap).
double distanceToOverlap(const std::vector<Capsule>& a, const std::vector<Capsule>& b, const Vec3& x, double inflate);
// The same in two steps, for many points against one pair of stems: where their inflated capsules overlap (a
// segment of middles, and the two inflated radii at the closest points), then the distance.
struct WoodOverlap {
  Vec3 from{0.0}, to{0.0};
  double reach = 0;
};
std::vector<WoodOverlap> woodOverlaps(const std::vector<Capsule>& a, const std::vector<Capsule>& b, double inflate);
double distanceToOverlap(const std::vector<WoodOverlap>& overlaps, const Vec3& x);

}  // namespace arbor
