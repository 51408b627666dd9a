#pragma once
// Radius along a stem: natural radius (stepped at branch points) times the Weber-Penn taper shape
// normalised to 1 at the stem base, times the trunk flare. Linear in the natural radius, so the
// natural rules hold exactly at every branch point whatever the taper.
#include "weber_penn_rules.hpp"

namespace arbor {

struct StemProfile {
  double taper = 1.0;
  double length = 1.0;
  double refRadius = 1.0;  // radius that sets the scale of tips and periodic spheres
  double norm = 1.0;       // taper shape at the base, so that at(0) == 1 before flare
  double flare = 0.0;      // trunk only; 0 elsewhere

  // Factor applied to the natural radius at arc length z from the stem base.
  double at(double z) const {
    const double t = length > 0.0 ? z / length : 0.0;
    const double shape = wp::taperedRadius(taper, refRadius, length, t) / (refRadius * norm);
    return flare != 0.0 ? shape * wp::flareFactor(flare, t) : shape;
  }
};

inline StemProfile makeStemProfile(double taper, double length, double refRadius, double flare) {
  StemProfile profile{taper, length, refRadius > 0.0 ? refRadius : 1.0, 1.0, flare};
  const double base = wp::taperedRadius(taper, profile.refRadius, length, 0.0) / profile.refRadius;
  profile.norm = base > 1e-6 ? base : 1.0;  // a sphere chain can start pinched; never divide by ~0
  return profile;
}

}  // namespace arbor
