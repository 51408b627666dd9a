#pragma once
// Seeded random branch graphs for tests and measurements: the shapes other growth models hand the mesher.
#include <cstdint>

#include "branch_graph.hpp"

namespace arbor {

// Branches are chains of 2 to 8 internodes leaving existing nodes, one time in four several at one node (3 to 6
// children there in all), now and then several trunks on the root; up to six children per node. A branch leaves
// near-parallel to its parent or to an earlier sibling (5 to 15 degrees, a fifth each), backward (120 to 180
// degrees, one in seven), anywhere on the sphere (one in six) or at 30 to 80 degrees, and turns up to 15 degrees
// per internode. Internodes are 0.01 to 10 of their pipe-model radii long (log-uniform, three in four at least
// one radius), so most branches reach several parent radii out (14 % stubs at 400 internodes). One node in ten
// has a given radius (0.7 to 1.6 times the pipe model's) and one tip in four a leaf. Node ids are the indices.
BranchGraph randomBranchGraph(std::uint64_t seed, int nodes, const GraphOptions& options = {});

}  // namespace arbor
