// Formula values of the natural rules (Nystad ch. 3, app. B; Murray 1926/27).
#include <catch2/catch.hpp>
#include <cmath>

#include "growth/math.hpp"
#include "growth/weber_penn/natural_rules.hpp"

using namespace arbor;
using namespace arbor::natural;
using Catch::Matchers::WithinAbs;

TEST_CASE("total branch angle for an equal split matches the thesis", "[natural]") {
  CHECK_THAT(degrees(totalAngle(1.0, 2.49)), WithinAbs(58.5, 0.05));
  CHECK_THAT(degrees(totalAngle(1.0, 3.0)), WithinAbs(74.9, 0.05));
}

TEST_CASE("Murray's exact split for S = 0.5, E = 2.49", "[natural]") {
  const double Cp = primaryRadiusFactor(0.5, 2.49), Cs = secondaryRadiusFactor(0.5, 2.49);
  const double x = primaryAngle(1.0, Cp, Cs), y = secondaryAngle(1.0, Cp, Cs);
  CHECK_THAT(degrees(x), WithinAbs(11.1, 0.05));
  CHECK_THAT(degrees(y), WithinAbs(50.4, 0.05));
  CHECK_THAT(degrees(x + y), WithinAbs(61.5, 0.05));
  // The closed form for x + y agrees with the two angles.
  CHECK_THAT(x + y, WithinAbs(totalAngle(0.5, 2.49), 1e-12));
}

TEST_CASE("radius factors conserve r^E and give the ratio S", "[natural]") {
  for (double E : {2.0, 2.49, 3.0}) {
    for (double S : {0.05, 0.3, 0.5, 0.8, 1.0}) {
      const double Cp = primaryRadiusFactor(S, E), Cs = secondaryRadiusFactor(S, E);
      CHECK_THAT(std::pow(Cp, E) + std::pow(Cs, E), WithinAbs(1.0, 1e-14));
      CHECK_THAT(Cs / Cp, WithinAbs(S, 1e-14));
    }
  }
}

TEST_CASE("Murray's angles balance the branch forces: r1^2 sin x = r2^2 sin y", "[natural]") {
  for (double S : {0.1, 0.4, 0.7, 1.0}) {
    const double r1 = primaryRadiusFactor(S, 2.49), r2 = secondaryRadiusFactor(S, 2.49);
    const double x = primaryAngle(1.0, r1, r2), y = secondaryAngle(1.0, r1, r2);
    CHECK_THAT(r1 * r1 * std::sin(x), WithinAbs(r2 * r2 * std::sin(y), 1e-12));
    // Along the parent axis: r0^2 = r1^2 cos x + r2^2 cos y.
    CHECK_THAT(r1 * r1 * std::cos(x) + r2 * r2 * std::cos(y), WithinAbs(1.0, 1e-12));
  }
}

TEST_CASE("equal secondary and primary deviate symmetrically", "[natural]") {
  const double r = primaryRadiusFactor(1.0, 2.49);
  CHECK_THAT(primaryAngle(1.0, r, r), WithinAbs(secondaryAngle(1.0, r, r), 1e-15));
}

TEST_CASE("n-way clones conserve r^E and generalise the equal split", "[natural]") {
  for (int n : {2, 3, 4, 7}) {
    const double c = cloneRadiusFactor(n, 2.49);
    CHECK_THAT(n * std::pow(c, 2.49), WithinAbs(1.0, 1e-14));
    CHECK_THAT(n * c * c * std::cos(cloneAngle(n, 2.49)), WithinAbs(1.0, 1e-14));
  }
  CHECK_THAT(cloneAngle(2, 2.49), WithinAbs(totalAngle(1.0, 2.49) / 2.0, 1e-12));
  CHECK(cloneAngle(3, 2.49) > cloneAngle(2, 2.49));
}
