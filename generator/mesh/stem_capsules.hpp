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

// Per stem, its edges as capsules. A child or clone starts where its axis has cleared its parent's wood
// (the parent's radius and its own, over the sine of the angle between them): inside the parent the two
// overlap by construction, and what the mesh does there is the neck's doing.
std::vector<std::vector<Capsule>> stemCapsules(const Skeleton& skeleton);

// Distance from x to the capsule's axis over its radius there (at least minRadius: the mesh keeps tips
// thicker than the skeleton's, which tapers to 0): <= 1 inside; infinite before a flat start.
double capsuleReach(const Capsule& c, const Vec3& x, double minRadius = 0.0);

// The smallest reach of x over a stem's capsules (infinite for a stem without any).
double stemReach(const std::vector<Capsule>& stem, const Vec3& x, double minRadius = 0.0);

// Where two stems' wood meets: over every pair of their capsules, each radius times `inflate`, that overlap
// at their axes' closest points, the smallest distance from x to the middle of those points, in units of the
// two inflated radii there (infinite when the stems' capsules never overlap).
double distanceToOverlap(const std::vector<Capsule>& a, const std::vector<Capsule>& b, const Vec3& x, double inflate);

}  // namespace arbor
