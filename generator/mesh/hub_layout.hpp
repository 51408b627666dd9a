#pragma once
// Ports for many trunks on one hub (a grass's tuft): the hub's top is a grid of cells, and each trunk leaves a port
// cell laid out as its axis lies where the necks meet the skeletons, in the same order, so that the necks from hub
// to skeleton run side by side as the skeleton's stems do, instead of crossing from sub-boxes crowded at the centre;
// then trunks whose necks would still cut each other trade cells (untangleHub).
#include <array>
#include <functional>
#include <vector>

#include "growth/math.hpp"

namespace arbor {

struct HubLayout {
  int slots = 0;                         // port cells a side; the top is 2 slots + 1 cells a side
  std::vector<std::array<int, 2>> cell;  // per trunk: its port cell (i, j), both odd, so no two ports touch
};

// Port slots a side for n trunks: their axes spread over a disc, which covers pi/4 of the square grid.
int hubSlots(std::size_t n);

// How far across the points spread: the distance (the larger of |x| and |y|) from the centre within which nine in
// ten of them lie (0 for none).
double hubSpread(const std::vector<std::array<double, 2>>& points);

// wanted: each trunk's axis at the level where the necks meet their skeletons, across the hub (its centre at 0),
// in any unit; they are scaled so that nine in ten fall within the ports' span (hubSpread). Columns take them by x,
// rows within a column by y, each in the least-squares increasing slots, so no two swap sides.
HubLayout layOutHub(const std::vector<std::array<double, 2>>& wanted);

// A trunk's neck from its port to where it meets its skeleton: a cubic (Hermite) leaving along the port's normal and
// arriving along the skeleton (no kink where the tube begins), cut into `steps` bands about sixteen radii long.
struct HubNeck {
  Vec3 from{0.0}, t0{0.0}, to{0.0}, t1{0.0};  // ends, and the tangents there (each as long as the neck's chord)
  int steps = 1;
  Vec3 at(double f) const;
  Vec3 tangent(double f) const;  // not normalised (zero where the curve stalls)
};
HubNeck hubNeck(const Vec3& from, const Vec3& normal, const Vec3& to, const Vec3& direction, double radius);

// The neck trunk t would get from cell (i, j).
using NeckFromCell = std::function<HubNeck(std::size_t t, const std::array<int, 2>& cell)>;

// Trunks swapped between port cells, or moved to free ones, while that lowers how far their necks cut into each
// other: two skeletons close where their necks meet them, reached from ports on the wrong sides of each other, made
// the necks cross just below (the grid keeps the axes' order by columns, then rows, not their nearest pairs).
// reach[t]: how far trunk t's surface stands from its centre line at most; tube[t]: its skeleton's first stretch
// past the neck (a neck crossing the tube beside it counts too; two necks closing in on tubes that overlap anyway
// do not). Each pass moves every trunk whose neck comes too close to another to the port cell within two slots
// that lowers the total most, until none does or two million cuts have been weighed (wheat, barley and rush at
// seeds 1-3: mesh-made pairs between stalks 54 -> 21).
void untangleHub(HubLayout& layout, const NeckFromCell& neck, const std::vector<double>& reach, const std::vector<std::vector<Vec3>>& tube);

}  // namespace arbor
