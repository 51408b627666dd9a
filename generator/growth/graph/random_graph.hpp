#pragma once
// Seeded random branch graphs for tests and measurements: the shapes other growth models hand the mesher.
#include <cstdint>

#include "branch_graph.hpp"

namespace arbor {

// Up to six children per node (bursts of three to six are common), directions anywhere: near-parallel to the
// parent (within 10 degrees, a third of them), backward (120 to 180 degrees, one in eight) or uniform;
// internodes 0.01 to 10 of their pipe-model radii long (log-uniform); one node in ten has a given radius
// (0.7 to 1.6 times the pipe model's) and one tip in four a leaf. Node ids are the indices.
BranchGraph randomBranchGraph(std::uint64_t seed, int nodes, const GraphOptions& options = {});

}  // namespace arbor
