#include "natural_rules.hpp"

#include <algorithm>
#include <cmath>

namespace arbor::natural {

namespace {
// acos of a value that rounding may push a hair outside [-1, 1].
double safeAcos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }
}  // namespace

double primaryRadiusFactor(double S, double E) { return 1.0 / std::pow(1.0 + std::pow(S, E), 1.0 / E); }

double secondaryRadiusFactor(double S, double E) { return S * primaryRadiusFactor(S, E); }

double cloneRadiusFactor(int n, double E) { return 1.0 / std::pow(static_cast<double>(n), 1.0 / E); }

double primaryAngle(double r0, double r1, double r2) {
  const double a = r0 * r0, b = r1 * r1, c = r2 * r2;
  return safeAcos((a * a + b * b - c * c) / (2.0 * a * b));
}

double secondaryAngle(double r0, double r1, double r2) {
  const double a = r0 * r0, b = r1 * r1, c = r2 * r2;
  return safeAcos((a * a + c * c - b * b) / (2.0 * a * c));
}

double totalAngle(double S, double E) {
  const double S2 = S * S;
  return safeAcos((std::pow(1.0 + std::pow(S, E), 4.0 / E) - 1.0 - S2 * S2) / (2.0 * S2));
}

double cloneAngle(int n, double E) { return safeAcos(std::pow(static_cast<double>(n), 2.0 / E - 1.0)); }

}  // namespace arbor::natural
