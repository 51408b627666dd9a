#pragma once
// Radius along a stem (da Vinci's pipes, Nystad ch. 3): the natural radius, stepped down at each branch
// point, stays constant between them; Weber-Penn's taper shapes only the tail after the last child (a twig
// without children is all tail). Tapers of 2 and more (hemispherical tips, periodic spheres) describe the
// whole stem and apply everywhere. The trunk also flares. Everything is a factor on the natural radius, so
// the natural rules hold exactly at every branch point whatever the taper.
#include <algorithm>

#include "weber_penn_rules.hpp"

namespace arbor {

struct StemProfile {
  double taper = 1.0;
  double length = 1.0;
  double refRadius = 1.0;   // radius that sets the scale of tips and periodic spheres
  double norm = 1.0;        // whole-stem shape at the base, so that at(0) == 1 before flare
  double flare = 0.0;       // trunk only; 0 elsewhere
  double tailStart = 0.0;   // arc length where the taper of a stem below 2 begins

  // Factor applied to the natural radius at arc length z from the stem base.
  double at(double z) const {
    const double t = length > 0.0 ? z / length : 0.0;
    double shape = 1.0;
    if (taper >= 2.0) {
      shape = wp::taperedRadius(taper, refRadius, length, t) / (refRadius * norm);
    } else if (z > tailStart) {
      const double tail = length - tailStart;
      const double start = wp::taperedRadius(taper, refRadius, tail, 0.0);
      shape = start > 0.0 ? wp::taperedRadius(taper, refRadius, tail, (z - tailStart) / tail) / start : 1.0;
    }
    return flare != 0.0 ? shape * wp::flareFactor(flare, t) : shape;
  }
};

inline StemProfile makeStemProfile(double taper, double length, double refRadius, double flare) {
  StemProfile profile{taper, length, refRadius > 0.0 ? refRadius : 1.0, 1.0, flare, 0.0};
  if (taper >= 2.0) {
    const double base = wp::taperedRadius(taper, profile.refRadius, length, 0.0) / profile.refRadius;
    profile.norm = base > 1e-6 ? base : 1.0;  // a sphere chain can start pinched; never divide by ~0
  }
  // Until its children are known the whole stem is body; growth then sets where the tail begins.
  profile.tailStart = length;
  return profile;
}

}  // namespace arbor
