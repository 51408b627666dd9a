#pragma once
// Choices the mesh stage leaves to the user (arbor generate --ring-spacing, --open-base, ...).
#include <cstddef>

#include "growth/tree_limits.hpp"

namespace arbor {

struct MeshOptions {
  double ringSpacing = 0.0;       // largest distance between cross sections, in local radii (0: off)
  double maxRingDistance = 0.0;   // and in metres (0: no absolute limit); uniform density for displacement
  bool openBase = false;          // leave the ring at the trunk base open (the mesh is otherwise closed)
  int levels = 0;                 // mesh stems of levels < this only (0: all); impostors draw the rest
  std::size_t maxQuads = TreeLimits{}.quads;  // refused beyond this (LimitError), before memory runs out
  // Control cross sections are enlarged so that the Catmull-Clark limit of a four-vertex ring (between
  // 0.648 and 0.667 of its control radius) has about the skeleton's radius.
  double limitCompensation = 1.0 / 0.657;
  // A thin child leaves through a square inset in its parent's side, as wide as a cross section of this many
  // child radii (0: through the whole side, as wide as the parent).
  double insetCollar = 1.0;
  // Children attached along a long neck (before their parent's tube begins) leave through that neck where they
  // attach; off: they crowd the parent's first slab, however far along that is.
  bool neckPorts = true;
  // A trunk clone bearing a child within four of its radii from the split has its collar at 0.4 of the usual distance
  // from its port, so that its tube and that child's slab begin near the split; off: as any clone's.
  bool nearEarlyCloneCollars = true;
  // A twig (no meshed child, nor any of its clones), or a branch two or more levels from its trunk that bears only
  // twigs, that its parent can join only more than half a parent radius (or half its own length) along from where it
  // attaches (where the parent has no tube yet, inside or against its own parent) is drawn, with its clones and
  // twigs, as fake branches on its skeleton (TreeMesh::fakedStems), as is a twig whose wood never clears its
  // parent's, or clears it only six parent radii along while at most half its parent's radius thick, or attaches at
  // most four parent radii before its parent splits, or attaches to a clone inside another clone of the same source
  // (as does such a branch), or (from level 2 on) passes within two radii of a neighbouring stem's axis at that
  // stem's joint, or whose first ring a pass left more than 1.5 parent radii along (the tree is meshed again
  // without it); a stem whose children are all faked is a twig, faked where its wood never clears its
  // parent's; off: meshed from that far slab, however far it is.
  bool fakeDisplaced = true;
  // With fakeDisplaced: a twig (from level 2 on, or thin at level 1, with its clones; or a branch bearing only
  // twigs, with them) in a mesh-made pair at a neck or first band (its own or the other stem's), or at the tip of a
  // stem bearing children, is taken out of the built mesh and drawn as fake branches (crossing_twigs.hpp).
  bool fakeCrossingTwigs = true;
  // The crossing-twig search on another core while the mesher builds (PairsToMendSearch): one-shot exports turn it on
  // (`arbor generate` and `grow`: the tupelo file 216 -> 195 ms). Off, it runs after the mesher: the viewer's tour
  // drew its frames some 6 ms slower after a build with the thread (lavapipe, more page faults in its frames).
  bool searchBesideMesher = false;
};

}  // namespace arbor
