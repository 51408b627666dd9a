#pragma once
// Weber & Penn's (1995) closed-form rules: crown shapes, taper, flare, lobes, child counts and lengths,
// the pruning envelope. Pure functions; the growth algorithm in weber_penn.cpp calls them.

namespace arbor {
struct SpeciesParams;
}

namespace arbor::wp {

// Envelope parameters used by shape 8 and by pruning.
struct Envelope {
  double width = 0.5, widthPeak = 0.5, powerLow = 0.5, powerHigh = 0.5;
};

// Shape ratio for shapes 0..8 at ratio in [0, 1] (0 = top of the crown, 1 = its base). Conical (0) is Arbaro's
// `ratio`, not the paper's 0.2 + 0.8 ratio.
double shapeRatio(int shape, double ratio, const Envelope& envelope = {});

// Radius of a stem at relative position z in [0, 1] for Weber-Penn taper in [0, 3]:
// 0 cylinder, 1 cone, (1, 2) rounded tip, 2 hemispherical tip, (2, 3] periodic spheres.
double taperedRadius(double taper, double baseRadius, double length, double z);

// Trunk base widening factor: 1 + Flare (100^y - 1) / 100 with y = max(0, 1 - 8 z).
double flareFactor(double flare, double z);

// Trunk cross-section modulation around the axis: 1 + LobeDepth sin(Lobes angle).
double lobeFactor(int lobes, double lobeDepth, double angle);

// Children of a trunk: the level's Branches.
double childCountOfTrunk(double branches);
// Children of a level-1 stem: Branches (0.2 + 0.8 (length / parentLength) / lengthChildMax).
double childCountOfLevel1(double branches, double length, double parentLength, double lengthChildMax);
// Children of deeper stems: Branches (1 - 0.5 offset / parentLength).
double childCountOfDeeper(double branches, double offset, double parentLength);

// Length of a child of the trunk at `offset` from the trunk base.
double childLengthOfTrunk(const SpeciesParams& p, double lengthChildMax, double trunkLength, double baseLength,
                          double offset);
// Length of a child of a deeper stem: lengthChildMax (parentLength - 0.6 offset).
double childLengthOfDeeper(double lengthChildMax, double parentLength, double offset);

// Whether a child is grown at all: as in Arbaro, every child longer than 10 µm with some wood grows, however
// stubby or slender (the mesh and impostor stages decide how to draw those).
bool childGrows(double length, double childRadius);

// Whether a grown child is a stub no tube can draw well: one ending inside its parent (shorter than twice the
// parent's radius there), shorter than 25 of its own radii, more slender than 500 (where a tapering parent runs
// out of wood), or hair-thin. Arbaro grows these, so Arbor does; the mesh and impostor stages may leave them out.
bool stubby(double length, double incomingRadius, double childRadius, double treeScale);

// Leaves on a deepest-level stem at `offset` along its parent: |Leaves| * ShapeRatio(LeafDistrib) * LeafQuality.
double leafCount(const SpeciesParams& p, double offset, double parentLength);

// Whether a point (tree space, z up, origin at the trunk base) lies inside the pruning envelope.
bool insideEnvelope(const SpeciesParams& p, double treeScale, double x, double y, double z);

Envelope envelopeOf(const SpeciesParams& p);

}  // namespace arbor::wp
