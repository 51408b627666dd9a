#pragma once
// Every pair of quads of one mesh that intersect (beyond the corners and edges they share), found over a
// bounding-volume hierarchy, and whether each was made by the skeleton (Weber-Penn lets branches cross) or
// by the mesher (necks through their parent, folds, bands cutting others): the latter are bugs.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "growth/skeleton.hpp"
#include "quad_contact.hpp"
#include "quad_mesh.hpp"
#include "tree_mesh.hpp"

namespace arbor {

enum class PairOrigin : std::uint8_t { Unclassified, Skeleton, Mesh };

// How the two quads' stems are related (Hub: one of them belongs to no stem, the root hub or an OBJ).
enum class StemRelation : std::uint8_t { Hub, Same, ParentChild, CloneSource, Siblings, Other };

struct QuadPairHit {
  std::uint32_t a = 0, b = 0;  // quad indices, a < b
  int stemA = -1, stemB = -1;  // -1: no stem (hub, or no skeleton given)
  Vec3 point{0.0};             // a point where the two meet
  QuadContact contact = QuadContact::Apart;
  PairOrigin origin = PairOrigin::Unclassified;
  StemRelation relation = StemRelation::Hub;
  double reachA = 0, reachB = 0;  // the point's distance from each stem's skeleton axis, in its radii there (or
                                  // the radius its quad was built for, when larger: tips)
  bool shallowJoint = false;      // mesh-made with a quad in the neck or first band of a child leaving at under 34
                                  // degrees (shallowJoint in stem_capsules.hpp)
  bool throughParent = false;     // a child's quad in its neck or first band against its own parent's
};

struct SelfIntersectionReport {
  std::size_t quads = 0;
  std::size_t pairs = 0;
  std::size_t skeletonMade = 0;
  std::size_t meshMade = 0;
  std::size_t folds = 0;          // pairs sharing an edge
  std::size_t neckCrossings = 0;  // a child's quad against its own parent's (or a clone's against its source's)
  std::size_t necksThroughParent = 0;  // of those, a child's quad in its neck or first band (throughParent); the rest
                                       // lie farther along the child, where its skeleton runs back into the parent or
                                       // close along it
  std::size_t meshMadeAtShallowJoints = 0;  // mesh-made pairs with shallowJoint set
  bool classified = false;        // false for a bare mesh: origins unknown
  double milliseconds = 0;
  std::vector<QuadPairHit> hits;  // sorted by (a, b)
};

// All intersecting pairs over a BVH of the quads' boxes; origins left Unclassified. Runs on every core.
std::vector<QuadPairHit> findIntersectingQuads(const QuadMesh& mesh);

// The same by testing every pair (O(n^2)): the reference the BVH is tested against.
std::vector<QuadPairHit> findIntersectingQuadsBruteForce(const QuadMesh& mesh);

// A bare mesh (an OBJ file): pairs, folds and time; nothing classified.
SelfIntersectionReport checkSelfIntersections(const QuadMesh& mesh);

// A tree's mesh with its skeleton: each pair classified, skeleton-made when the point lies within both
// stems' capsules (past where each leaves the stem it grows from; radii at least those the quads were built
// for), or, a child's collar standing for its parent's surface, when the other stem crosses that parent there;
// mesh-made otherwise; folds and pairs within one stem are always mesh-made.
SelfIntersectionReport checkSelfIntersections(const TreeMesh& tree, const Skeleton& skeleton);

// The pairs a mesher must mend, mesh-made ones and necks through their own parent (throughParent, whatever made
// them), between a quad of a stem flagged in `stems` (one flag per skeleton stem) and another quad
// (of another stem, or of its own: a neck through its own tube), where one of the two lies in its stem's neck or
// first band, or on the tip (last band and cap) of a stem bearing children, classified as above, sorted. Left
// out: pairs of a clone with its source (which it leaves through its end), or sharing a corner (the quads around
// every port: most of the work), and necks crowded by other stems (a thicket the skeleton made, where the search
// would grow with the square of the stems). Over a BVH of runs of each stem's quads, on every core for a large
// mesh, keeping only those pairs as it goes: cheap enough to run after every build.
std::vector<QuadPairHit> pairsToMendOf(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<bool>& stems);

// How much of a mesh being built is final: its first `quads` quads, `vertices` vertices and `rings` cross sections.
struct MeshProgress {
  std::size_t quads = 0, vertices = 0, rings = 0;
};

// pairsToMendOf with every stem flagged, fed a mesh while the mesher builds it: the mesher only appends quads,
// vertices and cross sections, so the parts it has finished are searched on another core while it builds the rest.
class PairsToMendSearch {
 public:
  PairsToMendSearch();
  ~PairsToMendSearch();
  PairsToMendSearch(PairsToMendSearch&&) noexcept;
  PairsToMendSearch& operator=(PairsToMendSearch&&) noexcept;

  // The mesh up to `settled` is final, and so is every stem with a quad or cross section in it: searches that part
  // against itself and the parts before it, on this thread. A part that breaks that promise (a stem's cross
  // sections in two parts, or a cross section on an earlier part's vertex) makes finish() search the whole mesh.
  void advance(const TreeMesh& tree, const Skeleton& skeleton, const MeshProgress& settled);
  // The whole mesh is in: pairsToMendOf(tree, skeleton, every stem), the rest searched on every core.
  std::vector<QuadPairHit> finish(const TreeMesh& tree, const Skeleton& skeleton);
  // Whether parts were searched before finish() and kept advance()'s promise (else finish() searched the whole mesh).
  bool searchedInParts() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
};
// The pairs to mend (as above) between one of `quads` (sorted; a few: the faces that closed twigs' ports) and any
// other quad, classified as above, sorted.
std::vector<QuadPairHit> pairsToMendWith(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<std::uint32_t>& quads);
// Of a pair of a child and its own parent, whether stemA is the child.
bool childIsA(const QuadPairHit& h, const Skeleton& skeleton);
// The number the mesher must bring to 0: pairs of quads that intersect where the skeleton does not.
std::size_t meshMadeIntersections(const TreeMesh& tree, const Skeleton& skeleton);

const char* pairOriginName(PairOrigin origin);
const char* stemRelationName(StemRelation relation);
const char* quadContactName(QuadContact contact);

}  // namespace arbor
