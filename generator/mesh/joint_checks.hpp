#pragma once
// Whether the mesh follows its skeleton at the joints: where each child's tube begins along its parent,
// and how far each stem's tip ring runs past the skeleton's tip.
#include <vector>

#include "tree_mesh.hpp"

namespace arbor {

struct ChildPlacement {
  int stem = -1, parentStem = -1;
  double offset = 0;  // child's first ring from its attachment, along the parent, in parent radii
  double attachArc = 0, parentRadius = 0;  // where on the parent it attaches (arc length) and its radius there
  // Attached before the parent's tube begins, i.e. where the parent is still inside (or against) its own
  // parent: the skeleton leaves the mesh no surface there, so the child joins the parent's first slab.
  bool beforeTube = false;
};

struct TipOvershoot {
  int stem = -1;
  double beyond = 0;     // tip ring past the skeleton tip, along the stem's end direction (metres)
  double tipRadius = 0;  // skeleton radius at the tip
  double length = 0;     // the stem's skeleton length
  double startRadius = 0;
};

// One entry per meshed child stem (not trunks, not clones: clones leave through the top of their split).
std::vector<ChildPlacement> childPlacements(const Skeleton& skeleton, const TreeMesh& tree);

// One entry per meshed stem that ends in a tip (split stems end in their clones).
std::vector<TipOvershoot> tipOvershoots(const Skeleton& skeleton, const TreeMesh& tree);

}  // namespace arbor
