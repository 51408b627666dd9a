#pragma once
// A rooted graph of internodes, as L-systems, space colonization and self-organizing trees grow them, and
// its conversion to the Skeleton the mesh stage takes: stems by pipe-model weight, pipe-model radii, short
// internodes merged, optional smoothing (docs/graph-format.md).
#include <cstdint>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "growth/skeleton.hpp"

namespace arbor {

struct BranchNode {
  Vec3 position{0.0};
  std::int32_t parent = -1;  // index of the parent node; -1 for the root (exactly one)
  double radius = 0;         // radius of the internode arriving here; <= 0: none given (pipe model)
  std::int64_t id = -1;      // the id errors name (as in the file); -1: the node's index
};

struct GraphLeaf {
  std::int32_t node = -1;    // index of the node it hangs from
  Vec3 position{0.0};        // base of the blade
  Vec3 direction{0.0, 0.0, 1.0};
  Vec3 normal{0.0};          // zero: the one facing the sky most
  double length = 0, width = 0;
  std::uint8_t kind = 0;     // LeafKind
};

struct BranchGraph {
  std::vector<BranchNode> nodes;
  std::vector<GraphLeaf> leaves;
};

struct GraphOptions {
  double exponent = 2.49;      // E of the pipe model r^E = sum r_i^E (the natural rules' default)
  double tipRadius = 0.01;     // radius of every tip without a given one, in the graph's units (metres)
  double maxDeviation = 0.25;  // merged segments keep every dropped node within this many radii of them
  double minSegment = 1.0;     // segments shorter than this many radii are merged (branch points stay)
  double maxSegment = 2.0;     // straight runs are merged into segments up to this many radii long
  int smoothingPasses = 0;     // Laplacian passes along each stem (branch points, root and tips stay)
  double smoothingWeight = 0.5;
  std::string species = "graph";
};

// A graph that is not a tree, or not a finite one: names the node id and what is allowed.
class GraphError : public InputError {
 public:
  using InputError::InputError;
};

// Throws GraphError (with `file` in it) unless there is exactly one root, every parent exists, there is no
// cycle, every value is finite, radii are not negative and no edge is shorter than 1e-9 of the tree's size.
void validateBranchGraph(const BranchGraph& graph, const std::string& file = "(graph)");

// Pipe-model radius of the internode arriving at each node: r^E = max(given^E, sum of the children's r^E),
// tips without a given radius at options.tipRadius, so radii never decrease toward the root.
std::vector<double> pipeRadii(const BranchGraph& graph, const GraphOptions& options);

// Validates, then converts. At each node the child whose subtree carries the largest pipe-model weight
// (r^E of its internode: the sum of its tips' r^E) continues the stem, ties (within 1e-9) going to the
// straightest; the others start new stems one level deeper. A root with several children, or whose trunk
// branches within two root radii of it, becomes a Root hub with one trunk per child. `nodeMap`, if given, receives per graph node its skeleton node, or -1 where
// the node was merged away.
Skeleton graphToSkeleton(const BranchGraph& graph, const GraphOptions& options = {},
                         std::vector<std::int32_t>* nodeMap = nullptr);

}  // namespace arbor
