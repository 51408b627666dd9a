#pragma once
// Twigs whose quads cross another stem's where the two skeletons do not meet (mesh-made pairs, which issue 13
// wants gone), or whose neck runs through their own parent (issue 13 wants none), are taken out of the built mesh
// and drawn as fake branches; each one's port in its parent is closed again by the face the twig replaced.
#include <cstddef>
#include <vector>

#include "growth/skeleton.hpp"
#include "self_intersection.hpp"
#include "tree_mesh.hpp"

namespace arbor {

// A twig here: a meshed stem two or more levels from its trunk, with the clones it splits into, none of which bears
// a meshed child; or such a branch bearing only twigs, which go with it; or a level-1 one whose radius is at most a
// quarter of its parent's base radius (a palm's frond, a horsetail's whorl branch: the fake branch drawn for it
// looks the same from a few metres). Takes out, in up to two passes, the twig of each mesh-made pair with a
// quad in either stem's neck or first band, or on the tip of another stem bearing children (of two twigs, the one
// whose quad lies farther off its skeleton; a twig's neck through its own tube counts), and the twig whose neck or
// first band crosses its own parent, whatever made the pair (a twig running close along a curving parent, meshed as
// one straight band that cut across it: the tamarack file's 238 pairs at seeds 1-3), adds its stems to
// tree.fakedStems and returns how many twigs were taken out. A twig whose quads do not meet the rest of the mesh in
// exactly one four-sided port stays. The faces that close the first pass's ports are searched for the second.
// Normals are computed again if the mesh had them. With `left`, every meshed stem's neck is searched, not only
// twigs', and `left` receives the mesh-made pairs no twig could be taken out for; `begun`, with `left`: that search,
// begun while the mesh was built.
struct CrossingsLeft {
  std::size_t pairs = 0;   // mesh-made pairs left among those searched
  std::vector<int> necks;  // sorted: of each, the stem whose quad lies farther off its skeleton (its neck)
};
std::size_t fakeCrossingTwigs(TreeMesh& tree, const Skeleton& skeleton, CrossingsLeft* left = nullptr, PairsToMendSearch* begun = nullptr);

// Takes the listed stems (none a clone), each with its clones and descendants, out of the built mesh the same way,
// adding them to tree.fakedStems; all or, where one does not meet the rest in one four-sided port, none (false).
// Normals are left for the caller to compute once the mesh is final (the mesh builder takes twigs out twice).
bool takeOutTwigs(TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& stems);

}  // namespace arbor
