#include "weber_penn_rules.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "species.hpp"

namespace arbor::wp {

double shapeRatio(int shape, double ratio, const Envelope& e) {
  constexpr double pi = std::numbers::pi;
  switch (shape) {
    case 0: return ratio;  // conical as Arbaro grows it (the paper's 0.2 + 0.8 ratio gives larches no point)
    case 1: return 0.2 + 0.8 * std::sin(pi * ratio);           // spherical
    case 2: return 0.2 + 0.8 * std::sin(0.5 * pi * ratio);     // hemispherical
    case 3: return 1.0;                                        // cylindrical
    case 4: return 0.5 + 0.5 * ratio;                          // tapered cylindrical
    case 5: return ratio <= 0.7 ? ratio / 0.7 : (1.0 - ratio) / 0.3;                  // flame
    case 6: return 1.0 - 0.8 * ratio;                                                 // inverse conical
    case 7: return ratio <= 0.7 ? 0.5 + 0.5 * ratio / 0.7 : 0.5 + 0.5 * (1.0 - ratio) / 0.3;  // tend flame
    case 8: {                                                                         // envelope
      if (ratio < 0.0 || ratio > 1.0) return 0.0;
      const double peak = 1.0 - e.widthPeak;  // envelope ratio of the widest point
      if (ratio < peak) return std::pow(ratio / peak, e.powerHigh);
      return std::pow((1.0 - ratio) / (1.0 - peak), e.powerLow);
    }
    default: return 1.0;
  }
}

double taperedRadius(double taper, double baseRadius, double length, double z) {
  z = std::clamp(z, 0.0, 1.0);
  double unitTaper = 0.0;
  if (taper < 1.0) unitTaper = taper;
  else if (taper < 2.0) unitTaper = 2.0 - taper;
  const double taperZ = baseRadius * (1.0 - unitTaper * z);
  if (taper < 1.0) return taperZ;

  // Tips and periodic spheres measure distances from the stem end against the local radius.
  const double z2 = (1.0 - z) * length;
  const double depth = (taper < 2.0 || z2 < taperZ) ? 1.0 : taper - 2.0;
  double z3 = z2;
  if (taper >= 2.0 && taperZ > 0.0) {
    z3 = std::fabs(z2 - 2.0 * taperZ * std::floor(z2 / (2.0 * taperZ) + 0.5));
  }
  if (taper < 2.0 && z3 >= taperZ) return taperZ;
  const double sphere = std::sqrt(std::max(0.0, taperZ * taperZ - (z3 - taperZ) * (z3 - taperZ)));
  return (1.0 - depth) * taperZ + depth * sphere;
}

double flareFactor(double flare, double z) {
  const double y = std::max(0.0, 1.0 - 8.0 * z);
  return 1.0 + flare * (std::pow(100.0, y) - 1.0) / 100.0;
}

double lobeFactor(int lobes, double lobeDepth, double angle) {
  return 1.0 + lobeDepth * std::sin(static_cast<double>(lobes) * angle);
}

double childCountOfTrunk(double branches) { return branches; }

double childCountOfLevel1(double branches, double length, double parentLength, double lengthChildMax) {
  if (parentLength <= 0.0 || lengthChildMax <= 0.0) return 0.0;
  return branches * (0.2 + 0.8 * (length / parentLength) / lengthChildMax);
}

double childCountOfDeeper(double branches, double offset, double parentLength) {
  if (parentLength <= 0.0) return 0.0;
  return branches * (1.0 - 0.5 * offset / parentLength);
}

bool childGrows(double length, double childRadius) {
  constexpr double kMinLength = 1e-5;  // Arbaro's MIN_STEM_LEN
  return length > kMinLength && childRadius > 0.0 && std::isfinite(childRadius);
}

bool stubby(double length, double incomingRadius, double childRadius, double treeScale) {
  constexpr double kMaxSlenderness = 500.0, kMinStubness = 25.0;
  return length < 2.0 * incomingRadius || length < kMinStubness * childRadius || childRadius < 1e-5 * treeScale ||
         childRadius * kMaxSlenderness < length;
}

Envelope envelopeOf(const SpeciesParams& p) {
  return Envelope{p.pruneWidth, p.pruneWidthPeak, p.prunePowerLow, p.prunePowerHigh};
}

double childLengthOfTrunk(const SpeciesParams& p, double lengthChildMax, double trunkLength, double baseLength,
                          double offset) {
  const double span = trunkLength - baseLength;
  const double ratio = span > 0.0 ? (trunkLength - offset) / span : 0.0;
  return trunkLength * lengthChildMax * shapeRatio(p.shape, ratio, envelopeOf(p));
}

double childLengthOfDeeper(double lengthChildMax, double parentLength, double offset) {
  return std::max(0.0, lengthChildMax * (parentLength - 0.6 * offset));
}

double leafCount(const SpeciesParams& p, double offset, double parentLength) {
  const double ratio = parentLength > 0.0 ? offset / parentLength : 0.0;
  return std::fabs(p.leaves) * shapeRatio(p.leafDistrib, ratio, envelopeOf(p)) * p.leafQuality;
}

bool insideEnvelope(const SpeciesParams& p, double treeScale, double x, double y, double z) {
  const double ratio = (treeScale - z) / (treeScale * (1.0 - p.baseSize));
  const double r = std::sqrt(x * x + y * y);
  return r / treeScale < p.pruneWidth * shapeRatio(8, ratio, envelopeOf(p));
}

}  // namespace arbor::wp
