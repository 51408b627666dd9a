#include "self_intersection.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "common/parallel.hpp"
#include "quad_bvh.hpp"
#include "stem_capsules.hpp"

namespace arbor {

namespace {

// A point within this many radii of both stems' axes lies where the skeleton puts wood of both: the surface
// sits at ~1.52 r (limit compensation); the rest allows for bands drawn as chords between rings.
constexpr double kWoodReach = 1.75;
// The mesh's corners sit at 1.52 r: capsules that big overlapping make crossing cages, and the crossing of
// two branches spreads over their joints; a point within twice the two radii of such an overlap is theirs.
constexpr double kCageReach = 1.52;
constexpr double kOverlapNear = 2.0;
// Fewer quads than this are checked on one thread: starting threads would cost more than it saves.
constexpr std::size_t kThreadsFrom = 20000;
// A stem whose neck (or tip) runs meet more runs of other stems than this lies in a thicket the skeleton made (a
// fuzzed palm of 64 trunks: a median of 740, and a million crossing quads); on every preset and Arbaro file at
// most 74 (a willow trunk clone's tip; 34 by necks alone).
constexpr std::uint32_t kCrowdedNeck = 128;
// A few bands of one stem (4 quads a band) make one box of pairsToMendOf's hierarchy.
constexpr std::uint32_t kRunQuads = 16;

QuadCorners cornersOf(const QuadMesh& mesh, std::uint32_t f) {
  QuadCorners c;
  c.index = mesh.quads[f];
  for (std::size_t k = 0; k < 4; ++k) c.p[k] = Vec3(mesh.positions[c.index[k]]);
  return c;
}

QuadBox boxOf(const QuadMesh& mesh, std::uint32_t f) {
  const auto& q = mesh.quads[f];
  QuadBox b{mesh.positions[q[0]], mesh.positions[q[0]]};
  for (std::size_t k = 1; k < 4; ++k) {
    b.lo = glm::min(b.lo, mesh.positions[q[k]]);
    b.hi = glm::max(b.hi, mesh.positions[q[k]]);
  }
  return b;
}

// Quads a < b with their corners: a hit when they meet.
void testPair(const QuadCorners& ca, const QuadCorners& cb, std::uint32_t a, std::uint32_t b, std::vector<QuadPairHit>& hits) {
  if (auto x = quadsMeet(ca, cb)) {
    QuadPairHit h;
    h.a = a;
    h.b = b;
    h.point = *x;
    h.contact = quadContact(ca.index, cb.index);
    hits.push_back(h);
  }
}

void testPair(const QuadMesh& mesh, std::uint32_t a, std::uint32_t b, std::vector<QuadPairHit>& hits) {
  testPair(cornersOf(mesh, a), cornersOf(mesh, b), a, b, hits);
}

// The radius the mesher built a quad for (its corners' radius attribute): tips keep a third of the ring
// before where the skeleton's radius runs out to 0.
double builtRadius(const QuadMesh& mesh, std::uint32_t f, bool perVertexRadius) {
  if (!perVertexRadius) return 0.0;
  double r = 0.0;
  for (std::uint32_t v : mesh.quads[f]) r = std::max(r, static_cast<double>(mesh.radius[v]));
  return r;
}

void sortHits(std::vector<QuadPairHit>& hits) {
  std::sort(hits.begin(), hits.end(), [](const QuadPairHit& x, const QuadPairHit& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
}

StemRelation relationOf(const Skeleton& skeleton, int a, int b) {
  if (a < 0 || b < 0 || a >= static_cast<int>(skeleton.stems.size()) || b >= static_cast<int>(skeleton.stems.size()))
    return StemRelation::Hub;
  if (a == b) return StemRelation::Same;
  const SkeletonStem& sa = skeleton.stems[static_cast<std::size_t>(a)];
  const SkeletonStem& sb = skeleton.stems[static_cast<std::size_t>(b)];
  if (sa.cloneOf == b || sb.cloneOf == a) return StemRelation::CloneSource;
  if ((sa.parentStem == b && sa.cloneOf < 0) || (sb.parentStem == a && sb.cloneOf < 0)) return StemRelation::ParentChild;
  if (sa.attachNode >= 0 && sa.attachNode == sb.attachNode) return StemRelation::Siblings;
  return StemRelation::Other;
}

// Whether a pair is a child's neck (or first band) through its own parent: the child's quad is on `neck`.
template <class Flags>
bool neckThroughParent(const Skeleton& skeleton, const Flags& neck, const QuadPairHit& h) {
  if (h.relation != StemRelation::ParentChild) return false;
  return neck[childIsA(h, skeleton) ? h.a : h.b];
}

// Both stems' skeletons reach the point, or their wood (at the size of the mesh's corners) overlaps within two
// radii of it: then the branches themselves cross there, and so must their surfaces, necks and collars.
// (`overlaps` yields them: worked out only where the skeletons alone do not settle it.)
template <class Overlaps>
bool woodMeets(Overlaps&& overlaps, const Vec3& point, double reachA, double reachB) {
  return (reachA <= kWoodReach && reachB <= kWoodReach) || distanceToOverlap(overlaps(), point) <= kOverlapNear;
}

// x crossing the collar of a child of p is x crossing p only if x is not p, nor p's parent or clone (those count
// as kin, below). (x may be another child of p: its capsules start where it leaves p's wood, so its own joint never
// counts as crossing p.)
bool unrelatedTo(const Skeleton& skeleton, int x, int p) {
  if (x == p || x < 0) return false;
  const SkeletonStem& sx = skeleton.stems[static_cast<std::size_t>(x)];
  if (sx.parentStem == p && sx.cloneOf < 0) return true;
  return relationOf(skeleton, x, p) == StemRelation::Other && grownFrom(skeleton, x) != p;
}

// x and p are clones of one split, or one is the other's clone: past where each has left the other's wood, two
// clones grown into each other cross as any two stems do (the willows' trunk clones, split at a few degrees).
bool cloneKin(const Skeleton& skeleton, int x, int p) {
  if (x < 0 || p < 0 || x == p) return false;
  const StemRelation r = relationOf(skeleton, x, p);
  const int sx = skeleton.stems[static_cast<std::size_t>(x)].cloneOf, sp = skeleton.stems[static_cast<std::size_t>(p)].cloneOf;
  return r == StemRelation::CloneSource || (r == StemRelation::Siblings && sx >= 0 && sx == sp);
}

// A key for a pair of stems (x, y in that order) in the classifier's caches.
std::uint64_t keyOf(int x, int y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) | static_cast<std::uint32_t>(y);
}

// The value cached under `key`, made the first time it is asked for.
template <typename Map, typename Make>
const typename Map::mapped_type& cached(Map& map, std::uint64_t key, Make&& make) {
  const auto it = map.find(key);
  if (it != map.end()) return it->second;
  return map.emplace(key, make()).first->second;
}

// Sorts pairs into skeleton-made and mesh-made, building a stem's capsules the first time a pair needs them: a
// check of a few stems' quads then costs what those stems do, not the whole tree's.
class PairClassifier {
 public:
  // The mesh's sizes are read here, once: a mesh still being built (PairsToMendSearch) grows while it is classified.
  PairClassifier(const TreeMesh& tree, const Skeleton& skeleton)
      : tree_(tree), skeleton_(skeleton), stemsKnown_(tree.quadStem.size()),
        perVertexRadius_(tree.mesh.radius.size() == tree.mesh.positions.size()), necks_(skeleton.stems.size()), wood_(skeleton.stems.size()) {}
  // A mesh being built: per-vertex radii, and stems known for the quads searched.
  PairClassifier(const TreeMesh& tree, const Skeleton& skeleton, std::size_t quads)
      : tree_(tree), skeleton_(skeleton), stemsKnown_(quads), perVertexRadius_(true), necks_(skeleton.stems.size()), wood_(skeleton.stems.size()) {}

  void classify(QuadPairHit& h) {
    h.stemA = h.a < stemsKnown_ ? tree_.quadStem[h.a] : -1;
    h.stemB = h.b < stemsKnown_ ? tree_.quadStem[h.b] : -1;
    h.relation = relationOf(skeleton_, h.stemA, h.stemB);
    const bool candidate = h.contact != QuadContact::Edge && h.relation != StemRelation::Hub && h.relation != StemRelation::Same;
    if (h.relation != StemRelation::Hub) {
      h.reachA = stemReach(capsules(h.stemA, h.stemB, h.stemA), h.point, builtRadius(tree_.mesh, h.a, perVertexRadius_));
      h.reachB = stemReach(capsules(h.stemA, h.stemB, h.stemB), h.point, builtRadius(tree_.mesh, h.b, perVertexRadius_));
    }
    bool meets = candidate && woodMeets([&]() -> const auto& { return overlaps(h.stemA, h.stemB); }, h.point, h.reachA, h.reachB);
    // A child's collar lies on its parent's surface (a clone's on its source's end): a stem crossing that wood crosses the collar too.
    if (candidate && !meets) {
      for (const auto& [x, fx, y] : {std::tuple{h.stemA, h.a, h.stemB}, std::tuple{h.stemB, h.b, h.stemA}}) {
        const int py = grownFrom(skeleton_, y);
        if (py < 0) continue;
        const bool kin = cloneKin(skeleton_, x, py);
        // x may be py's own parent: py's surface, and the collar on it, cross x where py's wood past its neck does.
        const bool grandparent = relationOf(skeleton_, x, py) == StemRelation::ParentChild && skeleton_.stems[static_cast<std::size_t>(py)].parentStem == x;
        if (kin || grandparent || unrelatedTo(skeleton_, x, py)) meets = meets || woodMeetsAt(x, py, kin, h.point, builtRadius(tree_.mesh, fx, perVertexRadius_));
      }
    }
    // Both quads stand for their parents' surfaces where the two parents' wood overlaps (two clones grown into each
    // other, two branches crossing where each bears a child): the children cross there as their parents do.
    if (candidate && !meets) {
      const int px = grownFrom(skeleton_, h.stemA), py = grownFrom(skeleton_, h.stemB);
      const bool kin = px >= 0 && py >= 0 && cloneKin(skeleton_, px, py);
      if (px >= 0 && py >= 0 && (kin || unrelatedTo(skeleton_, px, py) || unrelatedTo(skeleton_, py, px))) meets = woodMeetsAt(px, py, kin, h.point, 0.0);
    }
    h.origin = meets ? PairOrigin::Skeleton : PairOrigin::Mesh;
  }

 private:
  // Whether the wood of stems x and y meets at `point` (kin: clones of one split, each seen from where it has left
  // the other's wood); minX: the radius x's quad there was built for.
  bool woodMeetsAt(int x, int y, bool kin, const Vec3& point, double minX) {
    const std::vector<Capsule>& cx = kin ? kinCapsules(x, y) : capsules(x, y, x);
    const std::vector<Capsule>& cy = kin ? kinCapsules(y, x) : capsules(x, y, y);
    return woodMeets([&]() -> const auto& { return kin ? kinOverlaps(x, y) : overlaps(x, y); }, point, stemReach(cx, point, minX), stemReach(cy, point));
  }

  // Where the wood of stems x and y overlaps (their capsules as seen against each other), once per pair: a
  // crossing of two branches makes many pairs of quads.
  const std::vector<WoodOverlap>& overlaps(int x, int y) {
    return cached(overlaps_, keyOf(std::min(x, y), std::max(x, y)), [&] { return woodOverlaps(capsules(x, y, x), capsules(x, y, y), kCageReach); });
  }

  // Two clone kin's capsules, each from where it has left the other's wood, and where they overlap, once per pair.
  const std::vector<Capsule>& kinCapsules(int of, int other) {
    return cached(kin_, keyOf(of, other), [&] { return capsulesOutOf(skeleton_, of, other); });
  }
  const std::vector<WoodOverlap>& kinOverlaps(int x, int y) {
    return cached(kinOverlaps_, keyOf(std::min(x, y), std::max(x, y)), [&] { return woodOverlaps(kinCapsules(x, y), kinCapsules(y, x), kCageReach); });
  }

  // The capsules of `of` (x or y) as seen against the other: a child's neck overlaps its own parent by
  // construction; against any other stem it is the child's wood.
  const std::vector<Capsule>& capsules(int x, int y, int of) {
    const StemRelation r = relationOf(skeleton_, x, y);
    const bool neck = r == StemRelation::ParentChild || r == StemRelation::CloneSource;
    auto& cache = neck ? necks_ : wood_;
    auto& slot = cache[static_cast<std::size_t>(of)];
    if (!slot) slot = stemCapsulesOf(skeleton_, of, neck ? StemStart::ClearOfParent : StemStart::OutOfParentWood);
    return *slot;
  }

  const TreeMesh& tree_;
  const Skeleton& skeleton_;
  std::size_t stemsKnown_;  // quads with a stem in tree_.quadStem
  bool perVertexRadius_;
  std::vector<std::optional<std::vector<Capsule>>> necks_, wood_;
  std::unordered_map<std::uint64_t, std::vector<WoodOverlap>> overlaps_, kinOverlaps_;
  std::unordered_map<std::uint64_t, std::vector<Capsule>> kin_;
};

// Tests quads f and g (with their corners) and keeps the pair in `found` only when they meet and the mesh made it,
// or it is a child's neck through its own parent (throughParent(h) says, once classified); the lower index goes
// first, as every search reports pairs.
template <class ThroughParent>
void keepIfToMend(const QuadCorners& cf, const QuadCorners& cg, std::uint32_t f, std::uint32_t g, PairClassifier& classifier,
                  ThroughParent&& throughParent, std::vector<QuadPairHit>& found) {
  const std::size_t before = found.size();
  if (f < g) testPair(cf, cg, f, g, found);
  else testPair(cg, cf, g, f, found);
  if (found.size() == before) return;
  QuadPairHit& h = found.back();
  classifier.classify(h);
  h.throughParent = throughParent(h);
  if (h.origin != PairOrigin::Mesh && !h.throughParent) found.pop_back();
}

// Per quad, whether one of its corners lies on a cross section of its own stem marked in `ringOf` (per vertex, the
// stem whose marked cross section it is on; -1 for none).
bool onOwnRing(const std::array<std::uint32_t, 4>& q, int stem, const std::vector<int>& ringOf) {
  return stem >= 0 && (ringOf[q[0]] == stem || ringOf[q[1]] == stem || ringOf[q[2]] == stem || ringOf[q[3]] == stem);
}

std::vector<bool> quadsOnOwnRings(const TreeMesh& tree, const std::vector<int>& ringOf) {
  std::vector<bool> on(tree.mesh.quads.size(), false);
  // One write a quad: a bit of vector<bool> read and written per corner cost the tupelo file 1.2 % of its instructions.
  for (std::size_t f = 0; f < on.size() && f < tree.quadStem.size(); ++f) on[f] = onOwnRing(tree.mesh.quads[f], tree.quadStem[f], ringOf);
  return on;
}

// Whether a stem's cross section, met in build order, is one of its neck's (pastNeck: per stem, whether one on its
// skeleton came before).
bool neckRing(const MeshRing& ring, std::vector<bool>& pastNeck) {
  const auto stem = static_cast<std::size_t>(ring.stem);
  if (pastNeck.size() <= stem) pastNeck.resize(stem + 1, false);
  if (ring.arc >= 0.0) pastNeck[stem] = true;
  return !pastNeck[stem] || ring.alongNeck;
}

// Per quad, whether it lies in its own stem's neck or first band: a corner on one of the stem's cross sections
// before its first on the skeleton (an inset or a collar), or on a cross section of its neck's slabs (neck ports,
// made after the neck's far end: the tupelo file's 6 mesh-made pairs at seed 3 were a branch's neck slab through a
// twig, unsearched).
std::vector<bool> neckQuads(const TreeMesh& tree) {
  std::vector<int> neckOf(tree.mesh.vertexCount(), -1);
  std::vector<bool> pastNeck;
  for (const MeshRing& ring : tree.rings) {
    if (ring.stem < 0 || !neckRing(ring, pastNeck)) continue;
    for (std::uint32_t v : ring.vertices) neckOf[v] = ring.stem;
  }
  return quadsOnOwnRings(tree, neckOf);
}

SelfIntersectionReport summarise(std::vector<QuadPairHit> hits, std::size_t quads, bool classified) {
  SelfIntersectionReport r;
  r.quads = quads;
  r.pairs = hits.size();
  r.classified = classified;
  for (const QuadPairHit& h : hits) {
    r.folds += h.contact == QuadContact::Edge ? 1 : 0;
    r.neckCrossings += h.relation == StemRelation::ParentChild || h.relation == StemRelation::CloneSource ? 1 : 0;
    r.skeletonMade += h.origin == PairOrigin::Skeleton ? 1 : 0;
    r.meshMade += h.origin == PairOrigin::Mesh ? 1 : 0;
    r.meshMadeAtShallowJoints += h.shallowJoint ? 1 : 0;
    r.necksThroughParent += h.throughParent ? 1 : 0;
  }
  r.hits = std::move(hits);
  return r;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

namespace {

// The hits of all threads together, sorted.
std::vector<QuadPairHit> gathered(std::vector<std::vector<QuadPairHit>>& found) {
  std::vector<QuadPairHit> hits;
  for (auto& f : found) hits.insert(hits.end(), f.begin(), f.end());
  sortHits(hits);
  return hits;
}

// visit(i, j, t) on thread t for every two items of the BVH whose boxes overlap, on `threads` threads.
template <class Visit>
void overlappingPairs(const QuadBvh& bvh, unsigned threads, Visit&& visit) {
  // Many more tasks than threads, taken in turn: subtrees differ widely in work.
  const std::vector<NodePair> tasks = splitOverlapTasks(bvh, threads == 1 ? 1 : 64 * threads);
  inParallel(tasks.size(), threads, [&](std::size_t k, unsigned t) {
    forEachOverlappingPair(bvh, tasks[k], [&](std::uint32_t i, std::uint32_t j) { visit(i, j, t); });
  });
}

}  // namespace

std::vector<QuadPairHit> findIntersectingQuads(const QuadMesh& mesh) {
  const auto n = static_cast<std::uint32_t>(mesh.quads.size());
  std::vector<QuadBox> boxes(n);
  for (std::uint32_t f = 0; f < n; ++f) boxes[f] = boxOf(mesh, f);
  std::vector<std::vector<QuadPairHit>> found(threadsFor(n, kThreadsFrom));
  overlappingPairs(buildQuadBvh(boxes), static_cast<unsigned>(found.size()), [&](std::uint32_t a, std::uint32_t b, unsigned t) {
    testPair(mesh, std::min(a, b), std::max(a, b), found[t]);
  });
  return gathered(found);
}

std::vector<QuadPairHit> findIntersectingQuadsBruteForce(const QuadMesh& mesh) {
  const auto n = static_cast<std::uint32_t>(mesh.quads.size());
  std::vector<QuadBox> boxes(n);
  for (std::uint32_t f = 0; f < n; ++f) boxes[f] = boxOf(mesh, f);
  std::vector<QuadPairHit> hits;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (boxes[a].overlaps(boxes[b])) testPair(mesh, a, b, hits);
  return hits;
}

SelfIntersectionReport checkSelfIntersections(const QuadMesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  SelfIntersectionReport r = summarise(findIntersectingQuads(mesh), mesh.quads.size(), false);
  r.milliseconds = millisecondsSince(start);
  return r;
}

SelfIntersectionReport checkSelfIntersections(const TreeMesh& tree, const Skeleton& skeleton) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<QuadPairHit> hits = findIntersectingQuads(tree.mesh);
  PairClassifier classifier(tree, skeleton);
  for (QuadPairHit& h : hits) classifier.classify(h);
  // Where issue 13's two joint floors meet: a shallow child's neck must leave its skeleton (docs/mesh.md).
  const std::vector<bool> neck = neckQuads(tree);
  std::vector<bool> shallow(skeleton.stems.size(), false);
  for (std::size_t s = 0; s < shallow.size(); ++s) shallow[s] = shallowJoint(skeleton, static_cast<int>(s));
  auto inShallowNeck = [&](std::uint32_t quad, int stem) { return stem >= 0 && neck[quad] && shallow[static_cast<std::size_t>(stem)]; };
  for (QuadPairHit& h : hits) {
    h.shallowJoint = h.origin == PairOrigin::Mesh && (inShallowNeck(h.a, h.stemA) || inShallowNeck(h.b, h.stemB));
    h.throughParent = neckThroughParent(skeleton, neck, h);
  }
  SelfIntersectionReport r = summarise(std::move(hits), tree.mesh.quads.size(), true);
  r.milliseconds = millisecondsSince(start);
  return r;
}

// ---- the pairs to mend, searched part by part ----

struct PairsToMendSearch::State {
  // One stem's consecutive quads, all in its neck (and first band) or none, all on a bearing tip or none: a BVH over
  // them is a tenth the size of one over the quads, and pairs within a stem (most overlapping boxes: neighbours) or
  // away from any neck are skipped whole.
  struct Run {
    std::uint32_t begin = 0, end = 0;
    int stem = -1;
    bool neck = false, tip = false;
  };
  // Runs settled together, with a hierarchy over their boxes (items counted from firstRun).
  struct Part {
    std::uint32_t firstRun = 0, endRun = 0;
    QuadBvh bvh;
    QuadBox box;
  };
  // A pair kept before every part was in, with the two runs it was found between.
  struct Found {
    QuadPairHit hit;
    std::uint32_t x = 0, y = 0;
  };
  std::vector<bool> stems;  // flagged: pairs with one of these are searched
  bool whole = true;        // every part kept advance()'s promise
  MeshProgress done;
  std::vector<int> neckOf, tipOf;  // per vertex: the stem whose neck (or bearing tip) cross section it is on, or -1
  std::vector<bool> pastNeck;      // per stem: a cross section on its skeleton seen
  std::vector<int> ringPart;       // per stem: the part its cross sections came in, or -1
  std::vector<std::size_t> lastArcRing;  // per stem, within settleRings: its last cross section on its skeleton
  std::vector<bool> bearing;       // per stem: it has children
  std::vector<QuadBox> quadBoxes;
  std::vector<std::uint8_t> neck, tip;  // per quad: in its stem's neck (or first band), on a bearing tip
  std::vector<Run> runs;
  std::vector<QuadBox> runBoxes;
  std::uint32_t closedRuns = 0;  // runs that no later quad extends, all in parts
  std::vector<Part> parts;
  std::size_t partsAdvanced = 0;  // of those, searched by advance()
  std::vector<std::uint32_t> met;  // per stem: how many runs of others its neck (or tip) meets
  std::vector<Found> found;

  State(const Skeleton& skeleton, std::vector<bool> flagged)
      : stems(std::move(flagged)), pastNeck(skeleton.stems.size(), false), ringPart(skeleton.stems.size(), -1),
        bearing(skeleton.stems.size(), false), met(skeleton.stems.size(), 0) {
    for (const SkeletonStem& st : skeleton.stems) {
      if (st.parentStem >= 0 && static_cast<std::size_t>(st.parentStem) < bearing.size()) bearing[static_cast<std::size_t>(st.parentStem)] = true;
    }
  }

  bool marked(int stem) const { return stem >= 0 && static_cast<std::size_t>(stem) < stems.size() && stems[static_cast<std::size_t>(stem)]; }
  bool crowded(int stem) const { return stem >= 0 && met[static_cast<std::size_t>(stem)] > kCrowdedNeck; }
  // A run's neck and tip, or none once its stem is crowded (`crowding`): a thicket the skeleton made is searched no
  // more, which keeps the search linear in the stems where it would grow with their square.
  bool neckLive(const Run& r, bool crowding) const { return r.neck && !(crowding && crowded(r.stem)); }
  bool tipLive(const Run& r, bool crowding) const { return r.tip && !(crowding && crowded(r.stem)); }

  // Whether two runs' quads are to be tested: of two stems, one flagged, with a quad in a neck or a bearing tip.
  // Fewer pairs pass with crowding than without, and fewer as more stems are crowded.
  bool searched(const Skeleton& skeleton, const Run& x, const Run& y, bool crowding) const {
    if (x.stem < 0 || y.stem < 0 || !(marked(x.stem) || marked(y.stem))) return false;
    const bool xn = neckLive(x, crowding), yn = neckLive(y, crowding);
    if (!(xn || yn || tipLive(x, crowding) || tipLive(y, crowding))) return false;
    if (x.stem == y.stem) return xn || yn;  // a neck through its own stem's tube
    const StemRelation relation = relationOf(skeleton, x.stem, y.stem);
    if (relation == StemRelation::CloneSource) return false;
    // Against its parent, only a child's own neck: the parent's long neck runs along its children's tubes.
    return relation != StemRelation::ParentChild || (skeleton.stems[static_cast<std::size_t>(x.stem)].parentStem == y.stem ? xn : yn);
  }
  // A run's neck against itself: its own neck folding through itself.
  bool searchedAlone(const Run& r, bool crowding) const { return neckLive(r, crowding) && marked(r.stem); }

  // The cross sections up to `to.rings`: which vertices lie on necks and bearing tips. A stem's cross sections all
  // come in one part, on vertices of that part: else an earlier part's quads would change.
  void settleRings(const TreeMesh& tree, const MeshProgress& to) {
    neckOf.resize(to.vertices, -1);
    tipOf.resize(to.vertices, -1);
    const int part = static_cast<int>(parts.size());
    std::vector<int> touched;  // stems with a cross section on their skeleton here, and the last such of each
    lastArcRing.resize(ringPart.size(), SIZE_MAX);
    for (std::size_t r = done.rings; r < to.rings; ++r) {
      const MeshRing& ring = tree.rings[r];
      if (ring.stem < 0) continue;
      const auto stem = static_cast<std::size_t>(ring.stem);
      bool inPart = stem < ringPart.size();
      for (std::uint32_t v : ring.vertices) inPart = inPart && v >= done.vertices && v < to.vertices;
      if (!inPart || (ringPart[stem] >= 0 && ringPart[stem] != part)) {
        whole = false;
        return;
      }
      ringPart[stem] = part;
      if (neckRing(ring, pastNeck))
        for (std::uint32_t v : ring.vertices) neckOf[v] = ring.stem;
      if (ring.arc >= 0.0) {
        if (lastArcRing[stem] == SIZE_MAX) touched.push_back(ring.stem);
        lastArcRing[stem] = r;
      }
    }
    std::sort(touched.begin(), touched.end());  // a later stem's tip wins a shared corner, as over the whole mesh
    for (int s : touched) {
      const auto stem = static_cast<std::size_t>(s);
      if (bearing[stem])
        for (std::uint32_t v : tree.rings[lastArcRing[stem]].vertices) tipOf[v] = s;
      lastArcRing[stem] = SIZE_MAX;  // clean for the next part: one array for all parts, not one a part
    }
  }

  // The quads up to `to.quads`: their boxes, flags and runs (the last run stays open for the next quads).
  void settleQuads(const TreeMesh& tree, const MeshProgress& to) {
    const QuadMesh& mesh = tree.mesh;
    for (auto f = static_cast<std::uint32_t>(done.quads); f < to.quads; ++f) {
      const int stem = tree.quadStem[f];
      const auto& q = mesh.quads[f];
      bool known = true;
      for (std::uint32_t v : q) known = known && v < to.vertices;
      if (!known) {
        whole = false;
        return;
      }
      quadBoxes.push_back(boxOf(mesh, f));
      const bool inNeck = onOwnRing(q, stem, neckOf), onTip = onOwnRing(q, stem, tipOf);
      neck.push_back(inNeck ? 1 : 0);
      tip.push_back(onTip ? 1 : 0);
      if (runs.empty() || runs.back().stem != stem || runs.back().neck != inNeck || runs.back().tip != onTip ||
          runs.back().end - runs.back().begin == kRunQuads) {
        runs.push_back(Run{f, f, stem, inNeck, onTip});
        runBoxes.push_back(quadBoxes[f]);
      }
      runs.back().end = f + 1;
      runBoxes.back().lo = glm::min(runBoxes.back().lo, quadBoxes[f].lo);
      runBoxes.back().hi = glm::max(runBoxes.back().hi, quadBoxes[f].hi);
    }
    done = to;
  }

  // The runs closed since the last part (all of them at the end) as a new part; false when there are none.
  bool closePart(bool last) {
    const auto end = static_cast<std::uint32_t>(last || runs.empty() ? runs.size() : runs.size() - 1);
    if (end <= closedRuns) return false;
    Part part;
    part.firstRun = closedRuns;
    part.endRun = end;
    const std::vector<QuadBox> boxes(runBoxes.begin() + closedRuns, runBoxes.begin() + end);
    part.box = boxes.front();
    for (const QuadBox& b : boxes) part.box = QuadBox{glm::min(part.box.lo, b.lo), glm::max(part.box.hi, b.hi)};
    part.bvh = buildQuadBvh(boxes);
    parts.push_back(std::move(part));
    closedRuns = end;
    return true;
  }

  // Tests two runs' quads, each pair classified as it is found: only the pairs to mend are kept.
  void search(const TreeMesh& tree, const Skeleton& skeleton, std::uint32_t i, std::uint32_t j, PairClassifier& classifier,
              std::vector<QuadPairHit>& out, std::array<QuadCorners, kRunQuads>& nearCorners) const {
    const Run& x = runs[i];
    const Run& y = runs[j];
    // Only the quads of each run that reach into the other run's box can meet; their corners are read once.
    std::array<std::uint32_t, kRunQuads> near;
    std::size_t count = 0;
    for (std::uint32_t b = y.begin; b < y.end; ++b) {
      if (quadBoxes[b].overlaps(runBoxes[i])) near[count++] = b;
    }
    if (count == 0) return;
    for (std::size_t k = 0; k < count; ++k) nearCorners[k] = cornersOf(tree.mesh, near[k]);
    for (std::uint32_t a = x.begin; a < x.end; ++a) {
      if (!quadBoxes[a].overlaps(runBoxes[j])) continue;
      const QuadCorners ca = cornersOf(tree.mesh, a);
      for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t b = near[k];
        if (i == j && b <= a) continue;
        if (!quadBoxes[a].overlaps(quadBoxes[b]) || shareCorner(ca.index, nearCorners[k].index)) continue;
        keepIfToMend(ca, nearCorners[k], a, b, classifier, [&](const QuadPairHit& h) { return neckThroughParent(skeleton, neck, h); }, out);
      }
    }
  }

  // visit(i, j) for every two overlapping runs of the newest part, and of it and an earlier part, on `threads`.
  template <class Visit>
  void newestPairs(unsigned threads, Visit&& visit) const {
    const Part& part = parts.back();
    const std::vector<NodePair> within = splitOverlapTasks(part.bvh, threads == 1 ? 1 : 64 * threads);
    std::vector<std::size_t> earlier;
    for (std::size_t e = 0; e + 1 < parts.size(); ++e) {
      if (parts[e].box.overlaps(part.box)) earlier.push_back(e);
    }
    inParallel(within.size() + earlier.size(), threads, [&](std::size_t k, unsigned t) {
      if (k < within.size()) {
        forEachOverlappingPair(part.bvh, within[k], [&](std::uint32_t i, std::uint32_t j) { visit(part.firstRun + i, part.firstRun + j, t); });
        return;
      }
      const Part& other = parts[earlier[k - within.size()]];
      forEachOverlappingPair(part.bvh, other.bvh, [&](std::uint32_t i, std::uint32_t j) { visit(part.firstRun + i, other.firstRun + j, t); });
    });
  }
};

PairsToMendSearch::PairsToMendSearch() = default;
PairsToMendSearch::~PairsToMendSearch() = default;
PairsToMendSearch::PairsToMendSearch(PairsToMendSearch&&) noexcept = default;
PairsToMendSearch& PairsToMendSearch::operator=(PairsToMendSearch&&) noexcept = default;

void PairsToMendSearch::advance(const TreeMesh& tree, const Skeleton& skeleton, const MeshProgress& settled) {
  if (!state_) state_ = std::make_unique<State>(skeleton, std::vector<bool>(skeleton.stems.size(), true));
  State& st = *state_;
  if (!st.whole) return;
  st.settleRings(tree, settled);
  if (st.whole) st.settleQuads(tree, settled);
  if (!st.whole || !st.closePart(false)) return;
  ++st.partsAdvanced;
  // Pairs are searched as they are found, skipping stems already crowded; finish() drops those that crowding at the
  // end would not have searched.
  PairClassifier classifier(tree, skeleton, settled.quads);
  std::array<QuadCorners, kRunQuads> corners;
  std::vector<QuadPairHit> hits;
  auto keep = [&](std::uint32_t i, std::uint32_t j) {
    hits.clear();
    st.search(tree, skeleton, i, j, classifier, hits, corners);
    for (const QuadPairHit& h : hits) st.found.push_back(State::Found{h, i, j});
  };
  st.newestPairs(1, [&](std::uint32_t i, std::uint32_t j, unsigned) {
    const State::Run& x = st.runs[i];
    const State::Run& y = st.runs[j];
    if (!st.searched(skeleton, x, y, false)) return;
    if (x.stem != y.stem)
      for (const State::Run* r : {&x, &y}) st.met[static_cast<std::size_t>(r->stem)] += r->neck || r->tip ? 1 : 0;
    if (st.searched(skeleton, x, y, true)) keep(i, j);
  });
  for (std::uint32_t r = st.parts.back().firstRun; r < st.parts.back().endRun; ++r) {
    if (st.searchedAlone(st.runs[r], true)) keep(r, r);
  }
}

namespace {

// The rest of a search (all of it, when nothing was searched before): the last part's pairs, crowding, and the
// pairs found before that crowding keeps.
std::vector<QuadPairHit> finishSearch(PairsToMendSearch::State& st, const TreeMesh& tree, const Skeleton& skeleton) {
  using State = PairsToMendSearch::State;
  const MeshProgress all{std::min(tree.mesh.quads.size(), tree.quadStem.size()), tree.mesh.vertexCount(), tree.rings.size()};
  st.settleRings(tree, all);
  if (st.whole) st.settleQuads(tree, all);
  if (!st.whole) return {};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const std::uint32_t firstNew = st.closedRuns;
  const unsigned threads = threadsFor(st.runs.size() - firstNew, kThreadsFrom / kRunQuads);
  if (st.closePart(true)) {
    // The run pairs to search, and per stem how many runs of others its neck (or tip) meets.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> runPairs(threads);
    std::vector<std::vector<std::uint32_t>> met(threads, std::vector<std::uint32_t>(st.met.size(), 0));
    st.newestPairs(threads, [&](std::uint32_t i, std::uint32_t j, unsigned t) {
      const State::Run& x = st.runs[i];
      const State::Run& y = st.runs[j];
      if (!st.searched(skeleton, x, y, false)) return;
      runPairs[t].emplace_back(i, j);
      if (x.stem == y.stem) return;
      for (const State::Run* r : {&x, &y}) met[t][static_cast<std::size_t>(r->stem)] += r->neck || r->tip ? 1 : 0;
    });
    for (std::size_t t = 0; t < threads; ++t) {
      for (std::size_t s = 0; s < st.met.size(); ++s) st.met[s] += met[t][s];
      pairs.insert(pairs.end(), runPairs[t].begin(), runPairs[t].end());
    }
  }
  std::erase_if(pairs, [&](const auto& p) { return !st.searched(skeleton, st.runs[p.first], st.runs[p.second], true); });
  for (std::uint32_t r = firstNew; r < st.runs.size(); ++r) {
    if (st.searchedAlone(st.runs[r], true)) pairs.emplace_back(r, r);
  }
  std::vector<PairClassifier> classifiers(threads, PairClassifier(tree, skeleton));
  std::vector<std::vector<QuadPairHit>> hits(threads);
  std::vector<std::array<QuadCorners, kRunQuads>> corners(threads);  // per thread: the near quads' corners
  constexpr std::size_t kChunk = 64;  // run pairs a thread takes at once
  inParallel((pairs.size() + kChunk - 1) / kChunk, threads, [&](std::size_t c, unsigned t) {
    for (std::size_t k = c * kChunk; k < std::min(pairs.size(), (c + 1) * kChunk); ++k) {
      st.search(tree, skeleton, pairs[k].first, pairs[k].second, classifiers[t], hits[t], corners[t]);
    }
  });
  // Pairs found before the last part, where the crowding now known still searches their runs.
  for (const State::Found& f : st.found) {
    const bool alone = f.x == f.y;
    if (alone ? st.searchedAlone(st.runs[f.x], true) : st.searched(skeleton, st.runs[f.x], st.runs[f.y], true)) hits[0].push_back(f.hit);
  }
  return gathered(hits);
}

}  // namespace

std::vector<QuadPairHit> PairsToMendSearch::finish(const TreeMesh& tree, const Skeleton& skeleton) {
  if (state_ && state_->whole) {
    std::vector<QuadPairHit> hits = finishSearch(*state_, tree, skeleton);
    if (state_->whole) return hits;
  }
  // A part broke its promise: the whole mesh at once.
  state_ = std::make_unique<State>(skeleton, std::vector<bool>(skeleton.stems.size(), true));
  return finishSearch(*state_, tree, skeleton);
}

bool PairsToMendSearch::searchedInParts() const { return state_ && state_->whole && state_->partsAdvanced > 0; }

std::vector<QuadPairHit> pairsToMendOf(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<bool>& stems) {
  PairsToMendSearch::State st(skeleton, stems);
  return finishSearch(st, tree, skeleton);
}

std::vector<QuadPairHit> pairsToMendWith(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<std::uint32_t>& quads) {
  const QuadMesh& mesh = tree.mesh;
  std::vector<QuadBox> boxes;
  for (std::uint32_t f : quads) boxes.push_back(boxOf(mesh, f));
  if (boxes.empty()) return {};
  const QuadBvh bvh = buildQuadBvh(boxes);
  PairClassifier classifier(tree, skeleton);
  std::vector<bool> neck;  // worked out for the first pair of a child and its parent: most calls meet none
  auto throughParent = [&](const QuadPairHit& h) {
    if (h.relation != StemRelation::ParentChild) return false;
    if (neck.empty()) neck = neckQuads(tree);
    return neckThroughParent(skeleton, neck, h);
  };
  std::vector<QuadPairHit> found;
  for (std::uint32_t g = 0; g < mesh.quads.size(); ++g) {
    forEachOverlap(bvh, boxOf(mesh, g), [&](std::uint32_t k) {
      const std::uint32_t f = quads[k];
      // A pair of two listed quads once.
      if (f == g || shareCorner(mesh.quads[f], mesh.quads[g])) return;
      if (std::binary_search(quads.begin(), quads.end(), g) && g < f) return;
      keepIfToMend(cornersOf(mesh, f), cornersOf(mesh, g), f, g, classifier, throughParent, found);
    });
  }
  sortHits(found);
  return found;
}

bool childIsA(const QuadPairHit& h, const Skeleton& skeleton) { return skeleton.stems[static_cast<std::size_t>(h.stemA)].parentStem == h.stemB; }

std::size_t meshMadeIntersections(const TreeMesh& tree, const Skeleton& skeleton) {
  return checkSelfIntersections(tree, skeleton).meshMade;
}

const char* pairOriginName(PairOrigin origin) {
  switch (origin) {
    case PairOrigin::Skeleton: return "skeleton";
    case PairOrigin::Mesh: return "mesh";
    case PairOrigin::Unclassified: break;
  }
  return "unclassified";
}

const char* stemRelationName(StemRelation relation) {
  switch (relation) {
    case StemRelation::Same: return "same stem";
    case StemRelation::ParentChild: return "parent-child";
    case StemRelation::CloneSource: return "clone-source";
    case StemRelation::Siblings: return "siblings";
    case StemRelation::Other: return "other";
    case StemRelation::Hub: break;
  }
  return "hub";
}

const char* quadContactName(QuadContact contact) {
  switch (contact) {
    case QuadContact::Vertex: return "vertex";
    case QuadContact::Edge: return "edge";
    case QuadContact::Apart: break;
  }
  return "apart";
}

}  // namespace arbor
