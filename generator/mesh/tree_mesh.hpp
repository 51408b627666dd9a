#pragma once
// Skeleton -> one connected quad mesh (Nystad 4.3, 5.3, app. D).
#include <array>
#include <vector>

#include "growth/skeleton.hpp"
#include "mesh_options.hpp"
#include "quad_mesh.hpp"

namespace arbor {

// A cross section as built, for tests and tools: its corners, where it sits, its texture v.
struct MeshRing {
  int stem = -1;
  std::array<std::uint32_t, 4> vertices{};
  Vec3 center{0.0};
  double v = 0;
  double radius = 0;  // skeleton radius (the corners sit at limitCompensation times this)
  double arc = -1;    // arc length along its stem's skeleton (-1: a neck or sub-box ring, off the skeleton)
  bool inset = false; // a square inset in the parent's side: its corners carry the parent's texture
  bool alongNeck = false;  // a cross section of a neck's slabs (neck ports), made after the neck's far end
};

// A branch point as built: the parent stem, the children connected there and how.
struct MeshJoint {
  int node = -1;                 // skeleton node of the branch point (the first one, if several merged)
  int parentStem = -1;
  std::vector<int> childStems;
  Vec3 center{0.0};
  double radius = 0;             // parent radius there
  int subBoxes = 0;              // sides that several children shared
};

struct TreeMesh {
  QuadMesh mesh;
  std::vector<MeshRing> rings;    // in build order; a stem's rings are in order along it
  std::vector<MeshJoint> joints;
  std::vector<int> quadStem;      // per quad: the stem it belongs to (-1: the root hub)
  // Children left out because the mesh could join them only far from where they attach, or they run inside or
  // shallow along their parent, or attach just before it splits (MeshOptions::fakeDisplaced): drawn as fake
  // branches, like stubs.
  std::vector<int> fakedStems;
};

TreeMesh buildTreeMesh(const Skeleton& skeleton, const MeshOptions& options = {});

}  // namespace arbor
