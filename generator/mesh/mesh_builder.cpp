// The mesh builder: walks the skeleton stem by stem, places four-vertex cross sections along each stem,
// joins consecutive ones with bands of four quads, and connects children through the sides of connection
// slabs (connection.cpp). Every child tube starts from four vertices of its parent, so the result is one
// closed mesh without a single branch cylinder stuck inside another.
#include <algorithm>
#include <functional>
#include <iterator>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "connection.hpp"
#include "crossing_twigs.hpp"
#include "search_beside_builder.hpp"
#include "cross_section.hpp"
#include "edge_plane.hpp"
#include "face_grid.hpp"
#include "hub_layout.hpp"
#include "joint_checks.hpp"
#include "mesh_attributes.hpp"
#include "mesh_checks.hpp"
#include "quad_contact.hpp"
#include "stem_capsules.hpp"
#include "stem_polyline.hpp"
#include "tree_mesh.hpp"

namespace arbor {

namespace {

constexpr std::uint32_t kUnmade = 0xfffffff0u;  // indices of corners not emitted yet
// A child's neck at least this many of its radii long (from its first ring to where its tube begins) gives ports
// to its own children attached along it; on shorter ones they join the first slab (all trees at seeds 1-3, with
// bowed necks: 8 radii 1,830 mesh-made pairs, 12 radii 1,889, 16 radii 1,884, 6 radii 1,903, 4 radii 2,577). Since
// every later joint rule (2026-12-06): 6 radii and 8 both leave none, and at 6 ABOP fig. 1.24d's limbs on 7.9-radii
// necks leave where they attach instead of 2-4 parent radii along at their parent's first slab.
constexpr double kNeckPortsFrom = 6.0;
// A limb fused along its parent up to its split whose collar lies within this many of its radii of the split
// builds the split's box on the collar itself; farther, on the skeleton moved clear of the parent (continueStem).
constexpr double kFusedSplitNear = 4.0;
// A child attached farther from the neck's line than this many of its parent's radii joins the first slab: the
// neck is not where its skeleton is (a grass's stalks left their box hub along necks 400 radii long).
constexpr double kNeckReach = 20.0;
// A twig (or a twig-bearing branch off a limb) whose connection lies farther along its parent than this many parent
// radii from its attachment is a fake branch (the joint floor of docs/mesh.md: first rings within 1.5 parent radii).
// Half a radius: its first ring stands off the connection by up to a radius more (at 1, 15 twigs of the Arbaro files
// at seeds 1-3 ended past 1.5; all trees' mesh-made pairs 5,677 at 1, 5,290 at 0.75, 4,981 at 0.5, and 5,357
// with 1 kept for neck ports, whose twigs were most of the gain).
constexpr double kFakeFrom = 0.5;
// A twig whose wood clears its parent's only this many parent radii along (leaving at under some 15 to 20 degrees),
// and at most kThinTwig of the parent's radius thick, is a fake branch: all trees' mesh-made pairs at seeds 1-3
// 4,867 -> 3,486, none worse. Thicker shallow stems (a codominant fork) keep their wood.
constexpr double kShallowFrom = 6.0;
constexpr double kThinTwig = 0.5;
// A twig attached at most this many parent radii before its parent splits is a fake branch: the clones leaving the
// split slab's sides ran over it (all trees' mesh-made pairs at seeds 1-3 3,486 -> 2,965, none worse; the CA black
// oak file 676 -> 421, at 2 radii 531, at 6 411; faking only the twigs on a clone's side, 489).
constexpr double kBeforeSplit = 4.0;
// The joint floor (docs/mesh.md): a child's first ring at most this many parent radii along from its attachment.
constexpr double kFarChild = 1.5;
// A trunk clone bearing a child within this many of its radii from its start has its collar candidates at
// kEarlyCloneCollar of their distance from its port.
constexpr double kEarlyChild = 4.0;
constexpr double kEarlyCloneCollar = 0.4;
// A slab whose stem turns by more than this (cosine between its ends' directions: 30 degrees) faces along its chord.
constexpr double kSlabTurn = 0.866;
// A stem's last slab at most this many of its radii before its tip gives its top to the child most aligned with the
// stem, where that child runs within 25 degrees of it (cosine 0.9): the stem ends there. Tails of 2 or 3 radii and
// 37 or 45 degrees gave the same counts but for the cottonwood file (3 radii: 20 -> 28), measured before the children
// beside it kept their clearance.
constexpr double kTopTail = 1.5;
constexpr double kTopAligned = 0.9;
// Trunks from one root that always stand on a wide hub, whatever their axes (a tuft of 1,000 stalks, one lying
// flat, took the box hub 250 sub-boxes deep to a non-finite vertex; 800 upright ones meshed there).
constexpr std::size_t kBoxHubMost = 64;

// Passes of faking the twigs an earlier pass left past kFarChild.
constexpr int kFarTwigPasses = 3;
// A stem whose neck still crosses another where the skeletons do not (no twig to take out) is meshed again with its
// collar this much nearer its port: a shallow limb's collar, two child radii off its parent, reached into a limb
// passing the parent (the CA black oak file's limb 350 at seed 2, 8 pairs; at half the distance, none).
constexpr double kNearCollar = 0.5;
// How many half-radius steps a first cross section moves on before the steps widen (continueStem).
constexpr int kFineSteps = 256;
// The third whole mesh (collars leaning, below) only up to this many quads: a fuzzed palm of 65,520 trunk clones
// (917,000 quads) took 3.6 -> 5.0 s with it, past the fuzz run's time limit; every preset and Arbaro file stays under
// 200,000 quads, and only ABOP fig. 1.24d (3,600) takes that pass.
constexpr std::size_t kLeaningPassQuadsMost = 400000;
// Stems whose necks an earlier mesh left crossing another stem (each sorted): their collars stand nearer their
// ports, and those still crossing from there also lean along the stem (Builder::leavePort).
struct CollarHints {
  std::vector<int> nearer, leaning;
};
// A twig (level 2 on) passing within this many radii of a neighbouring stem's axis at that stem's joint, plus its
// own radius, is a fake branch: a collar is placed at twice the child's radius. All trees' mesh-made pairs at seeds
// 1-3 1,105 -> 973 and neck crossings 4,950 -> 2,735, quads 0.8 % fewer; at 2.5 radii 954 but quads 1.2 % fewer;
// at 3 from level 1 on, the palms lost a fifth of their quads (fronds) and shave-grass half.
constexpr double kCollarReach = 2.0;

struct Ring {
  std::array<std::uint32_t, 4> v{};
  RingFrame frame;
  Vec3 center{0.0};
  double radius = 0;  // skeleton radius
  double tex = 0;     // texture v
};

// Where a child tube begins: four vertices of its parent, seen counter-clockwise from outside.
struct PortStart {
  std::array<std::uint32_t, 4> port{};
  Vec3 branchPoint{0.0};
  bool top = false;   // the parent's top cross section (a split or a sub-box): leave along the child
  Vec3 parentAxis{0.0};     // the slab's axis: a side child's tube starts once clear of the parent
  double parentReach = 0.0; // distance of the parent's corners from that axis
  double parentEnd = 1e300; // where the parent's skeleton ends along that axis, from branchPoint (never, past a split)
  double slabReach = 0.0;   // the same for every port, also past a split and on the hub (where parentReach is 0)
  std::size_t parentFacesBegin = 0, parentFacesEnd = 0;  // the parent stem's quads, complete by then
  // A child attached before its parent's tube begins (moved to the first slab) also clears its grandparent.
  bool clearGrandparent = false;
  bool moved = false;  // attached before the parent's tube begins (or past its end), joined to the nearest slab
  bool onNeck = false; // leaving through a slab cut out of its parent's neck (neckPorts)
  Vec3 grandPoint{0.0}, grandAxis{0.0};
  double grandReach = 0.0;
  // Texture v at the port, read from the parent's cross sections when the port is made: a sibling's neck adding
  // to a shared corner later does not change it, so no child's texture depends on the order its siblings are built.
  double tex = 0.0;
  // A trunk leaving a wide hub (buildGridHub): its neck runs from the port to its skeleton at this arc length,
  // where its tube begins (-1: any other port).
  double tubeAt = -1.0;
};

class Builder {
 public:
  // `fake`: stems to draw as fake branches whatever the rules say (the far twigs of an earlier pass); `collars`:
  // stems whose collar candidates stand kNearCollar as far from their port, or also lean (CollarHints).
  Builder(const Skeleton& s, const MeshOptions& o, TreeMesh& out, const std::vector<int>& fake, const CollarHints& collars)
      : sk_(s), opt_(o), out_(out), fake_(fake), collars_(collars) {}

  // The crossing-twig search, told as each trunk and each of its children is built whole (with all that grows from
  // it), and stopped before a vector it reads would move.
  void searchBeside(SearchBesideBuilder* beside) { beside_ = beside; }

  void run() {
    const std::size_t vertices = out_.mesh.positions.capacity();
    uvwSum_.reserve(vertices);
    uvwCount_.reserve(vertices);
    portUse_.reserve(vertices);
    stemsAt_.assign(sk_.nodes.size(), {});
    std::vector<int> trunks;
    branching_.assign(sk_.stems.size(), false);
    clones_.assign(sk_.stems.size(), {});
    children_.assign(sk_.stems.size(), {});
    faked_.assign(sk_.stems.size(), false);
    cornerTurns_.assign(sk_.stems.size(), kNoCornerTurns);
    resolution_ = 1e-5 * sk_.treeScale;
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      const SkeletonStem& st = sk_.stems[i];
      if (!meshed(static_cast<int>(i))) continue;
      if (st.cloneOf >= 0) clones_[static_cast<std::size_t>(st.cloneOf)].push_back(static_cast<int>(i));
      else if (st.parentStem >= 0) children_[static_cast<std::size_t>(st.parentStem)].push_back(static_cast<int>(i));
      if (st.startRadius > 0.0) resolution_ = std::min(resolution_, st.startRadius);
    }
    branching_ = bearingStems();
    layJointAxes();
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      if (!meshed(static_cast<int>(i))) continue;
      if (unjoinableTwig(static_cast<int>(i)) || std::binary_search(fake_.begin(), fake_.end(), static_cast<int>(i))) fakeTwig(static_cast<int>(i));
    }
    // A stem all of whose children are fake branches is a twig itself: where its wood does not clear its parent's
    // either, it is one too, and so on down (an ABOP plant's branches inside its thick trunk: fig-1-24a's mesh-made
    // pairs 378 -> 0, its bumps on the trunk gone, the fake branches standing in). Only this rule cascades: all of the
    // twig rules took the whole weeping willow preset (its hanging twigs shallow, then their branches, then limbs).
    // Only stems that lost their last meshed child are looked at again: the rest were judged as twigs above.
    for (std::size_t faked = 0; faked != out_.fakedStems.size();) {
      faked = out_.fakedStems.size();
      const std::vector<bool> before = std::exchange(branching_, bearingStems());
      for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
        if (before[i] && meshed(static_cast<int>(i)) && !faked_[i] && buried(static_cast<int>(i), branching_)) fakeTwig(static_cast<int>(i));
      }
    }
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      const SkeletonStem& st = sk_.stems[i];
      if (!meshed(static_cast<int>(i)) || faked_[i]) continue;
      if (st.attachNode >= 0) stemsAt_[static_cast<std::size_t>(st.attachNode)].push_back(static_cast<int>(i));
      else trunks.push_back(static_cast<int>(i));
    }
    // A root node holding one trunk is that trunk's base, not a hub: a hub three radii tall held the children
    // attached along it (ABOP fig. 1.24b's lowest limb) up to where the trunk's tube began.
    const bool rooted = !sk_.nodes.empty() && sk_.nodes[0].kind == NodeKind::Root;
    if (rooted && stemsAt_[0].size() > 1) buildRoot(stemsAt_[0]);
    else
      for (int t : rooted ? stemsAt_[0] : trunks) buildStem(t, nullptr);
    finish();
  }

 private:
  const Skeleton& sk_;
  const MeshOptions& opt_;
  TreeMesh& out_;
  // The thinnest cross section the mesh makes (tapered tips keep four distinct corners): 1e-5 of the tree, but
  // no thicker than its thinnest stem starts (twigs in a graph 36 km across were swollen past their parents).
  double resolution_ = 0.0;
  std::vector<std::vector<int>> stemsAt_;  // per node: meshed stems whose first edge leaves it
  std::vector<bool> branching_;            // per stem: whether it or a clone after it has a meshed child (not a twig)
  std::vector<std::vector<int>> clones_;   // per stem: its meshed clones
  std::vector<std::vector<int>> children_; // per stem: its meshed children (not clones)
  std::vector<std::pair<Vec3, Vec3>> jointAxis_;  // per child: its axis from its attach node to where it clears its parent
  std::vector<double> clearance_;          // per child: parentClearance, the arc length where it clears its parent
  const std::vector<int>& fake_;            // sorted: stems faked whatever the rules say
  const CollarHints& collars_;              // stems whose collar candidates stand nearer their port, or also lean
  std::vector<bool> faked_;                // per stem: in out_.fakedStems
  std::vector<CornerTurns> cornerTurns_;    // per stem: the sides its children heading for its corners took
  std::vector<Vec3> uvwSum_;
  std::vector<int> uvwCount_;
  std::vector<std::uint8_t> portUse_;      // per vertex: how many ports it is a corner of
  // The port being left, when inset: the quads around it, and its side's plane with how far the side's (bilinear)
  // corners stand off it, for bandMeetsInset's quick answer.
  struct Inset {
    std::array<QuadCorners, 4> around;
    Vec3 center{0.0}, normal{0.0};
    double tolerance = 0.0;
  };
  std::optional<Inset> inset_;
  // The first bands of the current parent's children made so far: split clones leaving within a few degrees of
  // each other through ports that share an edge folded one band over the other there.
  struct SiblingBands {
    std::vector<QuadCorners> quads;
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> atCorner;  // port corner -> quads from it
  };
  SiblingBands siblingBands_;
  int currentStem_ = -1;                   // stem whose faces are being emitted
  const PortStart* currentStart_ = nullptr;  // how that stem left its parent (null: a trunk)
  bool connectingMoved_ = false;           // the slab being connected holds children moved to the tube's start
  bool slabMoved_ = false;                 // the same, whatever its stem's own start (its ports' `moved`)
  bool neckSlab_ = false;                  // the slab being connected is cut out of a neck (its ports' `onNeck`)
  // Children attached along a stem's neck, before its tube begins: they leave through its first band, which
  // starts at ring `from` (neckPorts), instead of crowding its first slab far from where they attach.
  struct NeckChildren {
    std::array<std::uint32_t, 4> from{};
    int stem = -1;
    std::vector<int> nodes;
  };
  std::optional<NeckChildren> neck_;
  std::vector<std::pair<int, PortStart>>* deferred_ = nullptr;  // children waiting for their parent
  // Grids over the faces of the parents whose children are being fitted, innermost last (built depth first, so
  // a parent's grid outlives its children's subtrees instead of being rebuilt for every child).
  struct ParentGrid {
    std::size_t begin = 0, end = 0;
    FaceGrid grid;
  };
  std::vector<std::unique_ptr<ParentGrid>> grids_;
  SearchBesideBuilder* beside_ = nullptr;
  int depth_ = 0;  // of the stem being built: 0 a trunk, 1 a trunk's child

  void settle() {
    if (beside_) beside_->settled(MeshProgress{out_.mesh.quads.size(), out_.mesh.positions.size(), out_.rings.size()});
  }
  // Before a push: a vector the search beside reads may not move while it reads it.
  template <class Values>
  void beforePush(const Values& values) {
    if (beside_ && values.size() == values.capacity()) {
      beside_->stop();
      beside_ = nullptr;
    }
  }

  // Stubs (shorter than a tube can be, hair-thin, or ending inside their parent) are drawn as fake branches.
  bool meshed(int stem) const {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    return !st.stub && (opt_.levels <= 0 || st.level < opt_.levels);
  }

  std::string tooManyQuads(double extraRings) const {
    std::string message = "the mesh would have more than " + std::to_string(opt_.maxQuads) + " quads";
    if (extraRings > 0.0) message += " (one stem alone asks for " + formatNumber(extraRings) + " extra cross sections)";
    if (opt_.ringSpacing > 0.0 || opt_.maxRingDistance > 0.0) {
      return message + "; space cross sections further apart (ring spacing " + formatNumber(opt_.ringSpacing) + " radii, largest ring distance " +
             formatNumber(opt_.maxRingDistance) + " m) or lower Levels or Branches";
    }
    return message + "; lower Levels or Branches, or mesh fewer levels and draw the rest as fake branches";
  }

  // ---- vertices, rings, faces ----

  std::uint32_t addVertex(const Vec3& p, double radius, int level, const Vec3& tangent) {
    QuadMesh& m = out_.mesh;
    beforePush(m.positions);
    beforePush(m.radius);
    m.positions.emplace_back(p);
    m.tangents.emplace_back(tangent);
    m.radius.push_back(static_cast<float>(radius));
    m.level.push_back(static_cast<std::uint8_t>(level));
    uvwSum_.emplace_back(0.0);
    uvwCount_.push_back(0);
    portUse_.push_back(0);
    return static_cast<std::uint32_t>(m.positions.size() - 1);
  }

  void addUvw(std::uint32_t v, int corner, double tex) {
    uvwSum_[v] += Vec3(kRingU[static_cast<std::size_t>(corner)], tex, kRingFlip[static_cast<std::size_t>(corner)]);
    ++uvwCount_[v];
  }

  // The child's texture at its port's corners, averaged with the parent's there (child-then-parent averaging). An
  // inset keeps the parent's: its corners lie on the parent's side, whose bark runs on undisturbed around the child
  // (the child's coordinates there squeezed the bark's furrows into rings around the inset).
  void addPortUvw(const std::array<std::uint32_t, 4>& port, double tex) {
    if (inset_) return;
    for (int k = 0; k < 4; ++k) addUvw(port[static_cast<std::size_t>(k)], k, tex);
  }

  Vec3 position(std::uint32_t v) const { return Vec3(out_.mesh.positions[v]); }

  Ring emitRing(int stem, const Vec3& center, const RingFrame& frame, double radius, double tex, double arc = -1.0) {
    Ring r;
    r.frame = frame;
    r.center = center;
    r.radius = radius;
    r.tex = tex;
    // The hub of several trunks belongs to no stem (-1): it is level 0.
    const int level = stem >= 0 ? sk_.stems[static_cast<std::size_t>(stem)].level : 0;
    const auto offsets = ringOffsets(frame, radius * opt_.limitCompensation);
    for (int k = 0; k < 4; ++k) {
      r.v[static_cast<std::size_t>(k)] = addVertex(center + offsets[static_cast<std::size_t>(k)], radius, level, frame.T);
      addUvw(r.v[static_cast<std::size_t>(k)], k, tex);
    }
    beforePush(out_.rings);
    out_.rings.push_back(MeshRing{stem, r.v, center, tex, radius, arc});
    return r;
  }

  void addQuad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (out_.mesh.quads.size() >= opt_.maxQuads) throw LimitError(tooManyQuads(0.0));
    beforePush(out_.mesh.quads);
    beforePush(out_.quadStem);
    out_.mesh.quads.push_back({a, b, c, d});
    out_.quadStem.push_back(currentStem_);
  }

  // Side k of the band between rings a and b, counter-clockwise from outside.
  static std::array<std::uint32_t, 4> side(const Ring& a, const Ring& b, int k) {
    const auto i = static_cast<std::size_t>(k), j = static_cast<std::size_t>((k + 1) % 4);
    return {a.v[i], a.v[j], b.v[j], b.v[i]};
  }

  void band(const Ring& a, const Ring& b, const std::array<bool, 4>& skip = {}) {
    if (neck_ && a.v == neck_->from && skip == std::array<bool, 4>{}) {
      const NeckChildren neck = std::move(*neck_);
      neck_.reset();
      neckPorts(neck, a, b);
      return;
    }
    for (int k = 0; k < 4; ++k) {
      if (skip[static_cast<std::size_t>(k)]) continue;
      const auto q = side(a, b, k);
      addQuad(q[0], q[1], q[2], q[3]);
    }
  }

  // The band out of a child's port, kept for its later siblings to keep clear of.
  void portBand(const Ring& port, const Ring& first) {
    const std::size_t from = out_.mesh.quads.size();
    band(port, first);
    for (std::size_t f = from; f < out_.mesh.quads.size(); ++f) {
      const auto& q = out_.mesh.quads[f];
      const auto index = static_cast<std::uint32_t>(siblingBands_.quads.size());
      siblingBands_.quads.push_back(QuadCorners{{position(q[0]), position(q[1]), position(q[2]), position(q[3])}, q});
      for (std::uint32_t v : q) {
        if (std::find(port.v.begin(), port.v.end(), v) != port.v.end()) siblingBands_.atCorner[v].push_back(index);
      }
    }
  }

  // Whether the band from port corners a (indices `port`) to corners b (not made yet) folds over the first band of
  // a sibling whose port shares a corner with this one.
  bool bandMeetsSiblings(const std::array<Vec3, 4>& a, const std::array<std::uint32_t, 4>& port, const std::array<Vec3, 4>& b) const {
    if (siblingBands_.atCorner.empty()) return false;
    for (std::uint32_t v : port) {
      const auto it = siblingBands_.atCorner.find(v);
      if (it == siblingBands_.atCorner.end()) continue;
      for (std::uint32_t other : it->second) {
        for (std::size_t i = 0; i < 4; ++i) {
          if (quadsMeet(unmadeSide(a, port, b, i), siblingBands_.quads[other])) return true;
        }
      }
    }
    return false;
  }

  Vec3 faceCenter(const std::array<std::uint32_t, 4>& q) const {
    return (position(q[0]) + position(q[1]) + position(q[2]) + position(q[3])) * 0.25;
  }

  // A port seen as a cross section: its corners are ring corners 0..3, so N and B point at corners 0 and 1.
  // A port is rarely square; N and B are the orthonormal pair that splits the angle between its diagonals.
  Ring portRing(const std::array<std::uint32_t, 4>& q) const {
    Ring port;
    port.v = q;
    port.center = faceCenter(q);
    const Vec3 a = glm::normalize(position(q[0]) - position(q[2]));
    const Vec3 b = glm::normalize(position(q[1]) - position(q[3]));
    const Vec3 sum = glm::normalize(a + b), difference = glm::normalize(a - b);
    const Vec3 n = glm::normalize(sum + difference), bi = glm::normalize(sum - difference);
    port.frame = RingFrame{glm::cross(n, bi), n, bi};
    return port;
  }

  // Texture v of a port: its corners' mean.
  double portTex(const std::array<std::uint32_t, 4>& q) const {
    double tex = 0.0;
    for (std::uint32_t v : q) tex += 0.25 * uvwSum_[v].y / std::max(1, uvwCount_[v]);
    return tex;
  }

  // How far a port's corners stand from its centre, on average: its size as a cross section's corners are.
  double meanCornerDistance(const std::array<std::uint32_t, 4>& q, const Vec3& center) const {
    double d = 0.0;
    for (std::uint32_t v : q) d += 0.25 * glm::distance(position(v), center);
    return d;
  }

  Vec3 faceNormal(const std::array<std::uint32_t, 4>& q) const {
    const Vec3 n = glm::cross(position(q[2]) - position(q[0]), position(q[3]) - position(q[1]));
    return glm::normalize(n);
  }

  // ---- stems ----

  // A stem is built whole before its children, so that each child can be fitted against all of its
  // parent's faces; `start` is null for a trunk standing on the ground.
  void buildStem(int stem, const PortStart* start) {
    std::vector<std::pair<int, PortStart>> children;
    auto* outerDeferred = deferred_;
    const int outer = currentStem_;
    const PortStart* outerStart = currentStart_;
    deferred_ = &children;
    currentStem_ = stem;
    currentStart_ = start;
    const std::size_t begin = out_.mesh.quads.size();
    buildStemFaces(stem, start);
    if (depth_ == 0) settle();
    ++depth_;
    buildChildren(children, begin);
    --depth_;
    if (depth_ <= 1) settle();
    currentStem_ = outer;
    currentStart_ = outerStart;
    deferred_ = outerDeferred;
  }

  void buildChildren(std::vector<std::pair<int, PortStart>>& children, std::size_t parentBegin) {
    const std::size_t parentEnd = out_.mesh.quads.size();
    SiblingBands outerBands;
    std::swap(outerBands, siblingBands_);
    for (auto& [child, start] : children) {
      start.parentFacesBegin = parentBegin;
      start.parentFacesEnd = parentEnd;
      buildStem(child, &start);
    }
    siblingBands_ = std::move(outerBands);
    // The parent's grid is done with once all its children are fitted.
    if (!grids_.empty() && grids_.back()->begin == parentBegin && grids_.back()->end == parentEnd) grids_.pop_back();
  }

  void buildStemFaces(int stem, const PortStart* start) {
    const StemPolyline poly(sk_, stem);
    Ring last;
    double sLo = 0.0, sUnclear = 0.0;
    if (!start) {
      const RingFrame frame = frameFromHint(poly.startDirection(), Vec3(1, 0, 0));
      last = emitRing(stem, poly.position(0.0), frame, poly.radius(0.0), 0.0, 0.0);
      if (opt_.openBase) out_.mesh.openBoundary.assign(last.v.begin(), last.v.end());
      else addQuad(last.v[3], last.v[2], last.v[1], last.v[0]);
    } else if (start->tubeAt >= 0.0) {
      last = leaveHub(stem, poly, *start);
      sLo = sUnclear = start->tubeAt;
    } else {
      last = leavePort(stem, poly, *start, sLo, sUnclear);
    }
    continueStem(stem, poly, last, sLo, sUnclear, start);
  }

  // The child's first cross section sits just outside the port, leaving between the port's normal and
  // the child's direction; a child that points backwards leaves straight out first (backward connection).
  // sLo: where the tube may begin; sUnclear: where it would without keeping its first band off the parent.
  Ring leavePort(int stem, const StemPolyline& poly, const PortStart& start, double& sLo, double& sUnclear) {
    inset_.reset();
    std::array<std::uint32_t, 4> q = start.port;
    if (!start.top) {
      if (auto inner = insetPort(poly, start)) q = *inner;
    }
    Ring port = portRing(q);
    const Vec3 center = port.center;
    const Vec3 normal = faceNormal(q);
    const double portRadius = meanCornerDistance(q, center);
    port.tex = start.tex;

    const Vec3 d = poly.startDirection();
    const double rc = poly.radius(0.0);
    // The first cross section must clear the port by its own size, or its tube grazes the parent. It leaves
    // between the port's normal and the child's direction; where that neck would cut a face of the parent,
    // straighter and longer necks are tried.
    // A split clone leaves at a small angle: its collar leans along its own direction (docs/mesh.md, Equal split).
    const bool clone = sk_.stems[static_cast<std::size_t>(stem)].cloneOf >= 0;
    const Vec3 preferred = start.top ? directionOr(normal + (clone ? 3.0 : 1.0) * d, normal)
                           : clone   ? directionOr(normal + 8.0 * d, normal)
                                     : (glm::dot(d, normal) > 0.2 ? glm::normalize(2.0 * normal + d) : normal);
    // A port is as wide as the parent; the neck narrows to the child's own radius at its first cross section
    // (a collar any wider stands out across passing and neighbouring twigs: all trees' mesh-made pairs 66,084 at
    // 1.5 child radii, 59,532 at 1), which is placed as a collar of twice that radius, at most half the port,
    // would be (nearer the port, a thin slab's long port folds over it).
    const double placedRadius = std::max(rc, std::min(0.5 * portRadius / opt_.limitCompensation, 2.0 * rc));
    const double exitRadius = rc;
    const double e0 = std::max(2.0 * placedRadius * opt_.limitCompensation, 0.35 * portRadius);
    const std::array<Vec3, 4> portCorners{position(q[0]), position(q[1]), position(q[2]), position(q[3])};
    if (!start.top) {
      // Best: the collar ends on the child's own skeleton where it has cleared the parent, so its tube, and
      // the slabs of its own children, begin where the skeleton leaves the parent.
      const double reach = std::sqrt(0.5) * start.parentReach + placedRadius * opt_.limitCompensation;
      const double s = std::max(poly.firstClearOf(start.branchPoint, start.parentAxis, reach, start.parentEnd + reach), grandClearance(poly, start, placedRadius));
      const Vec3 c = poly.position(s);
      // Only where that is close to the attachment: a child leaving at a shallow angle keeps its collar there.
      const double along = std::abs(glm::dot(c - start.branchPoint, start.parentAxis));
      if (s < 0.5 * poly.length() && along < 1.45 * start.parentReach / opt_.limitCompensation &&
          glm::dot(c - center, normal) > 0.5 * placedRadius * opt_.limitCompensation) {
        const RingFrame frame = transportFrame(port.frame, poly.direction(s));
        const auto offsets = ringOffsets(frame, exitRadius * opt_.limitCompensation);
        const std::array<Vec3, 4> corners{c + offsets[0], c + offsets[1], c + offsets[2], c + offsets[3]};
        if (!bandCrossesParent(start, portCorners, corners, &q) && !bandFolds(portCorners, q, corners) &&
            !bandMeetsInset(portCorners, q, corners) && !bandMeetsSiblings(portCorners, q, corners)) {
          addPortUvw(q, port.tex);
          const Ring exit = emitRing(stem, c, frame, exitRadius, port.tex + barkTextureAdvance(glm::distance(c, center), exitRadius), s);
          portBand(port, exit);
          sLo = sUnclear = s;
          return exit;
        }
      }
    }
    // Out of an inset (already the child's size) a child leaving at more than 30 degrees needs no neck: its tube
    // begins on its skeleton where the band from the inset clears the parent (all trees' mesh-made pairs 50,869
    // -> 47,537, four quads fewer a child). Shallower ones keep the neck: their long first band ran along the
    // parent beside its other children (from 15 degrees on, the willow file had 1,700 more pairs, 1,760 more folds).
    if (inset_ && !start.top && glm::length(glm::cross(d, start.parentAxis)) > 0.5) {
      if (auto direct = leaveInsetDirectly(stem, poly, start, port, portCorners, normal, sLo)) {
        sUnclear = sLo;
        return *direct;
      }
    }
    // The first cross section also stays within 1.5 parent radii of the attachment along the parent: a neck
    // that does not cut the parent and keeps that wins, then one that does not cut it, then the straight one.
    const double along = start.parentReach > 0.0 ? 1.45 * start.parentReach / opt_.limitCompensation : 1e300;
    Vec3 exitDir = normal;
    double e = e0;
    int best = 0;  // 4: clear, near and its tube clear of the parent, 3: clear and near, 2 and 1: clear
    // A clone's collar leaning along its direction can fold over a sibling's band: leaning half as far, as near,
    // comes before leaning farther out (a collar farther out moves the clone's tube and the children before it on).
    const std::array<std::pair<Vec3, double>, 6> plain{{{preferred, 1.0}, {preferred, 1.6}, {preferred, 2.5}, {normal, 1.0},
                                                        {normal, 1.6}, {normal, 2.5}}};
    const Vec3 halfway = directionOr(normal + 2.0 * d, normal);
    const std::array<std::pair<Vec3, double>, 9> cloned{{{preferred, 1.0}, {halfway, 1.0}, {preferred, 1.6}, {halfway, 1.6},
                                                         {preferred, 2.5}, {halfway, 2.5}, {normal, 1.0}, {normal, 1.6}, {normal, 2.5}}};
    // A neck still crossing another stem from its nearer collar leans along its stem as a clone's does, before the
    // usual candidates: ABOP fig. 1.24d's limb 26 leaves beside limb 25, which passes their parent 6 mm off 26's
    // port, and the band out to any collar between the port's normal and the usual lean crossed it.
    const std::array<std::pair<Vec3, double>, 9> leaned{
        {{halfway, 1.0}, {halfway, 1.6}, {halfway, 2.5}, plain[0], plain[1], plain[2], plain[3], plain[4], plain[5]}};
    const bool leaning = std::binary_search(collars_.leaning.begin(), collars_.leaning.end(), stem);
    const std::span<const std::pair<Vec3, double>> candidates = clone     ? std::span<const std::pair<Vec3, double>>(cloned)
                                                                : leaning ? std::span<const std::pair<Vec3, double>>(leaned)
                                                                          : plain;
    const double clearStep = 0.25 * std::max(portRadius, rc);
    struct TubeStart {
      double unclear, clear;  // where the tube may begin, without and with its first band clear of the parent
    };
    // The tube's start from a collar at c, leaving along `frame` with `corners`.
    auto tubeStart = [&](const Vec3& c, const RingFrame& frame, const std::array<Vec3, 4>& corners) {
      const double unclear = tubeStartPast(stem, poly, start, c);
      return TubeStart{unclear, clearOfParent(poly, start, frame, corners, unclear, clearStep)};
    };
    std::optional<TubeStart> chosenTube;  // the chosen collar's, where the choice worked it out
    // A trunk clone bearing a limb within a few of its radii: its collar nearer, so that its tube, and that limb's
    // slab, begin nearer the split (the CA black oak preset's limbs sat 2.6 clone radii along at every seed; with
    // every clone's so, two twig-bearing clones of the willow file folded at seed 3).
    const bool earlyClone = opt_.nearEarlyCloneCollars && clone && sk_.stems[static_cast<std::size_t>(stem)].level == 0 &&
                            attachedWithin(stem, poly, kEarlyChild * rc);
    const double nearness = earlyClone                                                                 ? kEarlyCloneCollar
                            : std::binary_search(collars_.nearer.begin(), collars_.nearer.end(), stem) ? kNearCollar
                                                                                                       : 1.0;
    for (const auto& [dir, farness] : candidates) {
      const double scale = farness * nearness;
      const Vec3 c = center + dir * (e0 * scale);
      // A child leaving straight against its port (dir = -d) leaves along the port first: backward connection.
      const RingFrame frame = transportFrame(port.frame, directionOr(dir + d, dir));
      const auto offsets = ringOffsets(frame, exitRadius * opt_.limitCompensation);
      const std::array<Vec3, 4> corners{c + offsets[0], c + offsets[1], c + offsets[2], c + offsets[3]};
      // A leaning band can fold along the parent (a graph's branch leaving its trunk at 7 degrees): not that one.
      if (bandCrossesParent(start, portCorners, corners, &q) || bandMeetsInset(portCorners, q, corners) ||
          bandMeetsSiblings(portCorners, q, corners) || (leaning && bandFolds(portCorners, q, corners))) {
        continue;
      }
      // A child moved to a slab or leaving a neck's is near only as the joint floor measures it too: the slab's axis
      // and reach are not its parent's skeleton there (ABOP fig. 1.24d's limbs 13, 33 and 113 sat 1.50-4.15 radii along).
      const bool near = std::abs(glm::dot(c - start.branchPoint, start.parentAxis)) <= along &&
                        (!(start.moved || start.onNeck) || nearAsChecked(stem, c, start));
      int score = near ? 3 : 1;
      // Better still, a collar from which the tube clears the parent before the stem ends or splits: from the others
      // one band ran on to the stem's end, back through the parent (the larch file's hooked twigs). Not from the
      // farthest collars: that jutted a willow limb's neck a metre sideways.
      std::optional<TubeStart> tube;
      if (score + 1 > best && scale < 2.0) {
        tube = tubeStart(c, frame, corners);
        const double sEnd = poly.length();
        if (tube->clear < sEnd || !bandCrossesParent(start, corners, ringCorners(poly, frame, sEnd))) ++score;
      }
      if (score > best) {
        best = score;
        exitDir = dir;
        e = e0 * scale;
        chosenTube = tube;
      }
      if (best == 4) break;
    }
    const Vec3 exitCenter = center + exitDir * e;
    addPortUvw(q, port.tex);

    const RingFrame exitFrame = transportFrame(port.frame, directionOr(exitDir + d, exitDir));
    const auto offsets = ringOffsets(exitFrame, exitRadius * opt_.limitCompensation);
    const std::array<Vec3, 4> exitCorners{exitCenter + offsets[0], exitCenter + offsets[1], exitCenter + offsets[2],
                                          exitCenter + offsets[3]};
    if (!chosenTube) chosenTube = tubeStart(exitCenter, exitFrame, exitCorners);
    sUnclear = chosenTube->unclear;
    sLo = chosenTube->clear;
    const Ring exit = emitRing(stem, exitCenter, exitFrame, exitRadius, port.tex + barkTextureAdvance(e, exitRadius));
    portBand(port, exit);
    return exit;
  }

  // Whether a first cross section at c stands within the joint floor as childPlacements measures it: along the
  // parent's skeleton direction at the attach node, in the larger of its radius there and the port slab's.
  bool nearAsChecked(int stem, const Vec3& c, const PortStart& start) const {
    return alongFromAttachment(stem, c) <= 1.45 * std::max(attachmentOf(stem).radius, start.parentReach / opt_.limitCompensation);
  }

  // The child's first cross section on its skeleton straight out of the inset `port` (corners c), where the band
  // from it clears the parent, if that band runs outwards and folds over nothing; sLo receives its arc length.
  std::optional<Ring> leaveInsetDirectly(int stem, const StemPolyline& poly, const PortStart& start, const Ring& port,
                                         const std::array<Vec3, 4>& c, const Vec3& normal, double& sLo) {
    const double rc = poly.radius(0.0);
    double s = tubeStartPast(stem, poly, start, port.center);
    double portRadius = 0.0;
    for (const Vec3& corner : c) portRadius += 0.25 * glm::distance(corner, port.center);
    const double step = 0.25 * std::max(portRadius, rc), unclear = s;
    s = clearOfParent(poly, start, port.frame, c, s, step);
    // Found where its band first clears, the cross section only grazes the parent (a cottonwood file limb's
    // corner 0.1 mm off the trunk's long band, 2 mesh-made pairs): one step on.
    if (s > unclear) s = std::min(s + step, poly.length());
    if (s >= 0.5 * poly.length()) return std::nullopt;
    const Vec3 center = poly.position(s);
    const RingFrame frame = transportFrame(port.frame, poly.direction(s));
    const double radius = std::max(poly.radius(s), resolution_);
    const auto offsets = ringOffsets(frame, radius * opt_.limitCompensation);
    const std::array<Vec3, 4> corners{center + offsets[0], center + offsets[1], center + offsets[2], center + offsets[3]};
    // Outwards: the new corners above the side, the inset's behind the new cross section.
    for (std::size_t k = 0; k < 4; ++k) {
      if (glm::dot(corners[k] - port.center, normal) <= 0.0 || glm::dot(c[k] - center, frame.T) >= 0.0) return std::nullopt;
    }
    if (bandFolds(c, port.v, corners) || bandMeetsInset(c, port.v, corners, false) || bandMeetsSiblings(c, port.v, corners)) {
      return std::nullopt;
    }
    addPortUvw(port.v, port.tex);
    const Ring first = emitRing(stem, center, frame, radius, port.tex + barkTextureAdvance(glm::distance(center, port.center), rc), s);
    portBand(port, first);
    sLo = s;
    return first;
  }

  // A thin child leaves through a square inset in its port where its skeleton meets the port, joined to the
  // port's corners by four quads: its neck then starts at the child's size instead of narrowing from a port as
  // wide as its parent (crowded thin children's wide necks crossed each other). Vertex valences do not change.
  std::optional<std::array<std::uint32_t, 4>> insetPort(const StemPolyline& poly, const PortStart& start) {
    if (opt_.insetCollar <= 0.0) return std::nullopt;
    const auto& q = start.port;
    const std::array<Vec3, 4> p{position(q[0]), position(q[1]), position(q[2]), position(q[3])};
    const Vec3 eu = p[1] - p[0] + p[2] - p[3], ev = p[3] - p[0] + p[2] - p[1];
    const double w = 0.5 * glm::length(eu), h = 0.5 * glm::length(ev);
    const double half = opt_.insetCollar * poly.radius(0.0) * opt_.limitCompensation * std::sqrt(0.5);
    // The inset is at most 0.7 of the side each way (the quads around it at least 0.15 wide), and only where it
    // narrows the port to under 0.44 of its width (wider ones cut crossings less than they add quads: all trees'
    // mesh-made pairs 58,618 -> 51,219 and quads +11 % at 0.44, 52,395 and +5 % at 0.3, 51,308 and +14 % at 0.6).
    const double hu = std::min(half, 0.35 * w), hv = std::min(half, 0.35 * h);
    if (!(hu > 0.0) || hu > 0.22 * w) return std::nullopt;
    // Where the child's first edge, from its attachment on the parent's axis, meets the port's plane.
    const Vec3 center = faceCenter(q), normal = faceNormal(q), d = poly.startDirection();
    const double dn = glm::dot(d, normal);
    const Vec3 at = dn > 0.1 ? start.branchPoint + d * (glm::dot(center - start.branchPoint, normal) / dn) : center;
    const double du = hu / w, dv = hv / h;
    // The bilinear weights of the side's corners at (a, b) across it, and the point there.
    auto weightsAt = [](double a, double b) { return std::array<double, 4>{(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b}; };
    auto pointAt = [&](const std::array<double, 4>& k) { return k[0] * p[0] + k[1] * p[1] + k[2] * p[2] + k[3] * p[3]; };
    // The inset's centre (s, t) across the side (0..1 each way), kept 0.15 from its edges.
    auto across = [&](const Vec3& x) {
      return std::array<double, 2>{std::clamp(0.5 + glm::dot(x - center, eu) / (2.0 * w * w), du + 0.15, 0.85 - du),
                                   std::clamp(0.5 + glm::dot(x - center, ev) / (2.0 * h * h), dv + 0.15, 0.85 - dv)};
    };
    std::array<double, 2> st0 = across(at);
    // A child moved from before its parent's tube begins whose first edge meets the side past the joint floor (a
    // shallow one meets it at its far end: the willow file's limb 287, 1.7 clone radii along): where the side is
    // nearest its attachment.
    auto alongAt = [&](const std::array<double, 2>& c) { return alongFromAttachment(currentStem_, pointAt(weightsAt(c[0], c[1]))); };
    const bool moved = start.moved && currentStem_ >= 0;
    const double limit = moved ? kFarChild * attachmentOf(currentStem_).radius : 0.0;
    if (moved && alongAt(st0) > limit) {
      st0 = across(start.branchPoint - normal * glm::dot(start.branchPoint - center, normal));
      // Still past it (a side slanting away along the parent: the willow file's limb 287 at seed 3 on a trunk
      // clone's collar band, 1.62 clone radii along): the place in the side nearest along the parent, on a grid over
      // the centres `across` allows.
      double best = alongAt(st0);
      for (int i = 0; i <= 8 && best > limit; ++i) {
        for (int j = 0; j <= 8; ++j) {
          const std::array<double, 2> c{du + 0.15 + (0.7 - 2.0 * du) * i / 8.0, dv + 0.15 + (0.7 - 2.0 * dv) * j / 8.0};
          const double a = alongAt(c);
          if (a < best - 1e-9 * sk_.treeScale) {
            best = a;
            st0 = c;
          }
        }
      }
    }
    const double s = st0[0], t = st0[1];
    const std::array<std::array<double, 2>, 4> st{{{s - du, t - dv}, {s + du, t - dv}, {s + du, t + dv}, {s - du, t + dv}}};
    std::array<std::array<double, 4>, 4> weights{};
    std::array<Vec3, 4> corners{};
    for (std::size_t k = 0; k < 4; ++k) {
      weights[k] = weightsAt(st[k][0], st[k][1]);
      corners[k] = pointAt(weights[k]);
    }
    // Where another of the parent's faces passes through the side (a neck of the parent's own, leaving its parent
    // there), the inset's quads would cut it: the child leaves through the whole side instead.
    std::array<QuadCorners, 4> around;
    for (std::size_t k = 0; k < 4; ++k) around[k] = unmadeSide(p, q, corners, k);
    if (quadsCutParent(start, around)) return std::nullopt;
    const QuadMesh& m = out_.mesh;
    std::array<std::uint32_t, 4> inner{};
    for (std::size_t k = 0; k < 4; ++k) {
      Vec3 tangent(0.0), uvw(0.0);
      double radius = 0.0;
      for (std::size_t c = 0; c < 4; ++c) {
        tangent += weights[k][c] * Vec3(m.tangents[q[c]]);
        radius += weights[k][c] * m.radius[q[c]];
        uvw += weights[k][c] * uvwSum_[q[c]] / static_cast<double>(std::max(1, uvwCount_[q[c]]));
      }
      inner[k] = addVertex(corners[k], radius, m.level[q[0]], directionOr(tangent, Vec3(m.tangents[q[0]])));
      // The side's texture where the inset's corner lies on it, as the parent's face had it there.
      uvwSum_[inner[k]] = uvw;
      uvwCount_[inner[k]] = 1;
    }
    // The inset is the child's first cross section (off its skeleton): its connection, where the joint checks look.
    beforePush(out_.rings);
    out_.rings.push_back(MeshRing{currentStem_, inner, 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]), start.tex,
                                  opt_.insetCollar * poly.radius(0.0), -1.0, true});
    double offPlane = 0.0;
    for (const Vec3& c : p) offPlane = std::max(offPlane, 2.0 * std::abs(glm::dot(c - center, normal)));
    inset_.emplace(Inset{{}, center, normal, offPlane + 1e-6 * (w + h)});
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t j = (k + 1) % 4;
      addQuad(q[k], q[j], inner[j], inner[k]);
      inset_->around[k] = QuadCorners{{p[k], p[j], corners[j], corners[k]}, {q[k], q[j], inner[j], inner[k]}};
    }
    return inner;
  }

  // Planes through a port's edges (EdgePlane): a face behind one of them cannot meet what is in front.
  using EdgePlanes = std::array<std::optional<EdgePlane>, 4>;

  static bool behindOne(const EdgePlanes& planes, const QuadCorners& face) {
    for (const auto& plane : planes) {
      if (plane && plane->behind(face.p, face.index)) return true;
    }
    return false;
  }

  // How far in front and behind points must be: twice quadsMeet's fold angle (1e-3) over their span, so that two
  // quads on one edge that the plane keeps apart are never near enough to folded to count as a fold there.
  static double planeMargin(double span) { return 2e-3 * span; }

  // Planes through the port's edges with the inset's quads c in front (quad k runs from port corner k to k + 1, then
  // inwards: it touches plane k only along that edge).
  static EdgePlanes insetPlanes(const std::array<QuadCorners, 4>& c) {
    const Vec3 up = glm::cross(c[2].p[0] - c[0].p[0], c[3].p[0] - c[1].p[0]);
    const Vec3 centroid = 0.25 * (c[0].p[0] + c[1].p[0] + c[2].p[0] + c[3].p[0]);
    const double margin = planeMargin(glm::distance(c[0].p[0], c[2].p[0]));
    EdgePlanes planes;
    for (std::size_t k = 0; k < 4; ++k) {
      std::array<Vec3, 6> front;
      std::size_t n = 0;
      for (std::size_t i = 0; i < 4; ++i) {
        if (i != k && i != (k + 1) % 4) front[n++] = c[i].p[0];
        front[n++] = c[i].p[3];
      }
      planes[k] = edgePlane(c[k].p[0], c[k].p[1], {c[k].index[0], c[k].index[1]}, up, centroid - c[k].p[0], front, {}, margin);
    }
    return planes;
  }

  // Planes through the port's edges with a band leaving it (corners a, then b farther out) wholly in front.
  EdgePlanes bandPlanes(const std::array<std::uint32_t, 4>& port, const std::array<Vec3, 4>& a, const std::array<Vec3, 4>& b) const {
    const std::array<Vec3, 4> p{position(port[0]), position(port[1]), position(port[2]), position(port[3])};
    const Vec3 centroid = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    Vec3 up = glm::cross(p[2] - p[0], p[3] - p[1]);
    if (glm::dot(up, 0.25 * (b[0] + b[1] + b[2] + b[3]) - centroid) < 0.0) up = -up;
    const std::array<Vec3, 8> front{a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]};
    EdgePlanes planes;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t j = (k + 1) % 4;
      planes[k] = edgePlane(p[k], p[j], {port[k], port[j]}, up, centroid - p[k], front, {}, planeMargin(glm::distance(a[0], a[2])));
    }
    return planes;
  }

  // Whether any of quads c (corners not made yet carry kUnmade indices) meets a face of the parent beyond what
  // they share.
  bool quadsCutParent(const PortStart& start, const std::array<QuadCorners, 4>& c) {
    if (start.parentFacesEnd <= start.parentFacesBegin) return false;
    FaceGrid& grid = parentGrid(start.parentFacesBegin, start.parentFacesEnd);
    std::array<Box, 4> boxes;
    for (std::size_t k = 0; k < 4; ++k) boxes[k] = boxOf(c[k].p);
    const Box all = boxOf(std::array<Vec3, 8>{c[0].p[0], c[0].p[1], c[1].p[1], c[2].p[1], c[0].p[2], c[0].p[3], c[2].p[2], c[2].p[3]});
    const EdgePlanes planes = insetPlanes(c);
    for (std::uint32_t f : grid.candidates(all)) {
      const Box& faceBox = grid.box(f);
      if (!faceBox.overlaps(all)) continue;
      const auto& q = out_.mesh.quads[start.parentFacesBegin + f];
      const QuadCorners face{{position(q[0]), position(q[1]), position(q[2]), position(q[3])}, q};
      if (behindOne(planes, face)) continue;
      for (std::size_t k = 0; k < 4; ++k) {
        if (faceBox.overlaps(boxes[k]) && quadsMeet(c[k], face)) return true;
      }
    }
    return false;
  }

  // Whether the neck from the inset (corners a, indices port) to corners b (not made yet) folds over the inset's quads;
  // `quick` trusts a short neck that stands clear above the side, a long band is always tested.
  bool bandMeetsInset(const std::array<Vec3, 4>& a, const std::array<std::uint32_t, 4>& port, const std::array<Vec3, 4>& b,
                      bool quick = true) const {
    if (!inset_) return false;
    // The inset's quads lie on the side: a neck whose far corners all stand clear above it cannot fold over them.
    bool above = quick;
    for (const Vec3& c : b) above = above && glm::dot(c - inset_->center, inset_->normal) > inset_->tolerance;
    if (above) return false;
    const Vec3 middle = 0.25 * (a[0] + a[1] + a[2] + a[3]);
    double reach = 0.0;  // the band's and the inset's span
    for (const Vec3& x : b) reach = std::max(reach, glm::distance(x, middle));
    for (const QuadCorners& around : inset_->around) reach = std::max(reach, glm::distance(around.p[0], middle));
    const double margin = planeMargin(2.0 * reach);
    for (std::size_t k = 0; k < 4; ++k) {
      // Quad k of the inset runs from the port's edge k in to the inset's edge k: a plane through the inset's edge
      // with the band in front and the port's edge behind leaves them that edge alone in common.
      const QuadCorners& around = inset_->around[k];
      std::array<Vec3, 8> front{b[0], b[1], b[2], b[3]};
      std::size_t n = 4;
      for (std::size_t i = 0; i < 4; ++i) {
        if (port[i] != around.index[2] && port[i] != around.index[3]) front[n++] = a[i];
      }
      const std::array<Vec3, 2> behind{around.p[0], around.p[1]};
      if (edgePlane(around.p[3], around.p[2], {around.index[3], around.index[2]}, inset_->normal, middle - around.p[3],
                    std::span<const Vec3>(front.data(), n), behind, margin)) {
        continue;
      }
      for (std::size_t i = 0; i < 4; ++i) {
        if (quadsMeet(unmadeSide(a, port, b, i), around)) return true;
      }
    }
    return false;
  }

  // Where a child's tube may begin after a first cross section centred at `from`: past it along the skeleton, and
  // (a side child) where the skeleton has left the parent and any grandparent it must clear.
  double tubeStartPast(int stem, const StemPolyline& poly, const PortStart& start, const Vec3& from) const {
    const double rc = poly.radius(0.0);
    double s = poly.firstBeyond(start.branchPoint, glm::distance(from, start.branchPoint) + 0.5 * rc);
    // A clone leaving a split slab's side needs no clearance from the source's axis, which runs on through the clone
    // on top: at a split of a few degrees that lay metres up (the willow file's trunk clones split at 3 degrees),
    // the clone's limbs crowding its first slab there.
    if (!start.top && sk_.stems[static_cast<std::size_t>(stem)].cloneOf < 0) {
      // A child at a small angle runs along its parent; its tube begins where its skeleton has left the parent.
      const double clearance = std::sqrt(0.5) * start.parentReach + rc * opt_.limitCompensation;
      s = std::max(s, poly.firstClearOf(start.branchPoint, start.parentAxis, clearance, start.parentEnd + clearance));
    }
    return std::max(s, grandClearance(poly, start, rc));
  }

  // Where a moved child's skeleton has cleared its grandparent's cross sections with a ring of `radius`.
  double grandClearance(const StemPolyline& poly, const PortStart& start, double radius) const {
    if (!start.clearGrandparent) return 0.0;
    return poly.firstClearOf(start.grandPoint, start.grandAxis, std::sqrt(0.5) * start.grandReach + radius * opt_.limitCompensation);
  }

  // Corners of the cross section a stem would get at arc length s, continuing from `from` (at least minRadius).
  std::array<Vec3, 4> ringCorners(const StemPolyline& poly, const RingFrame& from, double s, double minRadius = 0.0) const {
    const RingFrame frame = transportFrame(from, poly.direction(s));
    const auto offsets = ringOffsets(frame, std::max({poly.radius(s), minRadius, resolution_}) * opt_.limitCompensation);
    const Vec3 c = poly.position(s);
    return {c + offsets[0], c + offsets[1], c + offsets[2], c + offsets[3]};
  }

  // A grid over the parent's faces, kept while its children are fitted.
  FaceGrid& parentGrid(std::size_t begin, std::size_t end) {
    for (auto it = grids_.rbegin(); it != grids_.rend(); ++it) {
      if ((*it)->begin == begin && (*it)->end == end) return (*it)->grid;
    }
    std::vector<Box> boxes;
    boxes.reserve(end - begin);
    for (std::size_t f = begin; f < end; ++f) {
      const auto& q = out_.mesh.quads[f];
      boxes.push_back(boxOf(std::array<Vec3, 4>{position(q[0]), position(q[1]), position(q[2]), position(q[3])}));
    }
    grids_.push_back(std::make_unique<ParentGrid>(ParentGrid{begin, end, FaceGrid{}}));
    grids_.back()->grid.build(std::move(boxes));
    return grids_.back()->grid;
  }

  // Side i of the band from corners a (vertex indices ids) to corners b, not made yet: b's carry indices no vertex has.
  static QuadCorners unmadeSide(const std::array<Vec3, 4>& a, const std::array<std::uint32_t, 4>& ids, const std::array<Vec3, 4>& b,
                                std::size_t i) {
    const std::size_t j = (i + 1) % 4;
    return QuadCorners{{a[i], a[j], b[j], b[i]},
                       {ids[i], ids[j], kUnmade + static_cast<std::uint32_t>(j), kUnmade + static_cast<std::uint32_t>(i)}};
  }

  // Whether the band from the port to corners b (not made yet) twists so far that its sides cross each other.
  static bool bandFolds(const std::array<Vec3, 4>& a, const std::array<std::uint32_t, 4>& port, const std::array<Vec3, 4>& b) {
    std::array<QuadCorners, 4> sides;
    for (std::size_t i = 0; i < 4; ++i) sides[i] = unmadeSide(a, port, b, i);
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t k = i + 1; k < 4; ++k) {
        if (quadsMeet(sides[i], sides[k])) return true;
      }
    }
    return false;
  }

  // Whether the band of four quads between two cross sections (corners in ring order) cuts a parent face;
  // `port`: a's vertex indices when a is the port, whose neighbouring faces the band must not fold over.
  bool bandCrossesParent(const PortStart& start, const std::array<Vec3, 4>& a, const std::array<Vec3, 4>& b,
                         const std::array<std::uint32_t, 4>* port = nullptr) {
    if (start.parentFacesEnd <= start.parentFacesBegin) return false;
    FaceGrid& grid = parentGrid(start.parentFacesBegin, start.parentFacesEnd);
    const Box band = boxOf(std::array<Vec3, 8>{a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]});
    std::array<std::array<Vec3, 4>, 4> sides;
    std::array<Box, 4> sideBoxes;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::size_t j = (i + 1) % 4;
      sides[i] = {a[i], a[j], b[j], b[i]};
      sideBoxes[i] = boxOf(sides[i]);
    }
    // A band off the port (not from its corners) is usually clear of the port's neighbours by a plane.
    std::optional<EdgePlanes> planes;
    if (!port) planes = bandPlanes(start.port, a, b);
    for (std::uint32_t f : grid.candidates(band)) {
      const Box& faceBox = grid.box(f);
      const auto& q = out_.mesh.quads[start.parentFacesBegin + f];
      const std::array<Vec3, 4> face{position(q[0]), position(q[1]), position(q[2]), position(q[3])};
      if (planes && behindOne(*planes, QuadCorners{face, q})) continue;
      for (int k = 0; k < 4; ++k) {
        const auto i = static_cast<std::size_t>(k), j = static_cast<std::size_t>((k + 1) % 4);
        const std::array<Vec3, 4>& side = sides[i];
        if (!sideBoxes[i].overlaps(faceBox)) continue;
        if (port) {
          // Beside the port the side meets the face at their shared corners only, as the check tests it
          // (b's corners are not made yet: indices no vertex has).
          const std::array<std::uint32_t, 4> ids{(*port)[i], (*port)[j], kUnmade + static_cast<std::uint32_t>(j),
                                                 kUnmade + static_cast<std::uint32_t>(i)};
          if (shareCorner(ids, q)) {
            if (quadsMeet(QuadCorners{side, ids}, QuadCorners{face, q})) return true;
            continue;
          }
        }
        // A side that shares a corner with the face touches it there by construction.
        bool shares = false;
        for (std::uint32_t v : q) shares = shares || position(v) == a[i] || position(v) == a[j];
        if (!shares && quadsIntersect(side, face)) return true;
      }
    }
    return false;
  }

  // The band from the first cross section to the next must not cut any face of the parent: the next cross
  // section moves along the skeleton until it does not, in doubling jumps and then halving back to within
  // `step` of where the band first clears (step by step took a fifth of a willow's XML -> OBJ time).
  double clearOfParent(const StemPolyline& poly, const PortStart& start, const RingFrame& exitFrame,
                       const std::array<Vec3, 4>& exitCorners, double s, double step) {
    const double end = poly.length();
    auto crosses = [&](double at) { return bandCrossesParent(start, exitCorners, ringCorners(poly, exitFrame, at)); };
    if (s >= end || !crosses(s)) return std::min(s, end);
    double bad = s, good = end;
    for (double jump = step; bad + jump < end; jump *= 2.0) {
      if (!crosses(bad + jump)) {
        good = bad + jump;
        break;
      }
      bad += jump;
    }
    if (good >= end) return end;
    while (good - bad > step) {
      const double mid = 0.5 * (bad + good);
      (crosses(mid) ? bad : good) = mid;
    }
    return good;
  }

  struct Slab {
    double lo = 0, hi = 0, h = 0;
    double first = 0, last = 0;  // its first and last attachment
    double need = 0;  // radius its cross sections need to hold its largest child
    int node = -1;
    std::vector<int> children;
    bool moved = false;  // its children attach before the tube begins (or past its end) and were moved
  };

  // The widest start radius among these stems: what the slab they leave from must hold.
  double widestStart(const std::vector<int>& stems) const {
    double rc = 0.0;
    for (int c : stems) rc = std::max(rc, sk_.stems[static_cast<std::size_t>(c)].startRadius);
    return rc;
  }

  // Half a slab's height for children as wide as rc on a parent of radius ra: 1.2 child radii, within 0.3 to 1
  // parent radius.
  static double slabHalfHeight(double rc, double ra) { return std::clamp(1.2 * rc, 0.3 * ra, ra); }

  // Distance kept between plain cross sections: half the local radius (never zero on hair-thin twigs).
  double gapAt(const StemPolyline& poly, double s) const {
    return std::max(0.5 * poly.radius(std::min(s, poly.length())), 0.1 * resolution_);
  }

  // Connection slabs centred on their attachments, never pushed along the stem (a pushed slab's first
  // band runs back to its skeleton and cuts other branches). Attachments that nearly coincide share a slab
  // whatever their number, through sub-boxes. Neighbouring slabs shrink to meet halfway: one-child slabs
  // share the cross section there, busier ones keep a thin band between them, so no corner is in more than
  // two ports. Children attached before the tube begins (inside the stem's own parent) join the first slab, but for
  // those `onNeck` accepts: their nodes go to `neck` instead (neckPorts).
  std::vector<Slab> layOutSlabs(int stem, const StemPolyline& poly, double from, double to, std::vector<int>* neck = nullptr,
                                const std::function<bool(int)>& onNeck = {}) const {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    const int lastNode = st.firstNode + st.nodeCount - 1;
    std::vector<Slab> slabs;
    for (int i = 0; i < poly.pointCount(); ++i) {
      const int node = poly.node(i);
      if (node == st.attachNode || node == lastNode) continue;
      const auto& children = stemsAt_[static_cast<std::size_t>(node)];
      if (children.empty()) continue;
      const double ra = std::max(poly.radius(poly.arcLength(i) - 1e-9), 0.1 * resolution_);
      const double rc = widestStart(children);
      const double h = slabHalfHeight(rc, ra);
      const double hMin = 0.15 * ra;
      if (neck && poly.arcLength(i) < from + hMin && (!onNeck || onNeck(node))) {
        neck->push_back(node);
        continue;
      }
      const double s = to - from > 2.0 * hMin ? std::clamp(poly.arcLength(i), from + hMin, to - hMin) : from + hMin;
      const bool moved = s != poly.arcLength(i);
      if (!slabs.empty()) {
        Slab& prev = slabs.back();
        // Attachments that nearly coincide share a slab; any others get one each (sharing one for being within
        // a parent radius, up to three, made more crossings: the aspen's 71 mesh-made pairs became 108).
        if (s - prev.first < 2.0 * hMin) {
          prev.children.insert(prev.children.end(), children.begin(), children.end());
          prev.last = s;
          prev.h = std::max(prev.h, h);
          prev.need = std::max(prev.need, rc);
          continue;
        }
      }
      slabs.push_back(Slab{0.0, 0.0, h, s, s, rc, node, children, moved});
    }
    // Each slab spans its attachments and h beyond them, within [from, to]; then neighbours are fitted.
    for (Slab& slab : slabs) {
      slab.lo = std::max(slab.first - slab.h, from);
      slab.hi = slab.last + slab.h;
    }
    if (!slabs.empty()) {
      Slab& end = slabs.back();  // ends before the tip (or the split), however close to it its child attaches
      end.hi = std::min(end.hi, to - 0.2 * (to - end.last));  // never at it: that band would have no length
      if (end.hi <= end.last) end.hi = end.last + 0.5 * (to - end.last);
    }
    for (std::size_t j = 1; j < slabs.size(); ++j) {
      Slab& a = slabs[j - 1];
      Slab& b = slabs[j];
      const double room = b.first - a.last;
      if (b.lo >= a.hi + 0.2 * room) continue;
      const double mid = 0.5 * (a.last + b.first);
      const bool share = a.children.size() == 1 && b.children.size() == 1;
      a.hi = share ? mid : mid - 0.1 * room;
      b.lo = share ? mid : mid + 0.1 * room;
    }
    return slabs;
  }

  // Whether the straight line from the stem's point `from` to point `to` passes every point between within its radius.
  static bool chordPasses(const StemPolyline& poly, int from, int to) {
    if (to >= poly.pointCount()) return true;
    const Vec3 a = poly.position(poly.arcLength(from)), b = poly.position(poly.arcLength(to));
    for (int j = from + 1; j < to; ++j) {
      const double s = poly.arcLength(j);
      const Vec3 p = poly.position(s);
      if (segmentDistance(p, p, a, b) > poly.radius(s)) return false;
    }
    return true;
  }

  // Whether a child's skeleton, once out of its parent's reach about the branch point, comes back within it.
  static bool runsBackThrough(const StemPolyline& poly, const PortStart& start) {
    const double reach = start.slabReach;
    double farthest = 0.0;
    for (int i = 1; i < poly.pointCount(); ++i) {
      const Vec3 a = poly.position(poly.arcLength(i - 1)), b = poly.position(poly.arcLength(i));
      farthest = std::max(farthest, glm::distance(a, start.branchPoint));
      const Vec3 d = b - a;
      const double t = glm::dot(d, d) > 0.0 ? std::clamp(glm::dot(start.branchPoint - a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
      if (farthest > reach && glm::distance(a + t * d, start.branchPoint) < reach) return true;
    }
    return false;
  }

  void continueStem(int stem, const StemPolyline& poly, Ring last, double sLo, double sUnclear, const PortStart* start) {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    const int lastNode = st.firstNode + st.nodeCount - 1;
    const bool split = sk_.nodes[static_cast<std::size_t>(lastNode)].kind == NodeKind::Split &&
                       !stemsAt_[static_cast<std::size_t>(lastNode)].empty();
    const double sEnd = poly.length();

    // Where slabs may lie: after the first cross section, and before the tip or the split slab.
    double tubeStart = start ? sLo + 0.25 * poly.radius(sLo) : 0.0;
    Slab splitSlab;
    double slabsEnd = sEnd;
    if (split) {
      const auto& clones = stemsAt_[static_cast<std::size_t>(lastNode)];
      const double rc = widestStart(clones);
      const double ra = poly.radius(sEnd);
      splitSlab.h = std::clamp(1.2 * rc, 0.5 * ra, ra);
      splitSlab.node = lastNode;
      splitSlab.need = rc;
      splitSlab.children = clones;
      splitSlab.lo = std::max(sEnd - splitSlab.h, tubeStart);
      splitSlab.hi = splitSlab.lo + 2.0 * splitSlab.h;
      slabsEnd = splitSlab.lo;
    }
    std::vector<Slab> slabs = layOutSlabs(stem, poly, tubeStart, slabsEnd);
    // A stem whose tube begins past its end squeezes the slab of its children to nothing or less (two coincident
    // cross sections: four sliver quads, or a slab upside down). Neither repair below happens on a Weber-Penn tree
    // (22 species at seeds 1-5): its tips taper to a point, so its thinnest such slab is 0.006 of its children's
    // radius (wheat, barley), and its stems do not turn back through their parents.
    auto squeezed = [&] {
      return !slabs.empty() && !split && tubeStart > slabsEnd && slabs.back().hi - slabs.back().lo < 1e-3 * slabs.back().need;
    };
    if (!slabs.empty() && !split && tubeStart > slabsEnd && sUnclear < sLo && runsBackThrough(poly, *start)) {
      // Its first band could not clear the parent anywhere because its skeleton turns back through the parent
      // (a trunk through its hub): that crossing is the skeleton's, so the tube begins where it would without
      // clearing, on its skeleton, rather than the whole stem becoming one cone with its children past its tip.
      sLo = sUnclear;
      tubeStart = sLo + 0.25 * poly.radius(sLo);
      slabs = layOutSlabs(stem, poly, tubeStart, slabsEnd);
    }
    // Its skeleton never leaves the parent: the slab gets two start radii of room past the tip, along the last edge.
    const double slabsTo = squeezed() ? tubeStart + 2.0 * poly.radius(0.0) : slabsEnd;
    if (slabsTo != slabsEnd) slabs = layOutSlabs(stem, poly, tubeStart, slabsTo);
    // Children attached along a long neck leave through it where they attach (neckPorts), not from the first slab.
    if (opt_.neckPorts && start && !start->top && glm::distance(last.center, poly.position(tubeStart)) >= kNeckPortsFrom * poly.radius(0.0)) {
      std::vector<int> neckNodes;
      std::vector<Slab> rest = layOutSlabs(stem, poly, tubeStart, slabsTo, &neckNodes, [&](int node) { return onNeck(poly, last, tubeStart, node); });
      if (!neckNodes.empty()) {
        slabs = std::move(rest);
        neck_ = NeckChildren{last.v, stem, std::move(neckNodes)};
      }
    }
    // Its wood clears the parent only where it splits (a limb fused along its trunk, the willow file's): no tube, the
    // clones and the children laid out there leave one box. Its first cross section stood on the skeleton beside
    // the collar and the split slab squeezed after it folded against the neck, or ended a metre-long neck inside
    // the parent's corners (the willow file at seeds 1-3: mesh-made pairs 59 -> 7, those against their trunks 52 -> 0).
    if (split && start && !start->top && start->parentReach > 0.0 && st.cloneOf < 0 && tubeStart > sEnd - splitSlab.h) {
      std::vector<int> moved;
      for (const Slab& slab : slabs) {
        moved.insert(moved.end(), slab.children.begin(), slab.children.end());
        splitSlab.need = std::max(splitSlab.need, slab.need);
      }
      // A collar near the split is the box's first cross section, the box along the collar (across the neck's end).
      // Otherwise the box stands at the split, moved out from the parent's axis until its corners clear the parent's.
      const bool near = glm::distance(last.center, poly.position(sEnd)) <= kFusedSplitNear * poly.radius(0.0);
      Ring lo = last;
      if (!near) {
        Vec3 p = poly.position(sEnd);
        const Vec3 rel = p - start->branchPoint;
        const Vec3 radial = rel - glm::dot(rel, start->parentAxis) * start->parentAxis;
        const double r = std::max(poly.radius(sEnd), splitSlab.need);
        const double clear = start->parentReach + r * opt_.limitCompensation;
        const double off = glm::length(radial);
        if (off < clear && off > 0.0) p += radial * ((clear - off) / off);
        const RingFrame frame = transportFrame(last.frame, poly.endDirection());
        lo = emitRing(stem, p, frame, r, last.tex + barkTextureAdvance(glm::distance(p, last.center), r), sEnd);
        band(last, lo);
      }
      // Children attached along the fused length join the box where it stands within reach of their attachment;
      // farther ones are fake branches now (left to the next pass, they cost the whole tree a second meshing).
      const Vec3 boxAxis = near ? lo.frame.T : poly.endDirection();
      const std::vector<int> joined = joinedHere(lo.center + boxAxis * (0.5 * (splitSlab.hi - splitSlab.lo)), poly.radius(sEnd), moved);
      splitSlab.children.insert(splitSlab.children.end(), joined.begin(), joined.end());
      connectingMoved_ = !joined.empty();
      connectSplit(stem, lo, splitSlab, boxAxis);
      connectingMoved_ = false;
      return;
    }
    auto gap = [&](double at) { return gapAt(poly, at); };

    // Plain cross sections at the stem's own nodes outside slabs, then extra ones for even spacing.
    std::vector<std::pair<double, int>> stations;  // arc length, slab index ending there (-1: plain)
    auto addPlain = [&](double s) {
      for (const Slab& slab : slabs) {
        if (s > slab.lo - gap(slab.lo) && s < slab.hi + gap(slab.hi)) return;
      }
      if (s > sLo + gap(sLo)) stations.emplace_back(s, -2);
    };
    int pinned = 0;  // the last point the tube passes through: the chord from it must pass the points skipped since
    for (int i = 0; i < poly.pointCount(); ++i) {
      const int node = poly.node(i);
      if (node == st.attachNode || node == lastNode) continue;
      // Intermediate nodes pin the surface next to a joint; the slab's own cross sections do that here.
      const NodeKind kind = sk_.nodes[static_cast<std::size_t>(node)].kind;
      if (kind == NodeKind::Before || kind == NodeKind::After) continue;
      // A branch point whose children are all left to impostors needs no cross section of its own, unless the tube
      // would then pass it (or the ones skipped before it) farther than its radius: where the stem turns (an
      // L-system's every node may), it cut the corner across its parent and neighbours.
      if (kind == NodeKind::Attachment && stemsAt_[static_cast<std::size_t>(node)].empty() && chordPasses(poly, pinned, i + 1)) continue;
      pinned = i;
      addPlain(poly.arcLength(i));
    }
    for (std::size_t j = 0; j < slabs.size(); ++j) {
      if (j == 0 || slabs[j].lo != slabs[j - 1].hi) stations.emplace_back(slabs[j].lo, -1);
      stations.emplace_back(slabs[j].hi, static_cast<int>(j));
    }
    std::stable_sort(stations.begin(), stations.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

    double endS = sEnd;
    if (split) {
      endS = splitSlab.lo;
    } else {
      // The tip ring sits at the skeleton's tip; only a station right at the tip moves it on a little.
      const double after = stations.empty() ? sLo : stations.back().first;
      endS = std::max(sEnd, after + 0.1 * gap(after));
    }
    while (!stations.empty() && stations.back().first > endS - gap(endS) * 0.5) {
      if (stations.back().second == -2) stations.pop_back();
      else break;
    }
    stations.emplace_back(endS, split ? -3 : -4);

    // leavePort cleared the band from the first cross section to arc length sLo; where the first station lies
    // further on, a cross section at sLo comes first: the tube is back on its skeleton at its own radius right
    // after the collar, instead of a long cone from the collar (a wide, off-axis first band that cuts others).
    // Never behind the collar's cross section: that would fold the tube back on itself. Only for children
    // leaving at more than 30 degrees, at least half as thick as their parent, or with no clearance from their parent
    // to keep (parentReach 0: through a top, a split's clones, trunks on a hub): a thin one running along its parent
    // (barley's awns, a willow's hanging twigs) bends back to its skeleton beside its neighbours' necks (barley's
    // mesh-made pairs 3,647 with it, 340 without; all trees 1,206 -> 1,230 with every shallow child, -> 1,105 with
    // these only; most of that from the clearance-free ones: leaving them out later gave 1,048 against 973).
    const bool steep = start && glm::length(glm::cross(poly.startDirection(), start->parentAxis)) > 0.5;
    const bool thick = start && (start->parentReach <= 0.0 || poly.radius(0.0) >= 0.5 * start->parentReach / opt_.limitCompensation);
    if ((steep || thick) && sLo < stations.front().first - 4.0 * gap(sLo) && glm::dot(poly.position(sLo) - last.center, last.frame.T) > 0.0) {
      // Where the skeleton turns there, the cross section moves on by quarter radii until its band runs forwards.
      double at = sLo;
      const double next = stations.front().first;
      auto fits = [&](double s) { return ringAhead(poly, last, s) && !firstBandsCross(poly, last, s, next); };
      // Past kFineSteps half gaps the steps widen to a kFineSteps-th of the span: a fuzzed graph's 36 km internode of
      // 1 cm twigs took millions of steps (18 s).
      for (int k = 0; !fits(at) && at + gap(at) < next - 4.0 * gap(sLo); ++k) {
        at += k < kFineSteps ? 0.5 * gap(at) : std::max(0.5 * gap(at), (next - sLo) / kFineSteps);
      }
      if (fits(at)) {
        last = advance(stem, poly, last, at);
        sLo = at;
      }
    }
    // A last slab within 1.5 radii of the tip whose most aligned child runs on along the stem (within 25 degrees):
    // that child leaves through the slab's top and the stem ends there, as a split's clone does (its tapered tail is
    // left out). From a side, such a child (a palm's crown fronds, an aspen's top limbs) ran a long neck up beside
    // the tip across its neighbours: all trees' mesh-made pairs at seeds 1-3 1,606 -> 1,504.
    int topSlab = -1;
    if (!split && !slabs.empty() && stations.size() >= 2 && stations[stations.size() - 2].second == static_cast<int>(slabs.size()) - 1 &&
        sEnd - slabs.back().hi <= kTopTail * poly.radius(slabs.back().lo)) {
      double best = -1.0;
      for (const PortRequest& r : requestsFor(slabs.back().children)) best = std::max(best, glm::dot(r.direction, poly.direction(slabs.back().hi)));
      if (best >= kTopAligned) topSlab = static_cast<int>(slabs.size()) - 1;
    }
    double previousS = sLo;
    const std::array<std::uint32_t, 4> collar = last.v;  // the band from the collar may arrive sideways
    const bool trunkClone = st.level == 0 && st.cloneOf >= 0;
    for (const auto& [s, role] : stations) {
      // Extra cross sections where the spacing limits ask for them (never inside a slab).
      if (role < 0) {  // a slab's own band gets no extra cross sections
        const double span = s - previousS;
        // Towards a tip, and on hair-thin twigs, the radius vanishes; floors keep the count sensible.
        const double r = std::max({poly.radius(0.5 * (s + previousS)), 0.5 * poly.radius(0.0), poly.length() / 48.0});
        double limit = opt_.ringSpacing > 0.0 ? opt_.ringSpacing * std::max(r, 1e-6) : span;
        if (opt_.maxRingDistance > 0.0) limit = std::min(limit, opt_.maxRingDistance);
        // Counted in floating point first: a spacing of 1e-300 radii must be refused, not overflow an int.
        const double wanted = limit > 0.0 ? std::max(0.0, std::ceil(span / limit) - 1.0) : 0.0;
        if (4.0 * wanted > static_cast<double>(opt_.maxQuads - std::min(opt_.maxQuads, out_.mesh.quads.size()))) {
          throw LimitError(tooManyQuads(wanted));
        }
        const int extra = static_cast<int>(wanted);
        for (int k = 1; k <= extra; ++k) last = advance(stem, poly, last, previousS + span * k / (extra + 1));
      }
      if (role == -4) {
        // Tip: a last cross section (never thinner than a third of the one before) and a cap.
        const Vec3 p = poly.position(s);
        const double r = std::max(poly.radius(std::min(s, sEnd)), 0.35 * last.radius);
        RingFrame frame = transportFrame(last.frame, poly.endDirection());
        // Turned to a tip that bends away within a radius of the last cross section, its band ran backwards and
        // folded: the tip turns half-way then, or keeps the last cross section's direction.
        auto ahead = [&](const RingFrame& f) {
          const auto offsets = ringOffsets(f, r * opt_.limitCompensation);
          return bandAhead(last, {p + offsets[0], p + offsets[1], p + offsets[2], p + offsets[3]}, p, f.T);
        };
        if (!ahead(frame)) {
          const RingFrame half = transportFrame(last.frame, directionOr(last.frame.T + poly.endDirection(), last.frame.T));
          frame = ahead(half) ? half : last.frame;
        }
        const Ring tip = emitRing(stem, p, frame, r, last.tex + barkTextureAdvance(glm::distance(p, last.center), r), s);
        band(last, tip);
        addQuad(tip.v[0], tip.v[1], tip.v[2], tip.v[3]);
        return;
      }
      if (role == -3) {
        // A split slab right after the tube's start (a short stem): its band from there, a quarter radius long,
        // runs backwards where the skeleton turns; the slab moves on until that band runs forwards (or keeps the
        // last cross section's direction after eight radii): the larch file's folds. Eight, not two: a short stem's
        // collar cross section can lie three radii off its skeleton (larch file mesh-made 6,072 -> 4,142, seeds 1-3;
        // sixteen or more made the desert bush's worse).
        double at = s;
        const double step = 0.25 * std::max(poly.radius(std::min(s, sEnd)), splitSlab.need);
        while (!ringAhead(poly, last, at, splitSlab.need) && at < s + 32.0 * step) at += step;
        const bool keep = !ringAhead(poly, last, at, splitSlab.need);
        if (keep) at = s;
        splitSlab.hi += at - splitSlab.lo;
        splitSlab.lo = at;
        const Ring lo = makeRing(stem, poly, last, at, splitSlab.need, keep);
        band(last, lo);
        connectSplit(stem, lo, splitSlab, poly.endDirection());
        return;
      }
      // A plain cross section the band to which would run backwards (the inside of a bend tighter than the radius)
      // is left out: the tube goes on to the next one (all trees' folds 1,584 -> 1,551, mesh-made pairs -0.7 %).
      if (role == -2 && !ringAhead(poly, last, s)) continue;
      // A slab's first cross section the band to which would run backwards (behind a collar standing off the
      // skeleton, or where the slab's children attach before the tube begins) moves on within the slab until it
      // runs forwards; failing that, a collar no port uses yet is the slab's first cross section itself. All trees
      // at seeds 1-3: mesh-made pairs 1,830 -> 1,724, folds 19 -> 8 (any cross section as the slab's first: the
      // same, but a vertex of a random branch graph then had valence 7 or 8).
      double at = s;
      const Slab* slab = role == -1 ? slabStartingAt(slabs, s) : nullptr;
      if (slab && last.v == collar && unused(last) && slabFolds(poly, last, *slab) && ringAhead(poly, last, slab->hi, slab->need)) continue;
      // A trunk clone's slab holding children moved from before its tube begins, past the joint floor from them,
      // starts at the collar where that brings them nearer (the willow file's limb 287 on clone 4: 1.72 -> 1.51 clone
      // radii at seed 1, then within by its inset; 2.58 -> 1.62 at seed 3). Not on every stem: the slab's middle is
      // only an estimate of where a thin child's inset goes, and the tupelo file's level-2 branches, whose twigs'
      // insets were within already, got a tenth more skeleton-made pairs.
      if (slab && slab->moved && trunkClone && last.v == collar && unused(last) && nearerFromCollar(poly, last, *slab) &&
          ringAhead(poly, last, slab->hi, slab->need)) {
        continue;
      }
      if (slab && !ringAhead(poly, last, s, slabNeed(slabs, s))) {
        const double step = 0.1 * slab->need;
        for (double a = s + step; a < slab->hi - 0.3 * slab->need && at == s; a += step) {
          if (ringAhead(poly, last, a, slab->need)) at = a;
        }
        if (at == s && unused(last) && ringAhead(poly, last, slab->hi, slab->need)) continue;
      }
      const Ring next = makeRing(stem, poly, last, at, role >= -1 ? slabNeed(slabs, s) : 0.0, false, slabAxis(poly, slabs, s, role));
      if (role < 0) band(last, next);
      else if (connectSlab(stem, last, next, slabs[static_cast<std::size_t>(role)], role == topSlab)) return;
      last = next;
      previousS = s;
    }
  }

  // A slab around a sharp turn of its stem: both its cross sections face along its chord, so the slab is a straight
  // box and the inside of the turn cannot fold between them (each facing its own edge, they crossed there).
  static std::optional<Vec3> slabAxis(const StemPolyline& poly, const std::vector<Slab>& slabs, double s, int role) {
    if (role < -1) return std::nullopt;
    for (const Slab& slab : slabs) {
      if (role >= 0 ? &slab != &slabs[static_cast<std::size_t>(role)] : slab.lo != s) continue;
      const Vec3 chord = poly.position(slab.hi) - poly.position(slab.lo);
      if (glm::dot(poly.direction(slab.lo), poly.direction(slab.hi)) > kSlabTurn || glm::length(chord) <= 0.0) return std::nullopt;
      return glm::normalize(chord);
    }
    return std::nullopt;
  }

  // The slab whose first cross section is at arc length lo (null: none).
  static const Slab* slabStartingAt(const std::vector<Slab>& slabs, double lo) {
    const auto slab = std::find_if(slabs.begin(), slabs.end(), [lo](const Slab& x) { return x.lo == lo; });
    return slab == slabs.end() ? nullptr : &*slab;
  }

  // The bands cross sections at s and then at `next` would make, not yet built: the four quads from `last` to the
  // one at s, then the four from there to the one at `next` (side k of each at k and 4 + k).
  std::array<QuadCorners, 8> bandsTo(const StemPolyline& poly, const Ring& last, double s, double next, double need) const {
    const RingFrame frame = transportFrame(last.frame, poly.direction(s));
    const std::array<Vec3, 4> a = ringCorners(poly, last.frame, s, need), b = ringCorners(poly, frame, next, need);
    std::array<QuadCorners, 8> quads;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t j = (k + 1) % 4;
      quads[k] = {{position(last.v[k]), position(last.v[j]), a[j], a[k]}, {last.v[k], last.v[j], kUnmade + j, kUnmade + k}};
      quads[4 + k] = {{a[k], a[j], b[j], b[k]}, {kUnmade + k, kUnmade + j, kUnmade + 4 + j, kUnmade + 4 + k}};
    }
    return quads;
  }

  // Whether the band from `last` to the slab's first cross section folds over the slab's own band on one of its
  // sides: a long first band arriving sideways (a neck standing off the skeleton) just before a thin slab squeezed
  // against where the tube begins.
  bool slabFolds(const StemPolyline& poly, const Ring& last, const Slab& slab) const {
    if (slab.hi <= slab.lo) return false;
    const std::array<QuadCorners, 8> quads = bandsTo(poly, last, slab.lo, slab.hi, slab.need);
    for (std::size_t k = 0; k < 4; ++k)
      if (quadsMeet(quads[k], quads[4 + k])) return true;
    return false;
  }

  // Whether the band from `last` to a cross section at s, or the band from there to one at `next`, crosses itself or
  // the other: a collar beside its skeleton (on a parent's neck port) level with that cross section makes a band
  // that runs sideways and twists into the next.
  bool firstBandsCross(const StemPolyline& poly, const Ring& last, double s, double next) const {
    const std::array<QuadCorners, 8> quads = bandsTo(poly, last, s, next, 0.0);
    for (std::size_t i = 0; i < quads.size(); ++i)
      for (std::size_t j = i + 1; j < quads.size(); ++j)
        if (quadsMeet(quads[i], quads[j])) return true;
    return false;
  }

  // The node where `child` attaches to its parent.
  const SkeletonNode& attachmentOf(int child) const {
    return sk_.nodes[static_cast<std::size_t>(sk_.stems[static_cast<std::size_t>(child)].attachNode)];
  }

  // How far p lies from where `child` attaches, along its parent's skeleton there: as the joint floor is measured.
  double alongFromAttachment(int child, const Vec3& p) const {
    const SkeletonNode& at = attachmentOf(child);
    return std::abs(glm::dot(p - at.world.position, at.world.direction()));
  }

  // Whether a slab holding children moved from before the tube's start leaves one past the joint floor from its
  // attachment (along the parent there, at the slab's middle), and starting at the collar `last` would leave the
  // farthest nearer.
  bool nearerFromCollar(const StemPolyline& poly, const Ring& last, const Slab& slab) const {
    const Vec3 hi = poly.position(slab.hi);
    const Vec3 usual = 0.5 * (poly.position(slab.lo) + hi), fromCollar = 0.5 * (last.center + hi);
    double worstUsual = 0.0, worstCollar = 0.0;
    for (const int c : slab.children) {
      const double ra = std::max(attachmentOf(c).radius, 1e-12);
      worstUsual = std::max(worstUsual, alongFromAttachment(c, usual) / ra);
      worstCollar = std::max(worstCollar, alongFromAttachment(c, fromCollar) / ra);
    }
    return worstUsual > kFarChild && worstCollar < worstUsual;
  }

  // A cross section none of whose corners is a port's yet.
  bool unused(const Ring& r) const {
    return std::all_of(r.v.begin(), r.v.end(), [&](std::uint32_t v) { return portUse_[v] == 0; });
  }

  // minRadius: a slab's cross sections must hold its children, even where the stem tapers to a point.
  static double slabNeed(const std::vector<Slab>& slabs, double s) {
    double need = 0.0;
    for (const Slab& slab : slabs) {
      if (slab.lo == s || slab.hi == s) need = std::max(need, slab.need);
    }
    return need;
  }

  // keepFrame: the last cross section's frame instead of one turned to the skeleton's direction at s; axis: a
  // direction to face instead of the skeleton's (a slab on a sharp turn).
  Ring makeRing(int stem, const StemPolyline& poly, const Ring& last, double s, double minRadius = 0.0, bool keepFrame = false,
                std::optional<Vec3> axis = std::nullopt) {
    const Vec3 p = poly.position(s);
    const double r = std::max({poly.radius(s), minRadius, resolution_});
    const RingFrame frame = keepFrame ? last.frame : transportFrame(last.frame, axis.value_or(poly.direction(s)));
    return emitRing(stem, p, frame, r, last.tex + barkTextureAdvance(glm::distance(p, last.center), 0.5 * (r + last.radius)), s);
  }

  // Whether a band from ring a to the cross section with corners b (centre c, direction t) runs forwards: b's
  // corners ahead of a's plane and a's behind b's. Where it does not, the inside of a tight bend folds.
  bool bandAhead(const Ring& a, const std::array<Vec3, 4>& b, const Vec3& c, const Vec3& t) const {
    for (std::size_t k = 0; k < 4; ++k) {
      if (glm::dot(b[k] - a.center, a.frame.T) <= 0.0) return false;
      if (glm::dot(position(a.v[k]) - c, t) >= 0.0) return false;
    }
    return true;
  }

  // Whether the band from `last` to the cross section the stem would get at arc length s (at least minRadius)
  // runs forwards.
  bool ringAhead(const StemPolyline& poly, const Ring& last, double s, double minRadius = 0.0) const {
    return bandAhead(last, ringCorners(poly, last.frame, s, minRadius), poly.position(s),
                     transportFrame(last.frame, poly.direction(s)).T);
  }

  Ring advance(int stem, const StemPolyline& poly, const Ring& last, double s) {
    const Ring next = makeRing(stem, poly, last, s);
    band(last, next);
    return next;
  }

  // ---- connections ----

  std::array<bool, 4> allowedSides(const Ring& lo, const Ring& hi) const {
    std::array<bool, 4> allowed{};
    for (int k = 0; k < 4; ++k) {
      bool ok = true;
      for (std::uint32_t v : side(lo, hi, k)) ok = ok && portUse_[v] < 2;
      allowed[static_cast<std::size_t>(k)] = ok;
    }
    return allowed;
  }

  std::vector<PortRequest> requestsFor(const std::vector<int>& children) const {
    std::vector<PortRequest> requests;
    for (int c : children) {
      // The direction of the child's first edge, from its attach node to its first own node.
      const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(c)];
      const Vec3 from = sk_.nodes[static_cast<std::size_t>(st.attachNode)].world.position;
      const Vec3 to = sk_.nodes[static_cast<std::size_t>(st.firstNode)].world.position;
      requests.push_back(PortRequest{glm::normalize(to - from), st.startRadius});
    }
    return requests;
  }

  // Assigns children to the sides (and top, if `top` is given) of the slab between lo and hi, emits the
  // quads that stay, and builds the children.
  void connect(int parentStem, int node, const Ring& lo, const Ring& hi, const std::vector<int>& children,
               const Ring* top, bool roof) {
    const Vec3 axis = glm::normalize(hi.center - lo.center);
    const Vec3 slabCenter = 0.5 * (lo.center + hi.center);
    std::array<Vec3, 4> normals;
    for (int k = 0; k < 4; ++k) normals[static_cast<std::size_t>(k)] = glm::normalize(faceCenter(side(lo, hi, k)) - slabCenter);
    const auto requests = requestsFor(children);
    CornerTurns* turns = parentStem >= 0 ? &cornerTurns_[static_cast<std::size_t>(parentStem)] : nullptr;
    const PortAssignment a = assignPorts(normals, axis, requests, allowedSides(lo, hi), top != nullptr, turns);

    if (roof && top && a.top >= 0) {
      int used = -1, count = 0;
      for (int k = 0; k < 4; ++k) {
        if (!a.sides[static_cast<std::size_t>(k)].empty()) { used = k; ++count; }
      }
      if (count == 1) raiseRoof(lo, hi, used);
    }

    MeshJoint joint;
    joint.node = node;
    joint.parentStem = parentStem;
    joint.childStems = children;
    joint.center = sk_.nodes[static_cast<std::size_t>(node)].world.position;
    joint.radius = sk_.nodes[static_cast<std::size_t>(node)].radius;

    std::array<bool, 4> skip{};
    for (int k = 0; k < 4; ++k) skip[static_cast<std::size_t>(k)] = !a.sides[static_cast<std::size_t>(k)].empty();
    band(lo, hi, skip);

    std::vector<std::pair<std::array<std::uint32_t, 4>, std::vector<int>>> ports;
    for (int k = 0; k < 4; ++k) {
      const auto& on = a.sides[static_cast<std::size_t>(k)];
      if (on.empty()) continue;
      std::vector<int> stems;
      for (int r : on) stems.push_back(children[static_cast<std::size_t>(r)]);
      const auto q = side(lo, hi, k);
      for (std::uint32_t v : q) ++portUse_[v];
      ports.emplace_back(q, std::move(stems));
    }
    const Vec3 branchPoint = joint.center;
    const double parentEnd = endAlong(parentStem, branchPoint, axis);
    const double slabReach = std::max(lo.radius, hi.radius) * opt_.limitCompensation;
    auto portStart = [&](const std::array<std::uint32_t, 4>& q, bool onTop, double reach) {
      PortStart p{q, branchPoint, onTop, axis, reach};
      p.slabReach = slabReach;
      p.parentEnd = parentEnd;
      p.tex = portTex(q);
      p.moved = slabMoved_;
      p.onNeck = neckSlab_;
      return withGrandparent(p);
    };
    if (top && a.top >= 0) deferred_->emplace_back(children[static_cast<std::size_t>(a.top)], portStart(top->v, true, 0.0));
    // Past a split the parent's axis runs on through the clone on top, not the parent: clones need no clearance.
    // (Children beside a child through the top still clear their parent.)
    for (auto& [q, stems] : ports) {
      if (stems.size() == 1) {
        const bool clone = sk_.stems[static_cast<std::size_t>(stems[0])].cloneOf >= 0;
        deferred_->emplace_back(stems[0], portStart(q, false, top && clone ? 0.0 : slabReach));
      } else {
        ++joint.subBoxes;
        subBox(parentStem, node, q, stems);
      }
    }
    out_.joints.push_back(std::move(joint));
  }

  // throughTop: the slab's top goes to its child most aligned with the stem, which ends there; returns whether it
  // did (the slab had a child to give it to).
  bool connectSlab(int stem, const Ring& lo, const Ring& hi, const Slab& slab, bool throughTop = false) {
    connectingMoved_ = slab.moved && currentStart_ && !currentStart_->top;
    slabMoved_ = slab.moved;
    const std::vector<int> children = slab.moved ? joinedHere(lo, hi, slab.children) : slab.children;
    if (children.empty()) band(lo, hi);
    else connect(stem, slab.node, lo, hi, children, throughTop ? &hi : nullptr, false);
    connectingMoved_ = false;
    slabMoved_ = false;
    return throughTop && !children.empty();
  }

  // Of the children moved to a connection centred at `center` on a parent of radius ra there, those it joins. A
  // twig whose connection would lie more than kFakeFrom parent radii (or half its own length) along the parent from
  // where it attaches, inside its grandparent's wood where the parent has no surface, is a fake branch on its
  // skeleton instead: meshed there, its neck ran back through the parent to its skeleton and cut its neighbours. So
  // is a branch bearing only twigs, two or more levels from its trunk (a trunk's own limbs are always meshed).
  std::vector<int> joinedHere(const Vec3& center, double ra, const std::vector<int>& children) {
    if (!opt_.fakeDisplaced) return children;
    std::vector<int> joined;
    for (const int c : children) {
      const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(c)];
      // Measured along the parent's skeleton, as the joint floor is (a slab's own axis may lean off it).
      const double along = alongFromAttachment(c, center);
      const bool far = along > kFakeFrom * std::max(ra, attachmentOf(c).radius) || along > 0.5 * st.length;
      if (far && (!branching_[static_cast<std::size_t>(c)] || (st.level >= 2 && bearsTwigsOnly(c)))) fakeTwig(c);
      else joined.push_back(c);
    }
    return joined;
  }

 public:
  // The twigs (and twig-bearing branches off limbs) whose first ring this pass placed more than 1.5 parent radii
  // along their parent from where they attach (the joint floor), sorted: a neck port or a crowded sub-box can leave
  // one there although its connection lay within kFakeFrom. The next pass fakes them.
  std::vector<int> farTwigs() const {
    std::vector<int> far;
    if (!opt_.fakeDisplaced) return far;
    for (const ChildPlacement& c : childPlacements(sk_, out_)) {
      const auto i = static_cast<std::size_t>(c.stem);
      const SkeletonStem& st = sk_.stems[i];
      if (c.offset > kFarChild && (!branching_[i] || (st.level >= 2 && bearsTwigsOnly(c.stem)))) far.push_back(c.stem);
    }
    // So are stems left with no meshed child by the twigs this pass faked while joining them, where their wood
    // never clears their parent's (the ABOP plants' mesh-made pairs 8,500 -> 7,001 at seeds 1-3).
    const std::vector<bool> bearing = bearingStems();
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      if (branching_[i] && meshed(static_cast<int>(i)) && !faked_[i] && buried(static_cast<int>(i), bearing)) far.push_back(static_cast<int>(i));
    }
    std::sort(far.begin(), far.end());
    far.erase(std::unique(far.begin(), far.end()), far.end());
    return far;
  }

 private:
  // A stem, not bearing (no meshed child left), whose wood does not clear its parent's before it ends (or splits).
  bool buried(int stem, const std::vector<bool>& bearing) const {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    if (!opt_.fakeDisplaced || st.parentStem < 0 || st.cloneOf >= 0 || bearing[static_cast<std::size_t>(stem)]) return false;
    return clearance_[static_cast<std::size_t>(stem)] >= StemPolyline(sk_, stem).length();
  }

  // A meshed child not (yet) a fake branch makes its parent, and the stems that parent is a clone of, bearing.
  std::vector<bool> bearingStems() const {
    std::vector<bool> bearing(sk_.stems.size(), false);
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      const SkeletonStem& st = sk_.stems[i];
      if (!meshed(static_cast<int>(i)) || faked_[i]) continue;
      for (int x = st.cloneOf < 0 ? st.parentStem : -1; x >= 0 && !bearing[static_cast<std::size_t>(x)];
           x = sk_.stems[static_cast<std::size_t>(x)].cloneOf) {
        bearing[static_cast<std::size_t>(x)] = true;
      }
    }
    return bearing;
  }

  // A twig the mesh cannot join where it attaches is a fake branch with its clones, as a stub ending inside is:
  // - its wood does not clear its parent's before it ends or splits (it leaves at a few degrees): its tube would
  //   begin past its tip, or its split slab lie in its parent's side;
  // - it is shallow and thin: its neck would run along its parent's side across its neighbours' necks (barley's
  //   awns, the willows' hanging twigs);
  // - it attaches just before its parent splits: the clones leaving the split slab's sides ran over it;
  // - it attaches to a clone just past the split, inside another clone's wood (the desert bush's twigs); so does
  //   a branch off a limb bearing only twigs.
  bool unjoinableTwig(int stem) const {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    if (!opt_.fakeDisplaced || st.parentStem < 0 || st.cloneOf >= 0) return false;
    const SkeletonNode& at = sk_.nodes[static_cast<std::size_t>(st.attachNode)];
    if (branching_[static_cast<std::size_t>(stem)]) {
      return st.level >= 2 && bearsTwigsOnly(stem) && insideSiblingClone(st.parentStem, at.world.position, at.radius);
    }
    const double clearance = clearance_[static_cast<std::size_t>(stem)];
    const StemPolyline poly(sk_, stem);
    if (clearance >= poly.length() ||
        (clearance >= kShallowFrom * at.radius && st.startRadius <= kThinTwig * at.radius)) {
      return true;
    }
    const auto& splits = clones_[static_cast<std::size_t>(st.parentStem)];
    if (std::any_of(splits.begin(), splits.end(), [&](int c) {
          const double ahead = sk_.nodes[static_cast<std::size_t>(sk_.stems[static_cast<std::size_t>(c)].attachNode)].offset - at.offset;
          return ahead >= 0.0 && ahead <= kBeforeSplit * at.radius;
        })) {
      return true;
    }
    return insideSiblingClone(st.parentStem, at.world.position, at.radius) || (st.level >= 2 && crossesJoint(stem, poly));
  }

  // Whether a twig, once clear of its own parent, passes through the joint of a stem beside it (one leaving its
  // parent or its parent's parent): within that stem's collar reach (kCollarReach of its radii) of its axis from
  // where it leaves its parent to where its wood clears it; the collar and neck built there would cut the twig.
  bool crossesJoint(int stem, const StemPolyline& poly) const {
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    const double clear = clearance_[static_cast<std::size_t>(stem)];
    std::vector<Vec3> path{poly.position(std::min(clear, poly.length()))};
    for (int i = 0; i < poly.pointCount(); ++i) {
      if (poly.arcLength(i) > clear) path.push_back(poly.position(poly.arcLength(i)));
    }
    Box pathBox{path[0], path[0]};
    for (const Vec3& p : path) {
      pathBox.lo = glm::min(pathBox.lo, p);
      pathBox.hi = glm::max(pathBox.hi, p);
    }
    const int grand = sk_.stems[static_cast<std::size_t>(st.parentStem)].parentStem;
    for (const int from : {st.parentStem, grand}) {
      if (from < 0) continue;
      for (int c : children_[static_cast<std::size_t>(from)]) {
        if (c == stem || c == st.parentStem || faked_[static_cast<std::size_t>(c)]) continue;
        const auto& [a, b] = jointAxis_[static_cast<std::size_t>(c)];
        const double reach = (kCollarReach * sk_.stems[static_cast<std::size_t>(c)].startRadius + st.startRadius) * opt_.limitCompensation;
        const Box joint{glm::min(a, b) - Vec3(reach), glm::max(a, b) + Vec3(reach)};
        if (!joint.overlaps(pathBox)) continue;
        for (std::size_t i = 1; i < path.size(); ++i) {
          if (segmentDistance(path[i - 1], path[i], a, b) < reach) return true;
        }
      }
    }
    return false;
  }

  // Each child's clearance from its parent, and its joint as a segment: from its attach node to where its wood
  // clears its parent (or its tip).
  void layJointAxes() {
    jointAxis_.assign(sk_.stems.size(), {Vec3(0.0), Vec3(0.0)});
    clearance_.assign(sk_.stems.size(), 0.0);
    for (std::size_t i = 0; i < sk_.stems.size(); ++i) {
      const SkeletonStem& st = sk_.stems[i];
      if (st.parentStem < 0 || st.cloneOf >= 0 || st.attachNode < 0) continue;
      clearance_[i] = parentClearance(sk_, static_cast<int>(i));
      const StemPolyline poly(sk_, static_cast<int>(i));
      jointAxis_[i] = {poly.position(0.0), poly.position(std::min(clearance_[i], poly.length()))};
    }
  }

  // Whether a twig attached at `point` on `clone`, whose radius is `radius` there, would join it inside another clone
  // split from the same stem: just past a split the clones overlap, and where the other's axis is nearer than the two
  // cages' reach (the radii times limitCompensation) the twig's joint on its parent's cage lies in that clone's cage.
  bool insideSiblingClone(int clone, const Vec3& point, double radius) const {
    const int source = sk_.stems[static_cast<std::size_t>(clone)].cloneOf;
    if (source < 0) return false;
    for (int c : clones_[static_cast<std::size_t>(source)]) {
      if (c == clone) continue;
      const StemPolyline poly(sk_, c);
      const double s = poly.nearestArc(point);
      if (glm::distance(poly.position(s), point) < (poly.radius(s) + radius) * opt_.limitCompensation) return true;
    }
    return false;
  }

  // A twig, or a twig-bearing branch, with the clones it splits into and its children (never built: they would have
  // left through its split or its slabs) are fake branches.
  void fakeTwig(int stem) {
    if (faked_[static_cast<std::size_t>(stem)]) return;  // a twig inside its parent is faked before its parent is
    faked_[static_cast<std::size_t>(stem)] = true;
    out_.fakedStems.push_back(stem);
    for (int c : clones_[static_cast<std::size_t>(stem)]) fakeTwig(c);
    for (int c : children_[static_cast<std::size_t>(stem)]) fakeTwig(c);
  }

  // Whether every meshed child of a stem and of its clones is a twig.
  bool bearsTwigsOnly(int stem) const {
    const auto& children = children_[static_cast<std::size_t>(stem)];
    const auto& clones = clones_[static_cast<std::size_t>(stem)];
    return std::none_of(children.begin(), children.end(), [&](int c) { return branching_[static_cast<std::size_t>(c)]; }) &&
           std::all_of(clones.begin(), clones.end(), [&](int c) { return bearsTwigsOnly(c); });
  }

  std::vector<int> joinedHere(const Ring& lo, const Ring& hi, const std::vector<int>& children) {
    return joinedHere(0.5 * (lo.center + hi.center), std::max(lo.radius, hi.radius), children);
  }

  // Whether the children at `node`, attached before the tube begins, leave through the neck: where the node lies
  // along the neck (from the ring `last` to the tube's start, not past it) and near it (within kNeckReach of the
  // node's radii), and every child there leaves forwards along it. Others join the first slab as before: a child
  // far off the neck, or one leaving backwards, met its parent's tube or its own neighbours there (the ABOP figures).
  bool onNeck(const StemPolyline& poly, const Ring& last, double tubeStart, int node) const {
    const SkeletonNode& n = sk_.nodes[static_cast<std::size_t>(node)];
    const Vec3 axis = poly.position(tubeStart) - last.center;
    const double len2 = glm::dot(axis, axis);
    if (len2 <= 0.0) return false;
    const double t = glm::dot(n.world.position - last.center, axis) / len2;
    if (t > 1.0 || glm::distance(n.world.position, last.center + axis * t) > kNeckReach * n.radius) return false;
    for (int c : stemsAt_[static_cast<std::size_t>(node)]) {
      const Vec3 first = sk_.nodes[static_cast<std::size_t>(sk_.stems[static_cast<std::size_t>(c)].firstNode)].world.position;
      if (glm::dot(first - n.world.position, axis) < 0.0) return false;
    }
    return true;
  }

  // Whether a meshed child of the stem attaches within arc length `arc` of its start.
  bool attachedWithin(int stem, const StemPolyline& poly, double arc) const {
    const int from = sk_.stems[static_cast<std::size_t>(stem)].attachNode;  // its parent's children there are not its own
    for (int i = 0; i < poly.pointCount() && poly.arcLength(i) < arc; ++i) {
      if (poly.node(i) == from) continue;
      for (int c : stemsAt_[static_cast<std::size_t>(poly.node(i))]) {
        if (sk_.stems[static_cast<std::size_t>(c)].cloneOf < 0) return true;
      }
    }
    return false;
  }

  // The cross section between rings a and b at t (0..1): its corners on the band between them, moved by `shift`.
  Ring between(int stem, const Ring& a, const Ring& b, double t, const Vec3& shift = Vec3(0.0)) {
    Ring r;
    r.center = glm::mix(a.center, b.center, t) + shift;
    r.radius = a.radius + (b.radius - a.radius) * t;
    r.tex = a.tex + (b.tex - a.tex) * t;
    r.frame = transportFrame(a.frame, directionOr(b.center - a.center, a.frame.T));
    const int level = sk_.stems[static_cast<std::size_t>(stem)].level;
    for (std::size_t k = 0; k < 4; ++k) {
      r.v[k] = addVertex(glm::mix(position(a.v[k]), position(b.v[k]), t) + shift, r.radius, level, r.frame.T);
      addUvw(r.v[k], static_cast<int>(k), r.tex);
    }
    beforePush(out_.rings);
    out_.rings.push_back(MeshRing{stem, r.v, r.center, r.tex, r.radius, -1.0, false, true});
    return r;
  }

  // Children attached along the neck leave through slabs cut out of its first band (from a to b), each where its
  // attachment lies along that band, bowed as the skeleton bows: no child is moved along its parent.
  void neckPorts(const NeckChildren& neck, const Ring& a, const Ring& b) {
    const Vec3 axis = b.center - a.center;
    const double len = std::max(glm::length(axis), 1e-12 * sk_.treeScale);
    struct Group {
      double first = 0, last = 0, h = 0, lo = 0, hi = 0;  // along the band from a, in metres
      int node = -1;
      std::vector<int> children;
    };
    std::vector<std::pair<double, int>> along;
    for (int node : neck.nodes) {
      const Vec3 p = sk_.nodes[static_cast<std::size_t>(node)].world.position;
      along.emplace_back(glm::dot(p - a.center, axis) / len, node);
    }
    std::stable_sort(along.begin(), along.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Group> groups;
    for (const auto& [x, node] : along) {
      const auto& children = stemsAt_[static_cast<std::size_t>(node)];
      const double ra = std::max(sk_.nodes[static_cast<std::size_t>(node)].radius, 0.1 * resolution_);
      // A slab's half height, but at most a fifth of the band; centred at least 1.5 of it in.
      const double h = std::min(slabHalfHeight(widestStart(children), ra), 0.2 * len);
      const double at = std::clamp(x, 1.5 * h, len - 1.5 * h);
      // Attachments whose slabs would overlap share one (through sub-boxes where they want the same side).
      if (!groups.empty() && at - groups.back().first < std::max(0.3 * ra, groups.back().h + h)) {
        Group& g = groups.back();
        g.children.insert(g.children.end(), children.begin(), children.end());
        g.last = std::max(g.last, at);
        g.h = std::max(g.h, h);
        continue;
      }
      groups.push_back(Group{at, at, h, 0, 0, node, children});
    }
    for (Group& g : groups) {
      g.lo = std::max(g.first - g.h, 0.1 * g.h);
      g.hi = std::min(g.last + g.h, len - 0.1 * g.h);
    }
    // Neighbours that overlap shrink to meet halfway with a thin band between them; too close for that, they merge.
    for (std::size_t j = 1; j < groups.size();) {
      Group& p = groups[j - 1];
      Group& q = groups[j];
      const double room = q.first - p.last;
      if (q.lo >= p.hi) {
        ++j;
      } else if (room > 0.2 * (p.h + q.h)) {
        const double mid = 0.5 * (p.last + q.first);
        p.hi = mid - 0.1 * room;
        q.lo = mid + 0.1 * room;
        ++j;
      } else {
        p.children.insert(p.children.end(), q.children.begin(), q.children.end());
        p.last = std::max(p.last, q.last);
        p.hi = std::max(p.hi, q.hi);
        p.h = std::max(p.h, q.h);
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(j));
      }
    }
    // The neck bows as its skeleton does between the two ends (a straight neck over a long, curved skeleton ran
    // several radii off it, across its neighbours).
    const StemPolyline poly(sk_, neck.stem);
    const double sa = poly.nearestArc(a.center), sb = poly.nearestArc(b.center);
    auto bow = [&](double t) {
      Vec3 shift = poly.position(sa + (sb - sa) * t) - glm::mix(poly.position(sa), poly.position(sb), t);
      if (currentStart_) {
        // Never towards the parent's axis (bowed inwards, the ABOP plants' necks met their parents' other children).
        const Vec3 c = glm::mix(a.center, b.center, t) - currentStart_->branchPoint;
        const Vec3 away = directionOr(c - currentStart_->parentAxis * glm::dot(c, currentStart_->parentAxis), Vec3(0.0));
        const double in = glm::dot(shift, away);
        if (in < 0.0) shift -= away * in;
      }
      return shift;
    };
    Ring prev = a;
    for (const Group& g : groups) {
      const double mid = 0.5 * (g.lo + g.hi) / len;
      const std::vector<int> joined = joinedHere(a.center + axis * mid + bow(mid), a.radius + (b.radius - a.radius) * mid, g.children);
      if (joined.empty()) continue;  // the band from prev runs on over the group's place
      const Ring lo = between(neck.stem, a, b, g.lo / len, bow(g.lo / len));
      const Ring hi = between(neck.stem, a, b, g.hi / len, bow(g.hi / len));
      band(prev, lo);
      connectingMoved_ = currentStart_ && !currentStart_->top;
      neckSlab_ = true;
      connect(neck.stem, g.node, lo, hi, joined, nullptr, false);
      connectingMoved_ = neckSlab_ = false;
      prev = hi;
    }
    band(prev, b);
  }

  // How far along `axis` from `from` a stem's skeleton ends; never where clones or children run on from its tip.
  double endAlong(int stem, const Vec3& from, const Vec3& axis) const {
    if (stem < 0) return 1e300;  // the root hub
    const SkeletonStem& st = sk_.stems[static_cast<std::size_t>(stem)];
    const auto lastNode = static_cast<std::size_t>(st.firstNode + st.nodeCount - 1);
    if (!stemsAt_[lastNode].empty()) return 1e300;
    return glm::dot(sk_.nodes[lastNode].world.position - from, axis);
  }

  // A moved child's skeleton starts where its parent is still beside the grandparent: it must clear that too.
  PortStart withGrandparent(PortStart p) const {
    if (!connectingMoved_) return p;
    p.clearGrandparent = true;
    p.grandPoint = currentStart_->branchPoint;
    p.grandAxis = currentStart_->parentAxis;
    p.grandReach = currentStart_->parentReach;
    return p;
  }

  // An equal split (Nystad app. D): the clones leave through the top and the sides of a last slab;
  // with two clones the slab is shaped as a roof so that both leave at similar angles.
  // dir: the slab's axis (the stem's last edge, or a collar's own direction).
  void connectSplit(int stem, const Ring& lo, const Slab& slab, const Vec3& dir) {
    const Vec3 p = lo.center + dir * (slab.hi - slab.lo);
    const RingFrame frame = transportFrame(lo.frame, dir);
    const Ring hi = emitRing(stem, p, frame, lo.radius, lo.tex + barkTextureAdvance(slab.hi - slab.lo, lo.radius));
    connect(stem, slab.node, lo, hi, slab.children, &hi, slab.children.size() == 2);
  }

  // Moves the top corners so the side in use tilts up and the top tilts away from it.
  void raiseRoof(const Ring& lo, const Ring& hi, int used) {
    const double height = glm::distance(lo.center, hi.center);
    const Vec3 axis = glm::normalize(hi.center - lo.center);
    const Vec3 n = glm::normalize(faceCenter(side(lo, hi, used)) - 0.5 * (lo.center + hi.center));
    for (int k = 0; k < 4; ++k) {
      glm::vec3& p = out_.mesh.positions[hi.v[static_cast<std::size_t>(k)]];
      Vec3 q(p);
      const bool near = k == used || k == (used + 1) % 4;
      if (near) {
        q -= n * (0.8 * glm::dot(q - hi.center, n));
        q += axis * (0.3 * height);
      } else {
        q -= axis * (0.5 * height);
      }
      p = glm::vec3(q);
    }
  }

  // Several children want one side: that side grows a small box of its own whose top and sides they share.
  void subBox(int parentStem, int node, const std::array<std::uint32_t, 4>& q, const std::vector<int>& children) {
    const Vec3 center = faceCenter(q);
    const Vec3 n = faceNormal(q);
    const double rho = meanCornerDistance(q, center);
    Ring port = portRing(q);
    port.tex = portTex(q);
    const RingFrame frame = transportFrame(port.frame, n);
    const double r = 0.8 * rho / opt_.limitCompensation;
    const Ring a = emitRing(parentStem, center + n * (0.5 * rho), frame, r, port.tex + barkTextureAdvance(0.5 * rho, r));
    band(port, a);
    const Ring b = emitRing(parentStem, center + n * (1.5 * rho), frame, r, a.tex + barkTextureAdvance(rho, r));
    connect(parentStem, node, a, b, children, &b, false);
  }

  // Several trunks meet in a root node: a capped hub whose top and sides they leave from. More than the box's
  // top and four sides hold get a wide hub with a port for each (buildGridHub) where their axes allow one, and
  // more than kBoxHubMost always do: the box hub's sub-boxes, four trunks a level, shrank to nothing under 1,000.
  void buildRoot(const std::vector<int>& trunks) {
    if (trunks.empty()) return;
    if (trunks.size() > 5 && buildGridHub(trunks, trunks.size() > kBoxHubMost)) return;
    const double rho = widestStart(trunks);
    const Vec3 origin = sk_.nodes[0].world.position;
    const RingFrame frame = frameFromHint(kUp, Vec3(1, 0, 0));
    const Ring base = emitRing(trunks[0], origin, frame, 1.5 * rho, 0.0);
    if (opt_.openBase) out_.mesh.openBoundary.assign(base.v.begin(), base.v.end());
    else addQuad(base.v[3], base.v[2], base.v[1], base.v[0]);
    const Ring top = emitRing(trunks[0], origin + kUp * (3.0 * rho), frame, 1.5 * rho, barkTextureAdvance(3.0 * rho, rho));
    std::vector<std::pair<int, PortStart>> children;
    deferred_ = &children;
    connect(-1, 0, base, top, trunks, &top, false);
    buildChildren(children, 0);
    deferred_ = nullptr;
  }

  // ---- the wide hub of many trunks ----

  // Arc length at which a stem's skeleton first stands `level` above `origin` along `up` (-1: never).
  static double arcAtLevel(const StemPolyline& poly, const Vec3& origin, const Vec3& up, double level) {
    double before = glm::dot(poly.position(0.0) - origin, up);
    if (before >= level) return 0.0;
    for (int i = 1; i < poly.pointCount(); ++i) {
      const double s0 = poly.arcLength(i - 1), s1 = poly.arcLength(i);
      const double after = glm::dot(poly.position(s1) - origin, up);
      if (after >= level) return s0 + (s1 - s0) * (level - before) / (after - before);
      before = after;
    }
    return -1.0;
  }

  // Texture at a hub vertex (x, y) across its frame: u and the flip coordinate as around a cross section's corners.
  void addHubUvw(std::uint32_t v, double x, double y, double tex) {
    const double phi = std::atan2(y, x);  // 0 at corner 0 (+N), pi/2 at corner 1 (+B)
    const double flip = std::copysign(1.0 - std::abs(std::abs(phi) - 0.5 * std::numbers::pi) / (0.5 * std::numbers::pi), phi);
    uvwSum_[v] += Vec3(std::abs(phi) / std::numbers::pi, tex, flip);
    ++uvwCount_[v];
  }

  // Many trunks from one root (a grass's tuft): a flat hub whose top is a grid of cells, each trunk leaving its
  // own port cell, laid out as its axis lies where the necks meet the skeletons, its neck curving from there to
  // its skeleton (leaveHub). False where a trunk's skeleton never rises that far (the box hub is built instead),
  // unless `always`: then such a trunk's neck meets it half-way along.
  bool buildGridHub(const std::vector<int>& trunks, bool always) {
    const double rho = widestStart(trunks);
    if (!(rho > 0.0)) return false;  // no width to lay cells out by
    const double cell = std::sqrt(2.0) * rho * opt_.limitCompensation;  // a port's corners where a trunk's ring's are
    const int slots = hubSlots(trunks.size());
    const int cells = 2 * slots + 1;
    const double half = 0.5 * cells * cell, height = 2.0 * cell;
    const Vec3 origin = sk_.nodes[0].world.position;
    const RingFrame frame = frameFromHint(kUp, Vec3(1, 0, 0));
    std::vector<StemPolyline> polys;
    double shortest = 1e300;
    for (int t : trunks) {
      polys.emplace_back(sk_, t);
      shortest = std::min(shortest, polys.back().length());
    }
    // The necks meet their skeletons at one level, where nine in ten axes lie within twice the ports' span (the
    // necks fan out a little, as the stems do; wheat, barley and rush at seeds 1-3, mesh-made pairs 3,573 with the
    // box hub, 1,127 within the span, 526 within twice, 548 within 2.5 times). Found by scaling, as the axes
    // spread about in proportion to the level; never past a quarter of the shortest trunk.
    const double span = 2.0 * (slots - 1) * cell;
    std::vector<std::array<double, 2>> wanted(trunks.size());
    std::vector<double> arcs(trunks.size());
    auto spreadAt = [&](double level) {
      for (std::size_t i = 0; i < polys.size(); ++i) {
        arcs[i] = arcAtLevel(polys[i], origin, kUp, level);
        if (arcs[i] < 0.0 || arcs[i] > 0.5 * polys[i].length()) {
          if (!always) return -1.0;
          arcs[i] = 0.5 * polys[i].length();  // its neck meets it half-way, wherever that lies
        }
        const Vec3 d = polys[i].position(arcs[i]) - origin;
        wanted[i] = {glm::dot(d, frame.N), glm::dot(d, frame.B)};
      }
      return hubSpread(wanted);
    };
    const double lowest = height + 4.0 * rho, highest = std::max(lowest, 0.25 * shortest);
    double level = std::clamp(height + span, lowest, highest);
    for (int k = 0; k < 4; ++k) {
      const double r = spreadAt(level);
      if (r < 0.0) return false;
      level = std::clamp(level * span / std::max(r, 1e-9), lowest, highest);
    }
    if (spreadAt(level) < 0.0) return false;
    HubLayout layout = layOutHub(wanted);
    // A cell's port centre, where a neck from it starts.
    auto portCenter = [&](const std::array<int, 2>& c) {
      return origin + frame.N * (-half + (c[0] + 0.5) * cell) + frame.B * (-half + (c[1] + 0.5) * cell) + kUp * height;
    };
    // Where each neck meets its skeleton (and how it arrives), read once: the search weighs thousands of necks.
    struct NeckEnd {
      Vec3 at{0.0}, direction{0.0};
      double radius = 0;
    };
    std::vector<NeckEnd> ends(trunks.size());
    std::vector<double> reach(trunks.size());
    std::vector<std::vector<Vec3>> tube(trunks.size());
    for (std::size_t t = 0; t < trunks.size(); ++t) {
      ends[t] = {polys[t].position(arcs[t]), polys[t].direction(arcs[t]), std::max(rho, polys[t].radius(arcs[t]))};
      reach[t] = opt_.limitCompensation * ends[t].radius;
      for (int k = 0; k <= 4; ++k) tube[t].push_back(polys[t].position(std::min(polys[t].length(), arcs[t] + 8.0 * k * reach[t])));
    }
    untangleHub(
        layout,
        [&](std::size_t t, const std::array<int, 2>& c) { return hubNeck(portCenter(c), kUp, ends[t].at, ends[t].direction, ends[t].radius); },
        reach, tube);

    // The top grid, the base (its rim only where the base is left open) and the sides between them.
    const double texTop = barkTextureAdvance(height, rho);
    auto grid = [&](double z, double tex, bool rimOnly) {
      std::vector<std::uint32_t> v(static_cast<std::size_t>((cells + 1) * (cells + 1)), kUnmade);
      for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
          if (rimOnly && i > 0 && i < cells && j > 0 && j < cells) continue;
          const double x = -half + i * cell, y = -half + j * cell;
          const auto at = static_cast<std::size_t>(j * (cells + 1) + i);
          v[at] = addVertex(origin + frame.N * x + frame.B * y + kUp * z, 1.5 * rho, 0, kUp);
          // v runs outwards from the centre, as bark spreads over a root flare (constant, it streaked the pad).
          addHubUvw(v[at], x, y, tex + barkTextureAdvance(std::hypot(x, y), rho));
        }
      }
      return v;
    };
    const auto top = grid(height, texTop, false);
    const auto base = grid(0.0, 0.0, opt_.openBase);
    auto at = [&](const std::vector<std::uint32_t>& g, int i, int j) { return g[static_cast<std::size_t>(j * (cells + 1) + i)]; };
    std::vector<std::array<int, 2>> rim;  // counter-clockwise about the hub's axis
    for (int i = 0; i < cells; ++i) rim.push_back({i, 0});
    for (int j = 0; j < cells; ++j) rim.push_back({cells, j});
    for (int i = cells; i > 0; --i) rim.push_back({i, cells});
    for (int j = cells; j > 0; --j) rim.push_back({0, j});
    if (opt_.openBase) {
      out_.mesh.openBoundary.clear();
      for (const auto& p : rim) out_.mesh.openBoundary.push_back(at(base, p[0], p[1]));
    }
    for (std::size_t k = 0; k < rim.size(); ++k) {
      const auto& a = rim[k];
      const auto& b = rim[(k + 1) % rim.size()];
      addQuad(at(base, a[0], a[1]), at(base, b[0], b[1]), at(top, b[0], b[1]), at(top, a[0], a[1]));
    }
    std::vector<bool> isPort(static_cast<std::size_t>(cells * cells), false);
    for (const auto& c : layout.cell) isPort[static_cast<std::size_t>(c[1] * cells + c[0])] = true;
    for (int j = 0; j < cells; ++j) {
      for (int i = 0; i < cells; ++i) {
        if (!opt_.openBase) addQuad(at(base, i, j), at(base, i, j + 1), at(base, i + 1, j + 1), at(base, i + 1, j));
        if (!isPort[static_cast<std::size_t>(j * cells + i)]) addQuad(at(top, i, j), at(top, i + 1, j), at(top, i + 1, j + 1), at(top, i, j + 1));
      }
    }

    MeshJoint joint;
    joint.node = 0;
    joint.childStems = trunks;
    joint.center = origin;
    joint.radius = rho;
    out_.joints.push_back(std::move(joint));
    std::vector<std::pair<int, PortStart>> children;
    for (std::size_t t = 0; t < trunks.size(); ++t) {
      const auto [i, j] = layout.cell[t];
      PortStart p{{at(top, i, j), at(top, i + 1, j), at(top, i + 1, j + 1), at(top, i, j + 1)}, origin, true, kUp, 0.0};
      p.slabReach = half;
      p.tex = portTex(p.port);
      p.tubeAt = arcs[t];
      children.emplace_back(trunks[t], p);
    }
    deferred_ = &children;
    buildChildren(children, 0);
    deferred_ = nullptr;
    return true;
  }

  // A trunk's neck from its port on the wide hub to its skeleton at start.tubeAt: a cubic leaving along the port's
  // normal and arriving along the skeleton (no kink where the tube begins), with cross sections about sixteen radii
  // apart, as a stem's own are far apart between its nodes (the grasses' mesh-made pairs at seeds 1-3: 526 with
  // four radii, 452 with sixteen; wheat's quads +21 % over the box hub with four, +10 % with sixteen).
  Ring leaveHub(int stem, const StemPolyline& poly, const PortStart& start) {
    inset_.reset();
    Ring last = portRing(start.port);
    last.tex = start.tex;
    const double portRadius = meanCornerDistance(start.port, last.center) / opt_.limitCompensation;
    addPortUvw(start.port, last.tex);
    const double s = start.tubeAt;
    const double rc = poly.radius(s);
    const HubNeck neck = hubNeck(last.center, last.frame.T, poly.position(s), poly.direction(s), std::max(rc, portRadius));
    RingFrame frame = last.frame;
    for (int k = 1; k <= neck.steps; ++k) {
      const double f = static_cast<double>(k) / neck.steps;
      const Vec3 c = neck.at(f);
      const double r = portRadius + (rc - portRadius) * f;
      frame = transportFrame(frame, k < neck.steps ? directionOr(neck.tangent(f), last.frame.T) : poly.direction(s));
      const double tex = last.tex + barkTextureAdvance(glm::distance(c, last.center), r);
      const Ring next = emitRing(stem, c, frame, r, tex, k < neck.steps ? -1.0 : s);
      band(last, next);
      last = next;
    }
    return last;
  }

  void finish() {
    QuadMesh& m = out_.mesh;
    m.uvw.resize(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      m.uvw[i] = glm::vec3(uvwSum_[i] / static_cast<double>(std::max(1, uvwCount_[i])));
    }
  }
};

// `search`: the crossing-twig search, begun beside the mesher.
TreeMesh buildOnce(const Skeleton& skeleton, const MeshOptions& options, const std::vector<int>& fake, const CollarHints& collars,
                   std::vector<int>* farTwigs, PairsToMendSearch* search) {
  TreeMesh out;
  // About five quads (and as many vertices) per skeleton node; growing these vectors would cost page faults.
  const std::size_t vertices = std::min(skeleton.nodes.size() * 6, options.maxQuads + 8);
  out.mesh.positions.reserve(vertices);
  out.mesh.tangents.reserve(vertices);
  out.mesh.radius.reserve(vertices);
  out.mesh.level.reserve(vertices);
  out.mesh.quads.reserve(vertices);
  out.quadStem.reserve(vertices);
  out.rings.reserve(vertices / 4);
  Builder builder(skeleton, options, out, fake, collars);
  std::optional<SearchBesideBuilder> beside;
  if (search) {
    beside.emplace(out, skeleton, *search);
    builder.searchBeside(&*beside);
  }
  builder.run();
  if (beside) beside->stop();
  if (farTwigs) *farTwigs = builder.farTwigs();
  // Degenerate geometry must never leave here as NaN vertices (exports and the GPU would take them silently).
  for (const glm::vec3& p : out.mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw std::logic_error("mesh: a vertex is not finite (a degenerate joint); please report the species file and seed");
    }
  }
  return out;
}

// The mesh with the collars `collars` names nearer their ports (or leaning); `left` receives the crossings the
// crossing-twig pass could not take out. A twig the first pass left past the joint floor is a fake branch, and the tree meshed again without
// it: its neighbours' connections change, so the second pass may leave a few more (at most 1 to 3 twigs a tree,
// measured). Those are taken out of that mesh rather than meshing it all again, their neighbours keeping their
// places (a 100,000-internode graph was meshed four times); a further pass only where one cannot be.
TreeMesh buildWithTwigsFaked(const Skeleton& skeleton, const MeshOptions& options, const CollarHints& collars, CrossingsLeft* left) {
  std::vector<int> fake, far;
  for (int pass = 0;; ++pass) {
    // Searching every stem (as when what is left is asked for), the crossing-twig search begins beside the mesher.
    const bool crossing = options.fakeDisplaced && options.fakeCrossingTwigs;
    PairsToMendSearch search;
    const bool beside = crossing && left && options.searchBesideMesher;
    TreeMesh out = buildOnce(skeleton, options, fake, collars, pass < kFarTwigPasses ? &far : nullptr, beside ? &search : nullptr);
    bool changed = false;  // since the search beside began
    if (pass >= 1 && !far.empty() && takeOutTwigs(out, skeleton, far)) {
      far.clear();
      changed = true;
    }
    if (pass == kFarTwigPasses || far.empty()) {
      // Last, the twigs whose quads still cross another stem's where the skeletons do not meet.
      if (crossing) fakeCrossingTwigs(out, skeleton, left, beside && !changed ? &search : nullptr);
      // Once, on the mesh as it leaves, after every twig taken out (neither take-out computes them here).
      if (out.mesh.normals.size() != out.mesh.positions.size()) computeNormals(out.mesh);
      return out;
    }
    std::vector<int> more;
    std::set_union(fake.begin(), fake.end(), far.begin(), far.end(), std::back_inserter(more));
    fake = std::move(more);
  }
}

}  // namespace

TreeMesh buildTreeMesh(const Skeleton& skeleton, const MeshOptions& options) {
  CrossingsLeft left;
  TreeMesh out = buildWithTwigsFaked(skeleton, options, {}, &left);
  if (left.necks.empty()) return out;
  // Necks crossing other stems that no take-out could mend: once more with those collars nearer their ports, kept
  // only where that leaves fewer such crossings.
  CrossingsLeft nearer;
  const CollarHints near{left.necks, {}};
  TreeMesh again = buildWithTwigsFaked(skeleton, options, near, &nearer);
  std::size_t fewest = left.pairs;  // mesh-made pairs left in `out`
  if (nearer.pairs < fewest) {
    out = std::move(again);
    fewest = nearer.pairs;
  }
  if (nearer.necks.empty() || out.mesh.quads.size() > kLeaningPassQuadsMost) return out;
  // Those still crossing from there: once more leaning along their stems too, kept on the same terms.
  CollarHints leaning{{}, nearer.necks};
  std::set_union(left.necks.begin(), left.necks.end(), nearer.necks.begin(), nearer.necks.end(), std::back_inserter(leaning.nearer));
  CrossingsLeft leaned;
  TreeMesh third = buildWithTwigsFaked(skeleton, options, leaning, &leaned);
  return leaned.pairs < fewest ? third : out;
}

}  // namespace arbor
