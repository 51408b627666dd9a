// Weber-Penn closed-form rules: shapes, taper, flare, child counts and lengths.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "growth/weber_penn/weber_penn_rules.hpp"
#include "growth/weber_penn/species.hpp"

using namespace arbor;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("shape ratios at the crown's top, middle and base", "[wp]") {
  const double pi = std::numbers::pi;
  CHECK_THAT(wp::shapeRatio(0, 0.5), WithinAbs(0.5, 1e-15));  // Arbaro's conical, pointed at the top
  CHECK(wp::shapeRatio(0, 0.0) == 0.0);
  CHECK_THAT(wp::shapeRatio(1, 0.5), WithinAbs(1.0, 1e-15));
  CHECK_THAT(wp::shapeRatio(1, 0.25), WithinAbs(0.2 + 0.8 * std::sin(pi / 4), 1e-15));
  CHECK_THAT(wp::shapeRatio(2, 1.0), WithinAbs(1.0, 1e-15));
  CHECK_THAT(wp::shapeRatio(3, 0.1), WithinAbs(1.0, 1e-15));
  CHECK_THAT(wp::shapeRatio(4, 0.0), WithinAbs(0.5, 1e-15));
  CHECK_THAT(wp::shapeRatio(5, 0.7), WithinAbs(1.0, 1e-15));
  CHECK_THAT(wp::shapeRatio(5, 0.85), WithinAbs(0.5, 1e-12));
  CHECK_THAT(wp::shapeRatio(6, 1.0), WithinAbs(0.2, 1e-15));
  CHECK_THAT(wp::shapeRatio(7, 0.35), WithinAbs(0.75, 1e-12));
  const wp::Envelope e{0.5, 0.6, 0.5, 0.5};
  CHECK_THAT(wp::shapeRatio(8, 0.4, e), WithinAbs(1.0, 1e-12));  // widest at ratio 1 - PruneWidthPeak
  CHECK_THAT(wp::shapeRatio(8, 0.1, e), WithinAbs(std::pow(0.25, 0.5), 1e-12));
  CHECK(wp::shapeRatio(8, 1.2, e) == 0.0);
  CHECK(wp::shapeRatio(8, -0.1, e) == 0.0);
}

TEST_CASE("taper shapes: cylinder, cone, partial cone, tips and periodic spheres", "[wp]") {
  const double R = 0.2, L = 10.0;
  for (double z : {0.0, 0.3, 0.99}) CHECK(wp::taperedRadius(0.0, R, L, z) == R);           // cylinder
  CHECK_THAT(wp::taperedRadius(1.0, R, L, 0.5), WithinAbs(0.1, 1e-15));                     // cone
  CHECK_THAT(wp::taperedRadius(1.0, R, L, 1.0), WithinAbs(0.0, 1e-15));
  CHECK_THAT(wp::taperedRadius(0.5, R, L, 1.0), WithinAbs(0.1, 1e-15));                     // partial cone
  // 1.5: a cone to half the radius with a spherical cap of that radius at the end.
  CHECK_THAT(wp::taperedRadius(1.5, R, L, 0.5), WithinAbs(R * (1 - 0.5 * 0.5), 1e-15));
  const double tipZ = 1.0 - 0.05 / L;  // 5 cm before the tip, radius there ~0.1
  const double taperZ = R * (1 - 0.5 * tipZ);
  const double d = 0.05;
  CHECK_THAT(wp::taperedRadius(1.5, R, L, tipZ), WithinRel(std::sqrt(taperZ * taperZ - (d - taperZ) * (d - taperZ)), 1e-12));
  // 2: a cylinder with a hemispherical tip.
  CHECK_THAT(wp::taperedRadius(2.0, R, L, 0.5), WithinAbs(R, 1e-15));
  CHECK_THAT(wp::taperedRadius(2.0, R, L, 1.0 - 0.1 / L), WithinRel(std::sqrt(R * R - (0.1 - R) * (0.1 - R)), 1e-12));
  // 2.5: spheres of depth 0.5 repeating every 2R along the stem.
  const double a = wp::taperedRadius(2.5, R, L, 0.3), b = wp::taperedRadius(2.5, R, L, 0.3 + 2 * R / L);
  CHECK_THAT(a, WithinRel(b, 1e-9));
  double lo = 1, hi = 0;
  for (int i = 0; i < 400; ++i) {
    const double r = wp::taperedRadius(2.5, R, L, 0.2 + i * 0.001);
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  CHECK_THAT(lo, WithinAbs(0.5 * R, 1e-3));
  CHECK_THAT(hi, WithinAbs(R, 1e-3));
}

TEST_CASE("flare widens only the lowest eighth of the trunk", "[wp]") {
  CHECK_THAT(wp::flareFactor(0.6, 0.0), WithinAbs(1.0 + 0.6 * 0.99, 1e-15));
  CHECK_THAT(wp::flareFactor(0.5, 1.0 / 16.0), WithinAbs(1.0 + 0.5 * 9.0 / 100.0, 1e-12));
  CHECK(wp::flareFactor(2.0, 0.125) == 1.0);
  CHECK(wp::flareFactor(2.0, 0.7) == 1.0);
}

TEST_CASE("lobes modulate the trunk around its axis", "[wp]") {
  const double pi = std::numbers::pi;
  CHECK_THAT(wp::lobeFactor(5, 0.1, pi / 10), WithinAbs(1.1, 1e-15));
  CHECK_THAT(wp::lobeFactor(5, 0.1, 3 * pi / 10), WithinAbs(0.9, 1e-15));
  CHECK_THAT(wp::lobeFactor(0, 0.1, 1.0), WithinAbs(1.0, 1e-15));
}

TEST_CASE("child counts follow Weber-Penn's formulas", "[wp]") {
  CHECK(wp::childCountOfTrunk(50) == 50);
  // Level-1 parent: Branches (0.2 + 0.8 (len / parentLen) / lengthChildMax).
  CHECK_THAT(wp::childCountOfLevel1(30, 3.0, 10.0, 0.4), WithinAbs(30 * (0.2 + 0.8 * 0.3 / 0.4), 1e-12));
  // Deeper: Branches (1 - 0.5 offset / parentLen).
  CHECK_THAT(wp::childCountOfDeeper(10, 1.0, 4.0), WithinAbs(8.75, 1e-12));
}

TEST_CASE("child lengths follow the crown shape and the parent", "[wp]") {
  SpeciesParams p;
  p.shape = 0;  // conical: ratio
  // A child at mid-height of the branching part of a 10 m trunk whose base 2 m is bare.
  const double len = wp::childLengthOfTrunk(p, 0.3, 10.0, 2.0, 6.0);
  CHECK_THAT(len, WithinAbs(10.0 * 0.3 * 0.5, 1e-12));
  CHECK_THAT(wp::childLengthOfDeeper(0.5, 4.0, 1.0), WithinAbs(0.5 * (4.0 - 0.6), 1e-12));
}

TEST_CASE("the pruning envelope contains the trunk axis and excludes the ground", "[wp]") {
  SpeciesParams p;
  p.baseSize = 0.1;
  p.pruneWidth = 0.5;
  p.pruneWidthPeak = 0.5;
  CHECK(wp::insideEnvelope(p, 10.0, 0.0, 0.0, 5.0));
  CHECK(wp::insideEnvelope(p, 10.0, 2.0, 0.0, 5.5));   // width there: 0.5 * 10 * ~1
  CHECK_FALSE(wp::insideEnvelope(p, 10.0, 6.0, 0.0, 5.5));
  CHECK_FALSE(wp::insideEnvelope(p, 10.0, 0.5, 0.0, 0.5));  // below the base of the crown
  CHECK_FALSE(wp::insideEnvelope(p, 10.0, 0.0, 0.0, 10.5)); // above the top
}
