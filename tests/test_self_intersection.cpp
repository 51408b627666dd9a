// The self-intersection check: crossing quads found, neighbours that only touch not, folds and necks seen
// although they share corners, skeleton crossings told from the mesher's, the BVH equal to brute force.
#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <optional>
#include <random>
#include <set>

#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/crossing_twigs.hpp"
#include "mesh/edge_plane.hpp"
#include "mesh/quad_contact.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/stem_capsules.hpp"
#include "manifold_checks.hpp"
#include "mesh_diff.hpp"
#include "mesh_support.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "test_support.hpp"
#include "tree/tree_source.hpp"

using namespace arbor;

namespace {

// A mesh of loose quads: each given by its four corners, each corner its own vertex unless `shared` says.
struct QuadSoup {
  QuadMesh mesh;
  std::uint32_t add(const Vec3& p) {
    mesh.positions.emplace_back(p);
    return static_cast<std::uint32_t>(mesh.positions.size() - 1);
  }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) { mesh.quads.push_back({a, b, c, d}); }
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { quad(add(a), add(b), add(c), add(d)); }
};

std::size_t pairs(const QuadMesh& mesh) { return findIntersectingQuads(mesh).size(); }

// A unit cube, closed and outward: six quads on eight shared corners.
QuadMesh cube() {
  QuadSoup s;
  for (int i = 0; i < 8; ++i) s.add(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  s.quad(0, 2, 3, 1);
  s.quad(4, 5, 7, 6);
  s.quad(0, 1, 5, 4);
  s.quad(2, 6, 7, 3);
  s.quad(0, 4, 6, 2);
  s.quad(1, 3, 7, 5);
  return s.mesh;
}

// Two trunks, each one straight skeleton edge of radius r, crossing at the origin (along x and along y).
Skeleton crossingSkeleton(double r) {
  Skeleton s;
  for (int stem = 0; stem < 2; ++stem) {
    const Vec3 dir = stem == 0 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    SkeletonNode base, tip;
    base.stem = tip.stem = stem;
    base.kind = NodeKind::Base;
    tip.kind = NodeKind::Tip;
    base.world.position = -dir;
    tip.world.position = dir;
    base.radius = tip.radius = tip.startRadius = r;
    base.parent = -1;
    tip.parent = static_cast<int>(s.nodes.size());
    SkeletonStem st;
    st.firstNode = static_cast<int>(s.nodes.size());
    st.nodeCount = 2;
    s.nodes.push_back(base);
    s.nodes.push_back(tip);
    s.stems.push_back(st);
  }
  return s;
}

// Stem 2, a twig of radius 0.01 on stem 0 rising at x = 0.15 (its wood starting at its own base, not back at stem
// 0's node), added to a crossing skeleton of radius r.
void addTwigOnStem0(Skeleton& skeleton, double r, std::int16_t level) {
  SkeletonNode base, tip;
  base.stem = tip.stem = 2;
  base.kind = NodeKind::Base;
  tip.kind = NodeKind::Tip;
  base.world.position = Vec3(0.15, 0, r);
  tip.world.position = Vec3(0.15, 0, 1);
  base.radius = tip.radius = tip.startRadius = 0.01;
  base.parent = -1;
  tip.parent = 4;
  SkeletonStem twig;
  twig.firstNode = 4;
  twig.nodeCount = 2;
  twig.level = level;
  twig.parentStem = 0;
  twig.attachNode = 0;
  skeleton.nodes.push_back(base);
  skeleton.nodes.push_back(tip);
  skeleton.stems.push_back(twig);
}

// A flat quad of `flatStem` on stem 0's upper surface (x within +-halfLength), and an upright face of stem 1
// standing across it at x = 0, through stem 0's axis.
TreeMesh flatAcrossStem1(double r, double halfLength, int flatStem) {
  TreeMesh tree;
  QuadSoup s;
  s.quad(Vec3(-halfLength, -r, r), Vec3(halfLength, -r, r), Vec3(halfLength, r, r), Vec3(-halfLength, r, r));
  s.quad(Vec3(0, -0.5, -r), Vec3(0, 0.5, -r), Vec3(0, 0.5, 2 * r), Vec3(0, -0.5, 2 * r));
  tree.mesh = s.mesh;
  tree.quadStem = {flatStem, 1};
  return tree;
}

}  // namespace

TEST_CASE("two quads crossing each other are one pair, two apart are none", "[mesh][self-intersection]") {
  QuadSoup s;
  s.quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0));
  s.quad(Vec3(0, -0.5, -1), Vec3(0, 0.5, -1), Vec3(0, 0.5, 1), Vec3(0, -0.5, 1));
  const auto hits = findIntersectingQuads(s.mesh);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].a == 0);
  CHECK(hits[0].b == 1);
  CHECK(hits[0].contact == QuadContact::Apart);
  CHECK(std::abs(hits[0].point.x) < 1e-9);
  CHECK(std::abs(hits[0].point.z) < 1e-9);

  QuadSoup apart;
  apart.quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0));
  apart.quad(Vec3(-1, -1, 0.01), Vec3(1, -1, 0.01), Vec3(1, 1, 0.01), Vec3(-1, 1, 0.01));  // parallel, above
  apart.quad(Vec3(3, -0.5, -1), Vec3(3, 0.5, -1), Vec3(3, 0.5, 1), Vec3(3, -0.5, 1));      // beside, upright
  CHECK(pairs(apart.mesh) == 0);
}

TEST_CASE("a quad folded back over its neighbour across their shared edge is a fold, one bent is not", "[mesh][self-intersection]") {
  for (double angle : {180.0, 90.0, 20.0, 5.0, 0.0}) {
    INFO("dihedral angle " << angle << " degrees");
    QuadSoup s;
    const std::uint32_t e0 = s.add(Vec3(0, 0, 0)), e1 = s.add(Vec3(0, 1, 0));
    // The first quad lies on +x; the second turns about the shared edge (the y axis) by `angle`.
    const std::uint32_t a2 = s.add(Vec3(1, 1, 0)), a3 = s.add(Vec3(1, 0, 0));
    const double t = radians(angle);
    const Vec3 out(std::cos(t), 0, std::sin(t));
    const std::uint32_t b2 = s.add(out * 0.8 + Vec3(0, 1, 0)), b3 = s.add(out * 0.8);
    s.quad(e0, e1, a2, a3);
    s.quad(e1, e0, b3, b2);
    const auto hits = findIntersectingQuads(s.mesh);
    CHECK(hits.size() == (angle == 0.0 ? 1u : 0u));
    if (!hits.empty()) CHECK(hits[0].contact == QuadContact::Edge);
  }
  // A folded neighbour that is not flat on the first: its far edge dips through the first quad.
  QuadSoup s;
  const std::uint32_t e0 = s.add(Vec3(0, 0, 0)), e1 = s.add(Vec3(0, 1, 0));
  s.quad(e0, e1, s.add(Vec3(1, 1, 0)), s.add(Vec3(1, 0, 0)));
  s.quad(e1, e0, s.add(Vec3(0.8, -0.1, 0.3)), s.add(Vec3(0.8, 1.1, -0.3)));
  const auto hits = findIntersectingQuads(s.mesh);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].contact == QuadContact::Edge);
}

TEST_CASE("quads on one corner intersect only when they cross beyond it", "[mesh][self-intersection]") {
  // A square on the xy plane, and a second square sharing its corner at the origin.
  auto pairOn = [](const Vec3& b1, const Vec3& b2, const Vec3& b3) {
    QuadSoup s;
    const std::uint32_t v = s.add(Vec3(0, 0, 0));
    s.quad(v, s.add(Vec3(1, 0, 0)), s.add(Vec3(1, 1, 0)), s.add(Vec3(0, 1, 0)));
    s.quad(v, s.add(b1), s.add(b2), s.add(b3));
    return findIntersectingQuads(s.mesh);
  };
  // Touching at the corner only: standing on it, hanging below it, lying beside it in the plane.
  CHECK(pairOn(Vec3(-1, 0, 1), Vec3(-1, -1, 1), Vec3(0, -1, 1)).empty());
  CHECK(pairOn(Vec3(0, 0, -1), Vec3(1, 1, -1), Vec3(0.5, 0.5, -1.5)).empty());
  CHECK(pairOn(Vec3(0, -1, 0), Vec3(-1, -1, 0), Vec3(-1, 0, 0)).empty());
  // Through the first square beyond the corner: its far corners above and below the plane, inside it.
  const auto through = pairOn(Vec3(0.6, 0.2, 0.5), Vec3(0.8, 0.8, 0.2), Vec3(0.2, 0.6, -0.5));
  REQUIRE(through.size() == 1);
  CHECK(through[0].contact == QuadContact::Vertex);
  // Lying on the first square in its plane, overlapping it (a fold to zero about a corner).
  CHECK(pairOn(Vec3(0.5, 0.1, 0), Vec3(0.6, 0.6, 0), Vec3(0.1, 0.5, 0)).size() == 1);
}

TEST_CASE("an edge plane: none where no tilt separates, and a quad behind it never meets one in front", "[mesh][self-intersection]") {
  const Vec3 p0(0.0), p1(1.0, 0.0, 0.0), up(0.0, 0.0, 1.0), inward(0.0, 1.0, 0.0);
  const std::array<std::uint32_t, 2> edge{0, 1};
  // In front: up and inwards; behind: beyond the edge and low. A point on the edge's line, or a front point
  // beyond the edge lower than a back point beyond it, leaves no plane.
  using Points = std::vector<Vec3>;
  const auto plane = edgePlane(p0, p1, edge, up, inward, Points{{0.5, 1.0, 0.0}, {0.5, -0.5, 1.0}}, Points{{0.5, -1.0, 0.2}}, 1e-6);
  REQUIRE(plane);
  CHECK(plane->height({0.5, 1.0, 0.0}) > 0.0);
  CHECK(plane->height({0.5, -1.0, 0.2}) < 0.0);
  CHECK_FALSE(edgePlane(p0, p1, edge, up, inward, Points{{2.0, 0.0, 0.0}}, {}, 1e-6));
  CHECK_FALSE(edgePlane(p0, p1, edge, up, inward, Points{{0.5, -1.0, 0.5}}, Points{{0.5, -2.0, 2.0}}, 1e-6));
  // Random quads on the edge (and some off it): whenever the plane puts one behind, quadsMeet finds no crossing,
  // also for near-folds (the second quad turned back within a few fold angles of the first).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int separated = 0, met = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3 a2(0.5 + unit(random), 0.3 + unit(random), 0.3 + unit(random)), a3(0.5 + unit(random), 0.3 + unit(random), 0.3 + unit(random));
    std::array<Vec3, 4> b{p0, p1, Vec3(0.5 + unit(random), unit(random), unit(random)), Vec3(0.5 + unit(random), unit(random), unit(random))};
    if (trial % 4 == 0) {
      // A near-fold: a flat front quad, and behind it the same quad turned about the edge by 1e-4 to 1e-2 radians.
      const double at = 1.5 * unit(random);
      const double r2 = 1.2 + unit(random), r3 = 1.2 + unit(random);
      a2 = Vec3(0.2 + 0.3 * unit(random), r2 * std::cos(at), r2 * std::sin(at));
      a3 = Vec3(0.8 + 0.3 * unit(random), r3 * std::cos(at), r3 * std::sin(at));
      const double angle = -std::pow(10.0, -4.0 + 2.0 * (0.5 + 0.5 * unit(random)));  // towards behind
      auto turn = [&](const Vec3& x) { return Vec3(x.x, x.y * std::cos(angle) - x.z * std::sin(angle), x.y * std::sin(angle) + x.z * std::cos(angle)); };
      b[2] = turn(a2);
      b[3] = turn(a3);
    }
    const bool shareEdge = trial % 3 != 0;
    const std::array<std::uint32_t, 4> frontIds{0, 1, 2, 3}, backIds = shareEdge ? std::array<std::uint32_t, 4>{0, 1, 4, 5}
                                                                             : std::array<std::uint32_t, 4>{6, 7, 4, 5};
    if (!shareEdge) {
      b[0] += Vec3(0.0, unit(random), unit(random));
      b[1] += Vec3(0.0, unit(random), unit(random));
    }
    const QuadCorners front{{p0, p1, a2, a3}, frontIds}, back{b, backIds};
    const double margin = 2e-3 * 3.0;
    // On a shared edge the quad behind is given (as a band against an inset's quad), else only the front (as the
    // parent's faces against an inset).
    const auto found = edgePlane(p0, p1, edge, up, inward, Points{a2, a3}, shareEdge ? Points{b[2], b[3]} : Points{}, margin);
    const bool meets = quadsMeet(front, back).has_value();
    met += meets ? 1 : 0;
    if (found && found->behind(b, backIds)) {
      ++separated;
      if (meets) FAIL("trial " << trial << ": a quad behind the plane meets the quad in front");
    }
  }
  // Both outcomes occur often enough for the property to mean something.
  CHECK(separated > 2000);
  CHECK(met > 2000);
}

TEST_CASE("a closed cube has no intersecting quads", "[mesh][self-intersection]") {
  const SelfIntersectionReport r = checkSelfIntersections(cube());
  CHECK(r.quads == 6);
  CHECK(r.pairs == 0);
  CHECK_FALSE(r.classified);
}

TEST_CASE("two stems whose skeleton capsules cross make a skeleton-made pair, a fold stays mesh-made", "[mesh][self-intersection]") {
  const double r = 0.05;
  const Skeleton skeleton = crossingSkeleton(r);
  // Stem 0 along x, a flat quad at its top surface; stem 1 along y, an upright quad through its axis.
  TreeMesh tree = flatAcrossStem1(r, 0.5, 0);
  SelfIntersectionReport report = checkSelfIntersections(tree, skeleton);
  REQUIRE(report.pairs == 1);
  CHECK(report.classified);
  CHECK(report.skeletonMade == 1);
  CHECK(report.meshMade == 0);
  CHECK(report.hits[0].relation == StemRelation::Other);

  // The same two quads, but stem 1's skeleton moved far away: the mesh crosses where no wood is.
  Skeleton apart = skeleton;
  for (SkeletonNode& n : apart.nodes)
    if (n.stem == 1) n.world.position += Vec3(0, 0, 10);
  report = checkSelfIntersections(tree, apart);
  REQUIRE(report.pairs == 1);
  CHECK(report.meshMade == 1);

  // Both quads of one stem: mesh-made whatever the skeleton says.
  tree.quadStem = {0, 0};
  report = checkSelfIntersections(tree, skeleton);
  CHECK(report.meshMade == 1);
  CHECK(report.hits[0].relation == StemRelation::Same);
}

TEST_CASE("a stem crossing a branch's wood where the branch's child has its collar is skeleton-made", "[mesh][self-intersection]") {
  const double r = 0.05;
  Skeleton skeleton = crossingSkeleton(r);
  addTwigOnStem0(skeleton, r, 1);  // its collar lies on stem 0's upper surface
  skeleton.nodes[0].world.rotation = glm::angleAxis(radians(90.0), Vec3(0, 1, 0));  // stem 0 leaves along +x
  const TreeMesh tree = flatAcrossStem1(r, 0.1, 2);  // the twig's collar; stem 1 through stem 0 there
  SelfIntersectionReport report = checkSelfIntersections(tree, skeleton);
  REQUIRE(report.pairs == 1);
  CHECK(report.hits[0].reachA > 10.0);  // far from the twig's own axis: its wood does not explain it
  CHECK(report.skeletonMade == 1);      // stem 1 crosses stem 0 there, and the collar stands for stem 0's surface

  // Stem 1 a sibling of the twig (also grown from stem 0) whose skeleton passes through stem 0 far from where it
  // leaves it (its base 1 m away): its wood crosses stem 0's there, as Weber-Penn allows, so the pair is the
  // skeleton's as for any other stem.
  skeleton.stems[1].parentStem = 0;
  skeleton.stems[1].attachNode = 1;
  report = checkSelfIntersections(tree, skeleton);
  REQUIRE(report.pairs == 1);
  CHECK(report.skeletonMade == 1);

  // The sibling leaving stem 0 right there (its base on stem 0's axis under the collar): it crosses stem 0 by
  // construction at its own joint, where its capsules have not begun, so the pair is the mesher's.
  Skeleton atJoint = skeleton;
  for (SkeletonNode& n : atJoint.nodes)
    if (n.stem == 1) n.world.position = n.kind == NodeKind::Base ? Vec3(0.0) : Vec3(0, 1, 0);
  report = checkSelfIntersections(tree, atJoint);
  REQUIRE(report.pairs == 1);
  CHECK(report.meshMade == 1);

  // Stem 1 moved away from stem 0: nothing crosses there in the skeleton.
  skeleton.stems[1].parentStem = -1;
  skeleton.stems[1].attachNode = -1;
  for (SkeletonNode& n : skeleton.nodes)
    if (n.stem == 1) n.world.position += Vec3(0, 0, 10);
  report = checkSelfIntersections(tree, skeleton);
  CHECK(report.meshMade == 1);
}

TEST_CASE("a branch's own parent crossing it where its child has its collar is as the skeleton makes it", "[mesh][self-intersection]") {
  const double r = 0.05;
  Skeleton skeleton = crossingSkeleton(r);
  // Stem 0 (along x) is now a limb of stem 1 (along y), leaving it at its tip (0, 1, 0) for (-1, 0, 0) and turning
  // back through it at the origin, as an L-system limb can; stem 2, a twig on stem 0 at x = 0.15, has its collar on
  // stem 0's upper surface, across stem 1.
  skeleton.stems[0].parentStem = 1;
  skeleton.stems[0].attachNode = 3;
  skeleton.stems[0].level = 1;
  addTwigOnStem0(skeleton, r, 2);
  const TreeMesh tree = flatAcrossStem1(r, 0.1, 2);  // the twig's collar, and stem 1's surface there
  SelfIntersectionReport report = checkSelfIntersections(tree, skeleton);
  REQUIRE(report.pairs == 1);
  CHECK(report.hits[0].reachA > 10.0);  // far from the twig's own axis
  CHECK(report.skeletonMade == 1);      // stem 0's wood, past its neck, crosses its parent there: so does the collar on it

  // Stem 0 leaving stem 1 right there (from stem 1's axis at the origin): the crossing is its own joint, where its
  // capsules against its parent have not begun, so the pair is the mesher's.
  Skeleton atJoint = skeleton;
  atJoint.nodes[2].world.position = Vec3(0, -1, 0);
  atJoint.nodes[3].world.position = Vec3(0, 0, 0);
  atJoint.nodes[0].world.position = Vec3(0, 0, 0);
  report = checkSelfIntersections(tree, atJoint);
  REQUIRE(report.pairs == 1);
  CHECK(report.meshMade == 1);
}

TEST_CASE("against its parent, a child's capsules start where its wood has cleared the parent's", "[mesh][self-intersection]") {
  Skeleton s = crossingSkeleton(0.1);
  // Stem 1 grows from stem 0's base node, at right angles: cut at 1.6 (0.1 + 0.1) = 0.32 along it.
  s.stems[1].parentStem = 0;
  s.stems[1].attachNode = 0;
  s.nodes[0].world.position = Vec3(0, -1, 0);  // stem 0's base sits where stem 1 starts
  s.nodes[0].world.rotation = glm::angleAxis(radians(90.0), Vec3(0, 1, 0));  // stem 0 leaves along +x
  s.nodes[3].parent = 0;
  s.stems[1].nodeCount = 1;
  s.stems[1].firstNode = 3;
  const auto capsules = stemCapsules(s);
  REQUIRE(capsules[1].size() == 1);
  CHECK(capsules[1][0].flatStart);
  CHECK(capsules[1][0].a.y == Approx(-1 + 0.32));
  CHECK(std::isinf(stemReach(capsules[1], Vec3(0, -1, 0))));   // inside the parent: not the child's wood
  CHECK(stemReach(capsules[1], Vec3(0, 0, 0.1)) == Approx(1.0));  // on the child's surface further out
}

namespace {

// Stem 0 along x (radius 0.1) with its middle node at the origin; stem 1 a child of radius 0.02 leaving it there
// 20 degrees up: its axis leaves stem 0's wood at 0.1 / sin 20 = 0.292 along it, its wood clears stem 0's only
// at 1.6 (0.1 + 0.02) / sin 20 = 0.561.
Skeleton shallowChild() {
  Skeleton s;
  const Quat alongX = glm::angleAxis(radians(90.0), Vec3(0, 1, 0));
  for (int k = 0; k < 3; ++k) {
    SkeletonNode n;
    n.stem = 0;
    n.kind = k == 0 ? NodeKind::Base : (k == 1 ? NodeKind::Attachment : NodeKind::Tip);
    n.world.position = Vec3(k - 1.0, 0, 0);
    n.world.rotation = alongX;
    n.radius = n.startRadius = 0.1;
    n.parent = k - 1;
    s.nodes.push_back(n);
  }
  SkeletonNode tip;
  tip.stem = 1;
  tip.kind = NodeKind::Tip;
  tip.world.position = Vec3(std::cos(radians(20.0)), 0, std::sin(radians(20.0)));
  tip.radius = tip.startRadius = 0.02;
  tip.parent = 1;
  s.nodes.push_back(tip);
  SkeletonStem trunk;
  trunk.firstNode = 0;
  trunk.nodeCount = 3;
  SkeletonStem child;
  child.firstNode = 3;
  child.nodeCount = 1;
  child.level = 1;
  child.parentStem = 0;
  child.attachNode = 1;
  s.stems = {trunk, child};
  return s;
}

// Adds a straight stem of radius r from a to b (its own base node and tip), grown from `parent` at `attach`.
void addStem(Skeleton& s, const Vec3& a, const Vec3& b, double r, int parent = -1, int attach = -1) {
  const int id = static_cast<int>(s.stems.size());
  SkeletonNode base, tip;
  base.stem = tip.stem = id;
  base.kind = NodeKind::Base;
  tip.kind = NodeKind::Tip;
  base.world.position = a;
  tip.world.position = b;
  base.radius = tip.radius = tip.startRadius = r;
  base.parent = attach;
  tip.parent = static_cast<int>(s.nodes.size());
  SkeletonStem st;
  st.firstNode = static_cast<int>(s.nodes.size());
  st.nodeCount = 2;
  st.parentStem = parent;
  st.attachNode = attach;
  st.level = parent < 0 ? 0 : 1;
  if (attach >= 0) {  // a child's chain starts at its attachment: only its tip is its own node
    base = tip;
    base.parent = attach;
    st.nodeCount = 1;
    s.nodes.push_back(base);
  } else {
    s.nodes.push_back(base);
    s.nodes.push_back(tip);
  }
  s.stems.push_back(st);
}

}  // namespace

TEST_CASE("against stems but its parent, a child's wood starts where its axis leaves the parent's", "[mesh][self-intersection]") {
  const Skeleton s = shallowChild();
  const auto necks = stemCapsules(s, StemStart::ClearOfParent);
  const auto wood = stemCapsules(s, StemStart::OutOfParentWood);
  REQUIRE(necks[1].size() == 1);
  REQUIRE(wood[1].size() == 1);
  CHECK(glm::length(necks[1][0].a) == Approx(1.6 * 0.12 / std::sin(radians(20.0))));
  // Found on the parent's own capsules, not from a capped sine: fails with the neck's 14-degree floor at 10 degrees.
  CHECK(glm::length(wood[1][0].a) == Approx(0.1 / std::sin(radians(20.0))).epsilon(1e-3));
  CHECK(wood[1][0].flatStart);
  // One stem's capsules alone (what the checks build as pairs need them) are the same as in the whole tree's.
  for (int stem = 0; stem < static_cast<int>(s.stems.size()); ++stem) {
    for (const auto& [start, all] : {std::pair{StemStart::ClearOfParent, &necks}, std::pair{StemStart::OutOfParentWood, &wood}}) {
      const std::vector<Capsule> one = stemCapsulesOf(s, stem, start);
      const std::vector<Capsule>& expected = (*all)[static_cast<std::size_t>(stem)];
      REQUIRE(one.size() == expected.size());
      for (std::size_t k = 0; k < one.size(); ++k) {
        CHECK(one[k].a == expected[k].a);
        CHECK(one[k].b == expected[k].b);
        CHECK(one[k].ra == expected[k].ra);
        CHECK(one[k].rb == expected[k].rb);
        CHECK(one[k].flatStart == expected[k].flatStart);
      }
    }
  }

  // Stem 2, a thin trunk of its own along y, crosses the child's axis half a metre out: between where the child's
  // axis leaves stem 0 and where its wood clears stem 0's, and itself clear of stem 0 (1.52 (0.1 + 0.005) < 0.171).
  Skeleton crossing = s;
  const Vec3 dir(std::cos(radians(20.0)), 0, std::sin(radians(20.0))), up(-dir.z, 0, dir.x);
  const Vec3 at = 0.5 * dir;
  addStem(crossing, at - Vec3(0, 1, 0), at + Vec3(0, 1, 0), 0.005);
  TreeMesh tree;
  QuadSoup q;
  const Vec3 c = at + 0.03 * up;  // the child's surface (at 1.52 r) above its axis
  q.quad(c - 0.05 * dir - Vec3(0, 0.05, 0), c + 0.05 * dir - Vec3(0, 0.05, 0), c + 0.05 * dir + Vec3(0, 0.05, 0),
         c - 0.05 * dir + Vec3(0, 0.05, 0));
  q.quad(at + Vec3(0, -0.05, -0.05), at + Vec3(0, 0.05, -0.05), at + Vec3(0, 0.05, 0.05), at + Vec3(0, -0.05, 0.05));
  tree.mesh = q.mesh;
  tree.quadStem = {1, 2};
  SelfIntersectionReport report = checkSelfIntersections(tree, crossing);
  REQUIRE(report.pairs == 1);
  CHECK(report.hits[0].relation == StemRelation::Other);
  CHECK(report.skeletonMade == 1);  // both stems' wood is there; with the neck's capsules it was the mesher's

  // The same quads with stem 2 lifted 0.2 off the child: no wood of either there.
  Skeleton lifted = crossing;
  for (SkeletonNode& n : lifted.nodes)
    if (n.stem == 2) n.world.position += 0.2 * up;
  report = checkSelfIntersections(tree, lifted);
  REQUIRE(report.pairs == 1);
  CHECK(report.meshMade == 1);

  // Stem 2 a sibling leaving stem 0 beside the child (its axis along y from the origin): the two cross only
  // inside stem 0's wood, where neither's own wood has begun, so the pair is the mesher's.
  Skeleton sibling = s;
  addStem(sibling, Vec3(0), Vec3(0, 1, 0), 0.02, 0, 1);
  TreeMesh inside;
  QuadSoup r;
  r.quad(Vec3(-0.05, -0.05, 0.03), Vec3(0.1, -0.05, 0.03), Vec3(0.1, 0.05, 0.03), Vec3(-0.05, 0.05, 0.03));
  r.quad(Vec3(0.02, -0.05, -0.02), Vec3(0.02, 0.05, -0.02), Vec3(0.02, 0.05, 0.08), Vec3(0.02, -0.05, 0.08));
  inside.mesh = r.mesh;
  inside.quadStem = {1, 2};
  report = checkSelfIntersections(inside, sibling);
  REQUIRE(report.pairs == 1);
  CHECK(report.hits[0].relation == StemRelation::Siblings);
  CHECK(report.meshMade == 1);
}

TEST_CASE("a mesh-made pair in the neck of a child leaving at under 34 degrees is at a shallow joint", "[mesh][self-intersection]") {
  auto tilted = [](double degrees) {
    Skeleton s = shallowChild();
    s.nodes[3].world.position = Vec3(std::cos(radians(degrees)), 0, std::sin(radians(degrees)));
    return s;
  };
  // Its axis leaves the parent's radius at R / tan(angle): past 1.5 R below 33.7 degrees.
  CHECK(shallowJoint(tilted(20.0), 1));
  CHECK(shallowJoint(tilted(33.0), 1));
  CHECK_FALSE(shallowJoint(tilted(35.0), 1));
  CHECK_FALSE(shallowJoint(tilted(160.0), 1));  // a backward child leaves straight out first
  CHECK_FALSE(shallowJoint(tilted(20.0), 0));   // a trunk has no parent

  // A quad of the child (stem 1) crossed by one of a thin trunk (stem 2) whose wood is far off: mesh-made.
  auto check = [](const Skeleton& child, const std::vector<MeshRing>& rings) {
    Skeleton s = child;
    addStem(s, Vec3(0, -1, 5), Vec3(0, 1, 5), 0.005);
    const Vec3 at(0.4, 0, 0.3);
    QuadSoup q;
    q.quad(at + Vec3(-0.05, -0.05, 0), at + Vec3(0.05, -0.05, 0), at + Vec3(0.05, 0.05, 0), at + Vec3(-0.05, 0.05, 0));
    q.quad(at + Vec3(0, -0.1, -0.05), at + Vec3(0, 0.1, -0.05), at + Vec3(0, 0.1, 0.05), at + Vec3(0, -0.1, 0.05));
    TreeMesh tree;
    tree.mesh = q.mesh;
    tree.quadStem = {1, 2};
    tree.rings = rings;
    const SelfIntersectionReport r = checkSelfIntersections(tree, s);
    INFO(r.pairs << " pairs, " << r.skeletonMade << " skeleton-made");
    REQUIRE(r.meshMade == 1);
    CHECK(r.hits[0].shallowJoint == (r.meshMadeAtShallowJoints == 1));
    return r.meshMadeAtShallowJoints;
  };
  const MeshRing collar{1, {0, 1, 2, 3}, Vec3(0.4, 0, 0.3), 0.0, 0.02, -1.0, false};
  const MeshRing onSkeleton{1, {4, 5, 6, 7}, Vec3(0.6, 0, 0.2), 0.0, 0.02, 0.6, false};
  CHECK(check(tilted(20.0), {collar}) == 1);              // a corner on the child's collar: its neck
  CHECK(check(tilted(20.0), {}) == 0);                    // no cross section says where the neck is
  CHECK(check(tilted(20.0), {onSkeleton, collar}) == 0);  // an off-skeleton ring past the first on it: a tip
  CHECK(check(tilted(40.0), {collar}) == 0);              // a steep child's neck
}

TEST_CASE("a twig whose neck crosses another stem where the skeletons do not is a fake branch, its port closed", "[mesh][self-intersection]") {
  // Mesh-made pairs when written, before -> after: the CA black oak preset at seed 1 20 -> 0 (a twig with its two
  // clones), the willow preset at seed 2 30 -> 11 (four twigs with their clones; at seed 4 24 -> 11 once
  // limbs fused along a trunk up to their split got their own construction, which left seed 2 none to take), the palm preset at seed 2 14 -> 0
  // (thin level-1 fronds); the aspen file 25 -> 0 (all at
  // twigs' necks), the tupelo file 12 -> 0 (two branches bearing only twigs among them; at seed 3 once a neck's
  // slabs counted as its neck, 6 -> 0), the sassafras file at
  // seed 2 12 -> 0 (branches bearing only twigs, each neck through its own tube), the desert bush file
  // 23 -> 10 (the rest at limbs' necks). A thin clone bearing nothing goes alone, with the clones splitting from it:
  // the desert bush file at seed 3 8 -> 0 (forks at its branches' ends), the willow preset at seed 1 12 -> 0 (a limb
  // of a neighbouring trunk passing a shallow limb's collar).
  struct Case {
    const char* name;
    bool arbaroFile;
    std::uint64_t seed;
    bool allGone;
  };
  const Case tree = GENERATE(values<Case>({{"ca-black-oak", false, 1, true},
                                        {"weeping-willow", false, 4, false},
                                        {"palm", false, 2, true},
                                        {"quaking_aspen", true, 1, true},
                                        {"black_tupelo", true, 1, true},
                                        {"black_tupelo", true, 3, true},  // a twig through a branch's neck slab
                                        {"sassafras", true, 2, true},
                                        {"desert_bush", true, 1, false},
                                        {"desert_bush", true, 3, true},
                                        {"weeping-willow", false, 1, true}}));
  INFO(tree.name << " at seed " << tree.seed);
  if (tree.arbaroFile && test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR).empty()) return;  // it said why
  GrowthOptions o;
  o.seed = tree.seed;
  const SpeciesParams params =
      tree.arbaroFile ? loadSpeciesFile(std::string(ARBOR_SPECIES_DIR) + "/" + tree.name + ".xml") : test::loadPreset(tree.name);
  const Skeleton skeleton = generateSkeleton(params, o);
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  const TreeMesh before = buildTreeMesh(skeleton, keep);
  // The pass alone (buildTreeMesh may mesh again where it leaves crossings: the willow preset at seed 4).
  TreeMesh after = before;
  fakeCrossingTwigs(after, skeleton);
  const std::size_t meshMadeBefore = checkSelfIntersections(before, skeleton).meshMade;
  const std::size_t meshMadeAfter = checkSelfIntersections(after, skeleton).meshMade;
  REQUIRE(meshMadeBefore > 0);
  CHECK(meshMadeAfter < meshMadeBefore);
  if (tree.allGone) CHECK(meshMadeAfter == 0);

  const std::set<int> was(before.fakedStems.begin(), before.fakedStems.end());
  std::set<int> taken;
  for (int s : after.fakedStems) {
    if (!was.contains(s)) taken.insert(s);
  }
  REQUIRE_FALSE(taken.empty());
  std::size_t twigQuads = 0;
  for (int s : before.quadStem) twigQuads += taken.contains(s) ? 1 : 0;
  auto hadQuads = [&](std::size_t s) { return std::find(before.quadStem.begin(), before.quadStem.end(), static_cast<int>(s)) != before.quadStem.end(); };
  std::set<int> parents;  // of the twigs taken out whole: where their ports were
  std::size_t twigs = 0;
  for (int s : taken) {
    const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(s)];
    CHECK(st.level >= 1);
    // A twig: a family from its root, or a clone alone; its port is on what it grows from.
    const int from = st.cloneOf >= 0 ? st.cloneOf : st.parentStem;
    if (taken.contains(from)) continue;
    // At level 1 only a thin one (a quarter of its parent's radius at the parent's base), with its clones and twigs.
    if (st.level == 1) CHECK(st.startRadius <= 0.25 * skeleton.stems[static_cast<std::size_t>(st.parentStem)].startRadius);
    ++twigs;
    parents.insert(from);
  }
  for (int s : taken) {
    // A twig goes whole: its clones and children with it, or they had no quads.
    for (std::size_t c = 0; c < skeleton.stems.size(); ++c) {
      if (skeleton.stems[c].parentStem == s || skeleton.stems[c].cloneOf == s) CHECK((taken.contains(static_cast<int>(c)) || !hadQuads(c)));
    }
  }
  CHECK(std::none_of(after.quadStem.begin(), after.quadStem.end(), [&](int s) { return taken.contains(s); }));
  // Each twig's quads gone, one face closing its port.
  CHECK(after.mesh.quads.size() == before.mesh.quads.size() - twigQuads + twigs);

  // Nothing moved: every vertex left is one the mesh had, and every face but the ports is one it had.
  using Point = std::array<float, 3>;
  auto point = [](const glm::vec3& p) { return Point{p.x, p.y, p.z}; };
  std::set<Point> points;
  for (const glm::vec3& p : before.mesh.positions) points.insert(point(p));
  std::size_t moved = 0;
  for (const glm::vec3& p : after.mesh.positions) moved += points.contains(point(p)) ? 0 : 1;
  CHECK(moved == 0);
  const std::vector<std::uint32_t> ports = test::newFaces(before.mesh, after.mesh);
  for (std::uint32_t f : ports) CHECK(parents.contains(after.quadStem[f]));  // a port face is its parent's surface again
  CHECK(ports.size() == twigs);
  // A face that closed a port crosses nothing where the skeleton does not (a neighbouring twig's neck).
  // (A neck through its own parent is listed too, and stays where the child is no twig: the random graph's limbs.)
  const std::vector<QuadPairHit> atPorts = pairsToMendWith(after, skeleton, ports);
  CHECK(std::none_of(atPorts.begin(), atPorts.end(), [](const QuadPairHit& h) { return h.origin == PairOrigin::Mesh; }));

  CHECK(test::checkClosedManifold(after.mesh).degenerateFaces == 0);
  CHECK(after.mesh.normals.size() == after.mesh.positions.size());
  CHECK(after.mesh.uvw.size() == after.mesh.positions.size());
  // Nothing is left to take out.
  TreeMesh again = after;
  CHECK(fakeCrossingTwigs(again, skeleton) == 0);
}

TEST_CASE("two trunk clones grown into each other: a limb leaving one through the other crosses it as the skeleton makes it", "[mesh][self-intersection]") {
  // The willow preset at seed 1 splits its trunk at a few degrees; clones 4 and 5 stay within each other's wood
  // for a metre. Limb 535 leaves clone 5 on the side facing clone 4, and its neck crosses 4 in 9 pairs of quads,
  // 2.5 parent radii off 5's axis, where 4's and 5's wood overlap: a collar on 5 stands for 5's surface, which
  // lies inside 4 there. Counted mesh-made while a clone's kin were left out of that rule.
  const Skeleton skeleton = generateSkeleton(test::loadPreset("weeping-willow"), GrowthOptions{});
  REQUIRE(skeleton.stems.size() > 535);
  REQUIRE(skeleton.stems[4].cloneOf == skeleton.stems[5].cloneOf);
  REQUIRE(skeleton.stems[535].parentStem == 5);
  const TreeMesh tree = buildTreeMesh(skeleton);
  std::size_t pairs = 0;
  for (const QuadPairHit& h : checkSelfIntersections(tree, skeleton).hits) {
    if (std::min(h.stemA, h.stemB) != 4 || std::max(h.stemA, h.stemB) != 535) continue;
    ++pairs;
    CHECK(h.origin == PairOrigin::Skeleton);
  }
  CHECK(pairs > 0);
  // Each clone's wood as seen against the other begins where its axis has left the other's: their overlap at the
  // split itself (by construction) is left out, so a collar crossing there stays the mesher's.
  const std::vector<Capsule> four = capsulesOutOf(skeleton, 4, 5), fourFromSplit = stemCapsulesOf(skeleton, 4, StemStart::OutOfParentWood);
  const std::vector<Capsule> five = stemCapsulesOf(skeleton, 5, StemStart::OutOfParentWood);
  REQUIRE_FALSE(four.empty());
  const Vec3 split = skeleton.nodes[static_cast<std::size_t>(skeleton.stems[4].attachNode)].world.position;
  CHECK(glm::distance(four.front().a, split) > glm::distance(fourFromSplit.front().a, split) + 0.1);
  CHECK(stemReach(five, four.front().a) == Approx(1.0).epsilon(0.02));
}

TEST_CASE("two limbs leaving two clones grown into each other cross as the skeleton makes them, where both clones' wood is", "[mesh][self-intersection]") {
  // The willow preset at seed 1: limb 287 leaves clone 4 and limb 535 clone 5 where the two clones stand within
  // each other's wood; 287's inset and 535's neck meet there in 3 pairs of quads, 3-4 radii off either limb's axis
  // but inside both clones' wood (counted mesh-made before). Limb 411's neck against 116 (a limb of another trunk)
  // stays the mesher's: 411's clone and 116's source do not overlap there. (116, a thin clone bearing nothing, is
  // a fake branch in the tree as built; the classification is looked at with it meshed. Clones 4 and 5 bear these
  // limbs near the split, so their collars now stand nearer their ports and the two necks clear each other: the
  // pairs are looked at with the collars where they stood.)
  const Skeleton skeleton = generateSkeleton(test::loadPreset("weeping-willow"), GrowthOptions{});
  REQUIRE(skeleton.stems.size() > 535);
  REQUIRE(skeleton.stems[287].parentStem == 4);
  REQUIRE(skeleton.stems[535].parentStem == 5);
  REQUIRE(skeleton.stems[4].cloneOf == skeleton.stems[5].cloneOf);
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  keep.nearEarlyCloneCollars = false;
  const TreeMesh tree = buildTreeMesh(skeleton, keep);
  std::size_t clones = 0, apart = 0;
  for (const QuadPairHit& h : checkSelfIntersections(tree, skeleton).hits) {
    const auto [lo, hi] = std::minmax(h.stemA, h.stemB);
    if (lo == 287 && hi == 535) {
      ++clones;
      CHECK(h.origin == PairOrigin::Skeleton);
    }
    if (lo == 116 && hi == 411) {
      ++apart;
      CHECK(h.origin == PairOrigin::Mesh);
    }
  }
  CHECK(clones > 0);
  CHECK(apart > 0);
}

TEST_CASE("where two stems' wood overlaps: near the crossing of their capsules, never for stems apart", "[mesh][self-intersection]") {
  const std::vector<Capsule> a{Capsule{Vec3(-1, 0, 0), Vec3(1, 0, 0), 0.1, 0.1}};
  const std::vector<Capsule> b{Capsule{Vec3(0, -1, 0.05), Vec3(0, 1, 0.05), 0.1, 0.1}};   // crosses a at the origin
  const std::vector<Capsule> c{Capsule{Vec3(0, -1, 0.5), Vec3(0, 1, 0.5), 0.1, 0.1}};    // passes 0.5 above a
  CHECK(distanceToOverlap(a, b, Vec3(0, 0, 0), 1.0) < 0.3);
  CHECK(distanceToOverlap(a, b, Vec3(0.3, 0, 0), 1.0) == Approx(1.5 / 1.0).epsilon(0.05));  // 0.3 / (0.1 + 0.1)
  CHECK(std::isinf(distanceToOverlap(a, c, Vec3(0, 0, 0.25), 1.0)));
  CHECK(std::isinf(distanceToOverlap(a, c, Vec3(0, 0, 0.25), 2.4)));   // 0.48 of reach at 2.4 times: still apart
  CHECK(distanceToOverlap(a, c, Vec3(0, 0, 0.25), 2.6) < 0.1);         // 0.52: the inflated wood touches
  // Near-parallel axes overlap along their length (two grass stalks from one root), not only at one closest point.
  const std::vector<Capsule> d{Capsule{Vec3(-1, 0, 0.05), Vec3(1, 0.1, 0.05), 0.1, 0.1}};  // 3 degrees off a, beside it
  CHECK(distanceToOverlap(a, d, Vec3(-0.9, 0, 0.025), 1.0) < 0.1);
  CHECK(distanceToOverlap(a, d, Vec3(0.9, 0.04, 0.025), 1.0) < 0.1);
  CHECK(distanceToOverlap(a, d, Vec3(0.9, 0.04, 0.6), 1.0) > 2.5);  // beside the overlap, not on it
}

namespace {

// Points at which the mesher could have handed a built mesh over part by part (PairsToMendSearch::advance's
// promise): every stem with a quad or cross section before the point has all of them before it, on vertices before
// it, and nothing after it uses an earlier vertex but quads (ports in a parent). At most `most`, spread evenly.
std::vector<MeshProgress> settlePoints(const TreeMesh& tree, std::size_t most) {
  int stems = 0;
  for (int s : tree.quadStem) stems = std::max(stems, s + 1);
  for (const MeshRing& r : tree.rings) stems = std::max(stems, r.stem + 1);
  const auto n = static_cast<std::size_t>(stems);
  std::vector<std::size_t> firstQuad(n, SIZE_MAX), lastQuad(n, 0), firstRing(n, SIZE_MAX), lastRing(n, 0);
  for (std::size_t f = 0; f < tree.quadStem.size(); ++f) {
    if (tree.quadStem[f] < 0) continue;
    const auto s = static_cast<std::size_t>(tree.quadStem[f]);
    firstQuad[s] = std::min(firstQuad[s], f);
    lastQuad[s] = f;
  }
  for (std::size_t r = 0; r < tree.rings.size(); ++r) {
    if (tree.rings[r].stem < 0) continue;
    const auto s = static_cast<std::size_t>(tree.rings[r].stem);
    firstRing[s] = std::min(firstRing[s], r);
    lastRing[s] = r;
  }
  std::vector<MeshProgress> points;
  for (std::size_t q = 1; q < tree.quadStem.size(); ++q) {
    if (tree.quadStem[q] == tree.quadStem[q - 1] || tree.quadStem[q] < 0) continue;
    // The rings before the point: those of stems whose quads all lie before it.
    std::size_t r = 0;
    while (r < tree.rings.size() && tree.rings[r].stem >= 0 && firstQuad[static_cast<std::size_t>(tree.rings[r].stem)] < q) ++r;
    bool split = false;
    for (std::size_t s = 0; s < n && !split; ++s) {
      const bool quadsBefore = firstQuad[s] < q, quadsAfter = firstQuad[s] != SIZE_MAX && lastQuad[s] >= q;
      const bool ringsBefore = firstRing[s] < r, ringsAfter = firstRing[s] != SIZE_MAX && lastRing[s] >= r;
      split = ((quadsBefore || ringsBefore) && (quadsAfter || ringsAfter));
    }
    if (split) continue;
    std::uint32_t v = 0;  // the vertices before the point: all those of its quads and rings
    for (std::size_t f = 0; f < q; ++f)
      for (std::uint32_t x : tree.mesh.quads[f]) v = std::max(v, x + 1);
    bool late = false;  // a later cross section on an earlier vertex
    for (std::size_t k = r; k < tree.rings.size() && !late; ++k)
      for (std::uint32_t x : tree.rings[k].vertices) late = late || x < v;
    if (!late) points.push_back(MeshProgress{q, v, r});
  }
  std::vector<MeshProgress> spread;
  for (std::size_t k = 0; k < most && !points.empty(); ++k) spread.push_back(points[k * points.size() / most]);
  spread.erase(std::unique(spread.begin(), spread.end(), [](const MeshProgress& a, const MeshProgress& b) { return a.quads == b.quads; }), spread.end());
  return spread;
}

bool samePairs(const std::vector<QuadPairHit>& x, const std::vector<QuadPairHit>& y) {
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].a != y[i].a || x[i].b != y[i].b || x[i].origin != y[i].origin || x[i].throughParent != y[i].throughParent ||
        x[i].point != y[i].point || x[i].reachA != y[i].reachA || x[i].reachB != y[i].reachB)
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("searched part by part as the mesher settles them, the pairs to mend are those of one search of the whole mesh", "[mesh][self-intersection]") {
  // Trees whose meshes, left without the crossing-twig pass, have pairs to mend (mesh-made ones and necks).
  struct Case {
    const char* name;
    std::uint64_t seed;
  };
  const Case tree = GENERATE(values<Case>({{"ca-black-oak", 1}, {"weeping-willow", 4}, {"palm", 2}}));
  INFO(tree.name << " at seed " << tree.seed);
  GrowthOptions o;
  o.seed = tree.seed;
  const Skeleton skeleton = generateSkeleton(test::loadPreset(tree.name), o);
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  const TreeMesh mesh = buildTreeMesh(skeleton, keep);
  const std::vector<QuadPairHit> whole = pairsToMendOf(mesh, skeleton, std::vector<bool>(skeleton.stems.size(), true));
  REQUIRE(!whole.empty());
  const std::vector<MeshProgress> points = settlePoints(mesh, 12);
  INFO(points.size() << " points");
  REQUIRE(points.size() >= 3);
  PairsToMendSearch parts;
  for (const MeshProgress& p : points) parts.advance(mesh, skeleton, p);
  CHECK(samePairs(parts.finish(mesh, skeleton), whole));
  CHECK(parts.searchedInParts());
  // A part that cuts a stem's cross sections in two breaks the promise: the whole mesh is searched after all.
  PairsToMendSearch broken;
  const MeshProgress& mid = points[points.size() / 2];
  broken.advance(mesh, skeleton, MeshProgress{mid.quads, mid.vertices, mid.rings + 1});
  broken.advance(mesh, skeleton, points.back());
  CHECK(samePairs(broken.finish(mesh, skeleton), whole));
  CHECK_FALSE(broken.searchedInParts());
}

TEST_CASE("a tree meshed with the crossing-twig search beside the mesher is the tree meshed without", "[mesh][self-intersection]") {
  // Presets whose crossing-twig pass takes twigs out (the CA black oak, the palm) or leaves necks crossing (the willow).
  struct Case {
    const char* name;
    std::uint64_t seed;
  };
  const Case tree = GENERATE(values<Case>({{"ca-black-oak", 1}, {"weeping-willow", 4}, {"palm", 2}, {"black-tupelo", 1}}));
  INFO(tree.name << " at seed " << tree.seed);
  GrowthOptions o;
  o.seed = tree.seed;
  const Skeleton skeleton = generateSkeleton(test::loadPreset(tree.name), o);
  MeshOptions after, beside;
  beside.searchBesideMesher = true;
  const TreeMesh a = buildTreeMesh(skeleton, after);
  const TreeMesh b = buildTreeMesh(skeleton, beside);
  CHECK(a.mesh.quads == b.mesh.quads);
  CHECK(a.mesh.positions == b.mesh.positions);
  CHECK(a.quadStem == b.quadStem);
  CHECK(a.fakedStems == b.fakedStems);
}

TEST_CASE("the BVH finds the same pairs as testing every pair, on a preset's mesh", "[mesh][self-intersection]") {
  const TreeMesh tree = test::meshOf("palm", 1);
  const auto fast = findIntersectingQuads(tree.mesh);
  const auto slow = findIntersectingQuadsBruteForce(tree.mesh);
  INFO(tree.mesh.quads.size() << " quads");
  REQUIRE(fast.size() == slow.size());
  for (std::size_t i = 0; i < fast.size(); ++i) {
    CHECK(fast[i].a == slow[i].a);
    CHECK(fast[i].b == slow[i].b);
  }
  // A tree with some crossing in it, so that the comparison compares something.
  const TreeMesh willow = test::meshOf("weeping-willow", 2, 2);
  const auto fastW = findIntersectingQuads(willow.mesh);
  CHECK(fastW.size() == findIntersectingQuadsBruteForce(willow.mesh).size());
}

// Measurement only (issue 13): mesh-made and skeleton-made pairs per preset and Arbaro file at seeds 1-3.
// The mesher is being fixed; the assertion of zero mesh-made pairs comes with the fix
// (meshMadeIntersections()).
TEST_CASE("self-intersections of every preset and Arbaro file at seeds 1-3 (measured, not asserted)", "[mesh][self-intersection][measure][.]") {
  std::vector<std::pair<std::string, SpeciesParams>> species;
  for (const std::string& name : test::presetNames()) species.emplace_back(name, test::loadPreset(name));
  for (const std::string& file : test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR))
    species.emplace_back(file.substr(file.find_last_of('/') + 1), loadSpeciesFile(file));
  std::printf("%-24s %4s %9s %7s %9s %9s %6s %6s %9s\n", "species", "seed", "quads", "pairs", "skeleton", "mesh",
              "folds", "necks", "ms");
  for (const auto& [name, params] : species) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      GrowthOptions o;
      o.seed = seed;
      const Skeleton skeleton = generateSkeleton(params, o);
      const TreeMesh tree = buildTreeMesh(skeleton);
      const SelfIntersectionReport r = checkSelfIntersections(tree, skeleton);
      std::printf("%-24s %4llu %9zu %7zu %9zu %9zu %6zu %6zu %9.1f\n", name.c_str(), static_cast<unsigned long long>(seed),
                  r.quads, r.pairs, r.skeletonMade, r.meshMade, r.folds, r.neckCrossings, r.milliseconds);
      std::fflush(stdout);
      CHECK(r.skeletonMade + r.meshMade == r.pairs);
    }
  }
}

namespace {

// An ABOP plant at seed 1, meshed with its crossing twigs left in and taken out.
struct TakeOut {
  Skeleton skeleton;
  TreeMesh before, after;
};
TakeOut plantTakeOut(const std::string& name) {
  GrowthOptions o;
  o.seed = 1;
  TakeOut t{loadTreeSource(std::string(ARBOR_ASSET_DIR) + "/lsystems/" + name + ".lsys").grow(o), {}, {}};
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  t.before = buildTreeMesh(t.skeleton, keep);
  t.after = buildTreeMesh(t.skeleton);
  return t;
}

// The skeleton an Arbaro species file grows at `seed`; none where the files are missing (arbaroSpeciesFiles says why).
std::optional<Skeleton> arbaroSkeleton(const std::string& file, std::uint64_t seed) {
  if (test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR).empty()) return std::nullopt;
  GrowthOptions o;
  o.seed = seed;
  return generateSkeleton(loadSpeciesFile(std::string(ARBOR_SPECIES_DIR) + "/" + file + ".xml"), o);
}

}  // namespace

TEST_CASE("a level-1 twig high on a tapering stem is thin by that stem's base: a crossing one is a fake branch", "[mesh][self-intersection]") {
  // ABOP's fig. 1.31a: side branches near the top of a main axis that tapers to a third of its base radius. Mesh-made
  // pairs at seed 1 when written: 186 without the take-out, 26 with a quarter of the parent's radius where the twig
  // attaches as the measure, 5 with a quarter of its radius at its base.
  const auto [skeleton, before, after] = plantTakeOut("fig-1-31a");
  CHECK(checkSelfIntersections(after, skeleton).meshMade * 10 < checkSelfIntersections(before, skeleton).meshMade);
  const std::set<int> was(before.fakedStems.begin(), before.fakedStems.end());
  std::size_t thinByBase = 0;  // level-1 twigs taken out that are thicker than a quarter of the radius where they attach
  for (int s : after.fakedStems) {
    const SkeletonStem& st = skeleton.stems[static_cast<std::size_t>(s)];
    if (was.contains(s) || st.level != 1 || st.cloneOf >= 0) continue;
    CHECK(st.startRadius <= 0.25 * skeleton.stems[static_cast<std::size_t>(st.parentStem)].startRadius);
    thinByBase += st.startRadius > 0.25 * skeleton.nodes[static_cast<std::size_t>(st.attachNode)].radius ? 1 : 0;
  }
  CHECK(thinByBase > 0);
  test::checkClosedManifold(after.mesh);
}

TEST_CASE("a child leaving its inset straight for its skeleton stands clear of its parent, not grazing it", "[mesh][self-intersection]") {
  // The cottonwood file at seed 1: limb 29 leaves trunk 3 at 48 degrees through an inset. Its first cross section
  // stood where the band from the inset first cleared the trunk, a corner 0.1 mm off the trunk's 1.6 m band: the
  // next band crossed it (2 mesh-made pairs). One step further on it stands clear.
  const std::optional<Skeleton> grown = arbaroSkeleton("eastern_cottonwood", 1);
  if (!grown) return;  // it said why
  const Skeleton& skeleton = *grown;
  REQUIRE(skeleton.stems.size() > 29);
  REQUIRE(skeleton.stems[29].parentStem == 3);
  const TreeMesh tree = buildTreeMesh(skeleton);
  const std::size_t limbQuads = static_cast<std::size_t>(std::count(tree.quadStem.begin(), tree.quadStem.end(), 29));
  REQUIRE(limbQuads > 0);
  std::size_t meshMade = 0;
  for (const QuadPairHit& h : checkSelfIntersections(tree, skeleton).hits) {
    const auto [lo, hi] = std::minmax(h.stemA, h.stemB);
    meshMade += lo == 3 && hi == 29 && h.origin == PairOrigin::Mesh ? 1 : 0;
  }
  CHECK(meshMade == 0);
}

TEST_CASE("a twig crossing the tip of a branch that bears children is a fake branch", "[mesh][self-intersection]") {
  // ABOP's fig. 1.24c: its branches' tips reach past their skeletons' ends among the twigs beside them. Mesh-made
  // pairs at seed 1 when written: 152 without the take-out, 52 with it before tips were searched, 8 with them.
  const auto [skeleton, before, after] = plantTakeOut("fig-1-24c");
  const std::size_t meshMadeBefore = checkSelfIntersections(before, skeleton).meshMade;
  const std::size_t meshMadeAfter = checkSelfIntersections(after, skeleton).meshMade;
  CHECK(meshMadeAfter * 10 < meshMadeBefore);
  CHECK(after.fakedStems.size() > before.fakedStems.size());
  test::checkClosedManifold(after.mesh);
}

TEST_CASE("a twig whose neck runs through its own parent is a fake branch, and the check tells such necks from re-entries", "[mesh][self-intersection]") {
  // The tamarack file at seed 2: twigs running close along a curving branch, each meshed as one straight band from
  // its collar to its tip, cut across the branch (109 pairs of a child's neck or first band with its own parent,
  // all skeleton-made by the classifier, since the two stems' wood lies within two radii there). Its other 237
  // parent crossings lie farther along children whose skeletons run back into their parents.
  const std::optional<Skeleton> grown = arbaroSkeleton("tamarack", 2);
  if (!grown) return;  // it said why
  const Skeleton& skeleton = *grown;
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  const TreeMesh before = buildTreeMesh(skeleton, keep);
  const SelfIntersectionReport was = checkSelfIntersections(before, skeleton);
  REQUIRE(was.necksThroughParent > 0);
  CHECK(was.necksThroughParent < was.neckCrossings);
  // Per quad, a corner on one of its own stem's cross sections off the skeleton before its first on it, or on a
  // neck's slabs.
  std::vector<int> neckRingOf(before.mesh.vertexCount(), -1);
  std::set<int> onSkeleton;
  for (const MeshRing& ring : before.rings) {
    if (ring.arc >= 0.0) onSkeleton.insert(ring.stem);
    if (onSkeleton.contains(ring.stem) && !ring.alongNeck) continue;
    for (std::uint32_t v : ring.vertices) neckRingOf[v] = ring.stem;
  }
  std::vector<bool> neck(before.mesh.quads.size(), false);
  for (std::size_t f = 0; f < neck.size(); ++f) {
    for (std::uint32_t v : before.mesh.quads[f]) neck[f] = neck[f] || (before.quadStem[f] >= 0 && neckRingOf[v] == before.quadStem[f]);
  }
  for (const QuadPairHit& h : was.hits) {
    // Exactly a child's quad in its neck or first band against its own parent's.
    const bool aChild = h.stemA >= 0 && h.stemB >= 0 && skeleton.stems[static_cast<std::size_t>(h.stemA)].parentStem == h.stemB &&
                        skeleton.stems[static_cast<std::size_t>(h.stemA)].cloneOf < 0;
    const bool bChild = h.stemA >= 0 && h.stemB >= 0 && skeleton.stems[static_cast<std::size_t>(h.stemB)].parentStem == h.stemA &&
                        skeleton.stems[static_cast<std::size_t>(h.stemB)].cloneOf < 0;
    CHECK(h.throughParent == ((aChild && neck[h.a]) || (bChild && neck[h.b])));
  }
  const TreeMesh after = buildTreeMesh(skeleton);
  const SelfIntersectionReport now = checkSelfIntersections(after, skeleton);
  CHECK(now.necksThroughParent == 0);
  CHECK(now.meshMade == 0);
  CHECK(after.fakedStems.size() > before.fakedStems.size());
  CHECK(test::checkClosedManifold(after.mesh).degenerateFaces == 0);
}

TEST_CASE("a limb's neck crossing another limb where no twig can go is meshed again with its collar nearer its port", "[mesh][self-intersection]") {
  // The CA black oak file at seed 2: limb 350 (11 mm) leaves a trunk clone 18 mm thick at 12 degrees; its collar,
  // two child radii off the clone, reached into limb 162 of another clone passing 6 cm from the clone's axis (8
  // mesh-made pairs, the last of all trees at seeds 1-3). Both bear twenty children, so neither is a twig to take
  // out. Meshed again with that collar half as far out, none.
  const std::optional<Skeleton> grown = arbaroSkeleton("ca_black_oak", 2);
  if (!grown) return;  // it said why
  const Skeleton& skeleton = *grown;
  REQUIRE(skeleton.stems.size() > 350);
  MeshOptions keep;
  keep.fakeCrossingTwigs = false;
  TreeMesh first = buildTreeMesh(skeleton, keep);
  CrossingsLeft left;
  fakeCrossingTwigs(first, skeleton, &left);
  CHECK(left.pairs > 0);
  CHECK(std::binary_search(left.necks.begin(), left.necks.end(), 350));
  CHECK(checkSelfIntersections(first, skeleton).meshMade == left.pairs);  // the search saw every pair the check does
  const TreeMesh tree = buildTreeMesh(skeleton);
  CHECK(checkSelfIntersections(tree, skeleton).meshMade == 0);
  CHECK(test::checkClosedManifold(tree.mesh).degenerateFaces == 0);
  // The limb's collar (its first cross section off its skeleton) stands nearer its attachment than before.
  auto collarReach = [&](const TreeMesh& t) {
    for (const MeshRing& r : t.rings) {
      if (r.stem == 350 && r.arc < 0.0) return glm::distance(r.center, skeleton.nodes[static_cast<std::size_t>(skeleton.stems[350].attachNode)].world.position);
    }
    return -1.0;
  };
  CHECK(collarReach(tree) > 0.0);
  CHECK(collarReach(tree) < collarReach(first));
}
