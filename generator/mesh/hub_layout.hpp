#pragma once
// Ports for many trunks on one hub (a grass's tuft): the hub's top is a grid of cells, and each trunk leaves a port
// cell laid out as its axis lies where the necks meet the skeletons, in the same order, so that the necks from hub
// to skeleton run side by side as the skeleton's stems do, instead of crossing from sub-boxes crowded at the centre.
#include <array>
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

}  // namespace arbor
