#pragma once
// The limits every tree is held to, whatever grew it, and a model's estimate of a tree's size from its
// parameters alone: growth refuses a tree far past the limits before memory is spent on it, and the viewer
// shows the estimate beside its sliders.
#include <cstddef>
#include <string>
#include <vector>

namespace arbor {

// The limits every tree is held to (memory and time stay within about 2 GB and 10 s on two cores).
struct TreeLimits {
  std::size_t nodes = 1'500'000;   // skeleton nodes (counted as grown: every joint, stem base and branch point with its two neighbours)
  std::size_t leaves = 2'000'000;
  std::size_t quads = 2'500'000;   // mesh quads (also after subdivision for export)
  std::size_t modules = 0;         // L-system modules a derivation step may make, below the grammar's own `limit:` (0: that alone)
};

// How far from the origin a node of a skeleton or branch graph file may lie, on each axis (metres): a mesh's float
// positions still resolve 8 mm there; at 10,000 km they resolve a metre, and a twig's cross sections collapse.
inline constexpr double kMaxCoordinate = 100000.0;

// Consecutive points of a stem or graph closer than this fraction of the tree's size have no direction between them.
inline constexpr double kZeroLength = 1e-9;

// Why a coordinate (metres, on one axis) is out of the mesh's reach: past kMaxCoordinate or not finite; "" if within.
std::string outOfReach(double coordinate);

struct TreeEstimate {
  std::vector<double> stemsPerLevel;
  std::vector<double> nodesPerLevel;
  double stems = 0, nodes = 0, leaves = 0;
  double quads = 0;  // of the whole mesh, at the mesher's usual cross-section density
  std::string drivers;      // what makes the most stems, in the model's terms ("level 2: about 4100000 stems from ...")
  std::string lowerNodes;   // the model's advice when there are too many nodes ("lower Levels, Branches, ...")
  std::string lowerLeaves;  // and when there are too many leaves

  // The first limit the estimate passes, as a sentence naming what drives it and what to lower; "" if none.
  std::string excess(const TreeLimits& limits, double margin = 1.0) const;
};

}  // namespace arbor
