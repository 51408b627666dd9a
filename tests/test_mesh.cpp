// The tree mesh: one closed, consistently oriented 2-manifold per tree, no branch through its parent at a
// joint, flip-coordinate texture values, v along branches, limit radius, options.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "common/input_error.hpp"
#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/cross_section.hpp"
#include "mesh/face_grid.hpp"
#include "mesh/hub_layout.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/stem_capsules.hpp"
#include "mesh/stem_polyline.hpp"
#include "manifold_checks.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/limit_reference.hpp"
#include "growth/weber_penn/species_io.hpp"
#include "test_support.hpp"
#include "tree/build_tree.hpp"

using namespace arbor;
using Catch::Matchers::WithinAbs;

namespace {

Skeleton grow(const SpeciesParams& p, std::uint64_t seed, int levels = 0) {
  GrowthOptions o;
  o.seed = seed;
  o.levels = levels;
  return generateSkeleton(p, o);
}

// One of the Arbaro species files (../shared/arbaro-species), by name without .xml, grown at a seed.
Skeleton growSpeciesFile(const std::string& name, std::uint64_t seed) {
  return grow(loadSpeciesFile(std::string(ARBOR_SPECIES_DIR) + "/" + name + ".xml"), seed);
}

std::vector<int> valences(const QuadMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& q : mesh.quads)
    for (int k = 0; k < 4; ++k) edges[std::minmax(q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)])] = 1;
  std::vector<int> valence(mesh.vertexCount(), 0);
  for (const auto& [e, one] : edges) {
    valence[e.first] += one;
    valence[e.second] += one;
  }
  return valence;
}

// A straight, untapered trunk with nothing on it: a plain cylinder for limit-radius checks.
SpeciesParams cylinderSpecies() {
  SpeciesParams p = test::steadySpecies();
  p.levels = 1;
  p.flare = 0;
  p.stemLevels[0].taper = 0;
  p.stemLevels[0].curveRes = 8;
  return p;
}

// Per stem: whether it has a child (not a stub), or one of the clones it splits into has one: not a twig.
std::vector<bool> bearingStems(const Skeleton& s) {
  std::vector<bool> bears(s.stems.size(), false);
  for (const SkeletonStem& st : s.stems)
    for (int x = st.cloneOf < 0 && !st.stub ? st.parentStem : -1; x >= 0; x = s.stems[static_cast<std::size_t>(x)].cloneOf) bears[static_cast<std::size_t>(x)] = true;
  return bears;
}

}  // namespace

TEST_CASE("every preset meshes to one closed, outward, manifold piece at several seeds and levels", "[mesh]") {
  for (const std::string& name : test::presetNames()) {
    const SpeciesParams p = test::loadPreset(name);
    for (std::uint64_t seed : {1u, 2u}) {
      for (int levels : {2, p.levels}) {
        INFO(name << " seed " << seed << " levels " << levels);
        const TreeMesh tree = buildTreeMesh(grow(p, seed, levels));
        const MeshTopologyReport r = test::checkClosedManifold(tree.mesh);
        CHECK(tree.mesh.quads.size() > 100);
        CHECK(r.degenerateFaces == 0);
        CHECK(r.minValence >= 3);
        CHECK(r.maxValence <= 6);           // corners of at most two ports: every patch stays within 32 points
      }
    }
  }
}

TEST_CASE("the mesher's own crossings stay at or below what was measured for every preset", "[mesh][self-intersection]") {
  // Issue 13's floor is no mesh-made pair at all; it is not met yet (docs/mesh.md, "Known limits"). These are
  // the sums over seeds 1-3 of 2026-12-03 (thin children leaving through inset ports, steep ones with no neck: the
  // poplar 410 -> 114, the palm 457 -> 140, the tupelo 158 -> 126, all trees 58,618 -> 47,537; then siblings grown
  // back into their parent classified as any stem: the oak 251 -> 232, the palm 140 -> 108; then split slabs moved on
  // until their first band runs forwards, tips turning half-way where a full turn folds, and the cross section
  // after a collar moving on until its band runs forwards: the willow 2,000 -> 1,888, its folds 42 -> 0, the
  // poplar 114 -> 102, its folds 4 -> 0; then a child's neck counted as its wood against stems but its parent: the
  // tupelo 126 -> 38, the willow 1,888 -> 1,170, the poplar 102 -> 59, the palm 108 -> 68; then children attached
  // along a long neck leaving through it: the willow 1,170 -> 1,128, its necks 72 -> 50; then twigs joined only
  // past half their length faked: the willow 1,128 -> 1,018, its necks 50 -> 12; then twigs joined only more than a
  // parent radius from their attachment faked: the oak 220 -> 88, the poplar 59 -> 26 (its necks 8 -> 16: the
  // first band of a steep branch whose first slab held those twigs now grazes the trunk), the aspen 38 -> 0, the willow 1,018 ->
  // 939; then branches off limbs bearing only twigs faked likewise: the willow 939 -> 589; then twigs faked from half
  // a radius, and split clones leaving without clearing their source's axis: the willow 589 -> 519; then shallow
  // thin twigs faked: the willow 519 -> 258, the palm 68 -> 34, the poplar 26 -> 22; then twigs just before a
  // split faked: the oak 88 -> 68; then clones leaving a split slab's side with their collar along their own
  // direction: the willow 258 -> 139, the oak 68 -> 38; and the clone through its top likewise: the willow
  // 139 -> 106, the oak 38 -> 27; then long necks bowed with their skeletons, never towards the parent's axis: the
  // willow 106 -> 108, its necks 2 -> 4, for all trees' 1,980 -> 1,889 and the ABOP plants' 13,261 -> 11,383; then
  // neck ports from necks 8 radii long, not 12: the poplar 22 -> 0, its necks 16 -> 4; then a slab's first cross
  // section moved on where its band ran back behind a collar standing off the skeleton: the tupelo 38 -> 2, its
  // folds 1 -> 0; then twigs and twig-bearing branches inside a sibling clone faked: the willow 108 -> 88) plus a
  // tenth; then a child running on along its parent leaving through the top of its last slab: the palm 34 -> 15; then
  // twigs inside a sibling clone's cage, not only its skeleton radius, faked: the willow 88 -> 73, the oak 27 -> 25;
  // then a thick shallow child back on its skeleton right after its collar: the oak 25 -> 21; then twigs through a
  // neighbour's joint faked: the oak's neck crossings 77 -> 45, the poplar's 4 -> 0; since 2026-12-05 every preset's
  // mesh-made pairs are 0, the last the willow's 12 -> 0 once a thin clone bearing nothing was a crossing twig
  // alone, and the caps are the counts themselves): a change to the mesher that makes more fails here. Three seeds, not one: any change to a joint moves one tree's count by a
  // fifth either way (the exact clearance of a child's skeleton: the poplar's seed 1 went 138 -> 161, seed 2
  // 115 -> 103), the sum by a few percent.
  struct Measured {
    const char* preset;
    std::size_t meshMade, folds, necks;
  };
  for (const Measured& m : {Measured{"black-tupelo", 0, 0, 0}, Measured{"ca-black-oak", 0, 0, 45},
                            Measured{"lombardy-poplar", 0, 0, 0}, Measured{"palm", 0, 0, 0},
                            Measured{"quaking-aspen", 0, 0, 0}, Measured{"weeping-willow", 0, 0, 0}}) {
    INFO(m.preset);
    std::size_t meshMade = 0, folds = 0, necks = 0, throughParent = 0, skeletonMade = 0;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const Skeleton s = grow(test::loadPreset(m.preset), seed);
      const SelfIntersectionReport r = checkSelfIntersections(buildTreeMesh(s), s);
      skeletonMade += r.skeletonMade;
      meshMade += r.meshMade;
      folds += r.folds;
      necks += r.neckCrossings;
      throughParent += r.necksThroughParent;
    }
    CHECK(skeletonMade > 0);  // Weber-Penn's branches do cross: the check sees them and tells them apart
    CHECK(throughParent == 0);  // issue 13: no neck through its own parent (the oak's 45 lie farther along its children)
    CHECK(meshMade * 10 <= m.meshMade * 11 + 5);
    CHECK(folds * 10 <= m.folds * 11 + 5);
    CHECK(necks * 10 <= m.necks * 11 + 5);
  }
}

TEST_CASE("the flip coordinate is 0 at front and back and +-1 at the sides of every unshared corner", "[mesh]") {
  const TreeMesh tree = buildTreeMesh(grow(test::loadPreset("quaking-aspen"), 3));
  const std::vector<int> valence = valences(tree.mesh);
  std::size_t exact = 0, shared = 0, insets = 0;
  for (const MeshRing& ring : tree.rings) {
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t v = ring.vertices[static_cast<std::size_t>(k)];
      const glm::vec3 uvw = tree.mesh.uvw[v];
      CHECK(uvw.x >= 0.0f);
      CHECK(uvw.x <= 1.0f);
      CHECK(std::fabs(uvw.z) <= 1.0f);
      if (ring.inset) {  // on the parent's side, with the parent's texture (tested with the inset)
        ++insets;
      } else if (valence[v] <= 4) {  // not a port corner: nothing averaged into it
        CHECK(uvw.x == static_cast<float>(kRingU[static_cast<std::size_t>(k)]));
        CHECK(uvw.z == static_cast<float>(kRingFlip[static_cast<std::size_t>(k)]));
        ++exact;
      } else {
        ++shared;
      }
    }
  }
  CHECK(exact > 10 * shared / 2);
  CHECK(shared > 0);
  CHECK(insets > 0);
}

TEST_CASE("texture v grows monotonically along every branch", "[mesh]") {
  const TreeMesh tree = buildTreeMesh(grow(test::loadPreset("black-tupelo"), 2));
  std::map<int, double> last;
  std::size_t steps = 0;
  for (const MeshRing& ring : tree.rings) {
    auto it = last.find(ring.stem);
    if (it != last.end()) {
      CHECK(ring.v > it->second);
      ++steps;
    }
    last[ring.stem] = ring.v;
  }
  CHECK(steps > 1000);
}

TEST_CASE("the same skeleton gives the same mesh", "[mesh]") {
  const Skeleton s = grow(test::loadPreset("weeping-willow"), 4, 3);
  const TreeMesh a = buildTreeMesh(s), b = buildTreeMesh(s);
  CHECK(a.mesh.positions == b.mesh.positions);
  CHECK(a.mesh.quads == b.mesh.quads);
  CHECK(a.mesh.uvw == b.mesh.uvw);
}

TEST_CASE("the subdivided surface of a branch has the skeleton's radius", "[mesh]") {
  const Skeleton s = grow(cylinderSpecies(), 1);
  const double r = s.nodes[0].radius;
  const TreeMesh tree = buildTreeMesh(s);
  const LimitSurface limit(tree.mesh);
  double lo = 1e9, hi = 0;
  for (std::size_t f = 0; f < tree.mesh.quads.size(); ++f) {
    const glm::dvec3 c(tree.mesh.positions[tree.mesh.quads[f][0]]);
    if (c.z < 2.0 || c.z > 7.0) continue;  // away from the capped ends
    for (double u : {0.0, 0.25, 0.5}) {
      const glm::dvec3 p = limit.position(static_cast<int>(f), u, 0.5);
      const double d = std::hypot(p.x, p.y);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  CHECK(lo > 0.97 * r);
  CHECK(hi < 1.03 * r);
}

TEST_CASE("an open base leaves exactly the base ring open", "[mesh]") {
  MeshOptions options;
  options.openBase = true;
  const TreeMesh tree = buildTreeMesh(grow(test::loadPreset("palm"), 1), options);
  const MeshTopologyReport r = checkTopology(tree.mesh);
  CHECK(tree.mesh.openBoundary.size() == 4);
  CHECK(r.boundaryEdges == 4);
  CHECK(r.eulerCharacteristic == 1);
  CHECK(r.components == 1);
}

TEST_CASE("mesh levels leave the deeper stems out and the mesh closed", "[mesh]") {
  MeshOptions options;
  options.levels = 2;
  const Skeleton s = grow(test::loadPreset("black-tupelo"), 1);
  const TreeMesh tree = buildTreeMesh(s, options);
  for (int stem : tree.quadStem) {
    if (stem >= 0) CHECK(s.stems[static_cast<std::size_t>(stem)].level < 2);
  }
  const MeshTopologyReport r = checkTopology(tree.mesh);
  CHECK(r.boundaryEdges == 0);
  CHECK(r.eulerCharacteristic == 2);
  // Branch points of left-out children get no cross sections: as light as the tree grown with two levels (to a
  // cross section: the extra nodes of the deeper skeleton move where a child's tube first meets its skeleton).
  const std::size_t lighter = buildTreeMesh(grow(test::loadPreset("black-tupelo"), 1, 2)).mesh.quads.size();
  CHECK(tree.mesh.quads.size() <= lighter + 8);
  CHECK(tree.mesh.quads.size() + 8 >= lighter);
}

TEST_CASE("fake-branch segments are exactly the skeleton edges the mesh leaves out, chained with their radii",
          "[mesh][impostors]") {
  const Skeleton s = grow(test::loadPreset("quaking-aspen"), 1, 3);
  const std::vector<ImpostorSegment> segments = impostorSegments(s, 2);
  std::size_t expected = 0;
  std::map<std::pair<double, double>, const SkeletonNode*> nodeAt;  // by (x, y) of its world position
  for (const SkeletonNode& node : s.nodes) {
    if (node.parent >= 0 && node.level >= 2) ++expected;
    nodeAt[{node.world.position.x, node.world.position.y}] = &node;
  }
  REQUIRE(expected > 1000);
  REQUIRE(segments.size() == expected);
  std::size_t continued = 0;
  for (const ImpostorSegment& seg : segments) {
    CHECK(seg.level == 2);
    const SkeletonNode* node = nodeAt.at({seg.to.x, seg.to.y});
    CHECK(seg.to == node->world.position);
    CHECK(seg.from == s.nodes[static_cast<std::size_t>(node->parent)].world.position);
    CHECK(seg.toRadius == node->radius);
    CHECK(seg.fromRadius == node->startRadius);
    CHECK(seg.toV >= seg.fromV);
    // Bark runs on along the stem: a segment from an impostor node starts at the v where that node's ended.
    const SkeletonNode& parent = s.nodes[static_cast<std::size_t>(node->parent)];
    if (parent.level >= 2 && parent.parent >= 0) {
      const auto previous = std::find_if(segments.begin(), segments.end(), [&](const ImpostorSegment& o) { return o.to == seg.from; });
      REQUIRE(previous != segments.end());
      CHECK(previous->toV == seg.fromV);
      ++continued;
    }
  }
  CHECK(continued > segments.size() / 2);
  // Nothing beyond the grown levels but the stubs, which are fake branches at every level.
  std::size_t stubNodes = 0;
  for (const SkeletonNode& node : s.nodes) stubNodes += node.parent >= 0 && s.stems[static_cast<std::size_t>(node.stem)].stub ? 1 : 0;
  CHECK(impostorSegments(s, 3).size() == stubNodes);
}

TEST_CASE("a tree meshed at every level still draws its stubs as fake branches", "[mesh][impostors]") {
  // The oak preset grows stubs (children too short or thin for a tube); with every level meshed, buildTree had
  // left out every fake-branch segment, so `arbor render` and the viewer drew none of them.
  const Skeleton s = grow(test::loadPreset("ca-black-oak"), 1);
  std::size_t stubNodes = 0;
  for (const SkeletonNode& node : s.nodes) stubNodes += node.parent >= 0 && node.stem >= 0 && s.stems[static_cast<std::size_t>(node.stem)].stub ? 1 : 0;
  REQUIRE(stubNodes > 0);
  // Besides the stubs, the twigs the mesh could join only far from their attachment are fake branches too.
  std::size_t fakedNodes = 0;
  for (const int c : buildTreeMesh(s).fakedStems) fakedNodes += static_cast<std::size_t>(s.stems[static_cast<std::size_t>(c)].nodeCount);
  BuildOptions options;
  options.patches = false;
  const TreeGeometry all = buildTree(s, options);
  CHECK(all.impostors.size() == stubNodes + fakedNodes);
  CHECK(all.sketch.empty());
  options.mesh.levels = s.levels;  // the same, asked for by number
  CHECK(buildTree(s, options).impostors.size() == stubNodes + fakedNodes);
  options.mesh.fakeDisplaced = false;  // every twig meshed: the stubs alone
  CHECK(buildTree(s, options).impostors.size() == stubNodes);
}

TEST_CASE("a distance limit adds cross sections until none are farther apart", "[mesh]") {
  const Skeleton s = grow(test::loadPreset("quaking-aspen"), 1);
  MeshOptions options;
  options.maxRingDistance = 1.0;
  const TreeMesh plain = buildTreeMesh(s), dense = buildTreeMesh(s, options);
  CHECK(dense.rings.size() > plain.rings.size());
  double previous = -1, gap = 0;
  glm::dvec3 at(0.0);
  for (const MeshRing& ring : dense.rings) {
    if (ring.stem != 0) continue;
    if (previous >= 0) gap = std::max(gap, glm::distance(ring.center, at));
    at = ring.center;
    previous = 1;
  }
  CHECK(gap <= 1.0 + 1e-9);
}

TEST_CASE("triangles keep the orientation of their quads", "[mesh]") {
  for (const std::string& name : test::presetNames()) {
    INFO(name);
    const TreeMesh tree = buildTreeMesh(grow(test::loadPreset(name), 1));
    const auto triangles = triangulate(tree.mesh);
    REQUIRE(triangles.size() == 2 * tree.mesh.quads.size());
    auto P = [&](std::uint32_t v) { return glm::dvec3(tree.mesh.positions[v]); };
    std::size_t folded = 0;
    for (std::size_t i = 0; i < triangles.size(); i += 2) {
      const auto& q = tree.mesh.quads[i / 2];
      for (std::size_t t = i; t < i + 2; ++t)
        for (std::uint32_t v : triangles[t]) CHECK(std::find(q.begin(), q.end(), v) != q.end());
      // Each triangle runs the quad's way round: they share one diagonal, walked in opposite directions.
      const auto& a = triangles[i];
      const auto& b = triangles[i + 1];
      const glm::dvec3 na = glm::cross(P(a[1]) - P(a[0]), P(a[2]) - P(a[0]));
      const glm::dvec3 nb = glm::cross(P(b[1]) - P(b[0]), P(b[2]) - P(b[0]));
      // A quad folded along its diagonal (its halves facing apart by more than 120 degrees) is counted.
      folded += glm::dot(na, nb) < -0.5 * glm::length(na) * glm::length(nb) ? 1 : 0;
    }
    // A handful at most (fewer than 1 in 5000), where a child's first band turns back along a bent parent.
    CHECK(folded * 5000 < tree.mesh.quads.size());
  }
}

TEST_CASE("many trunks meet in one closed hub, and every vertex keeps a level the tree has", "[mesh][trunks]") {
  // Four or more trunks share the hub's sides (sub-boxes), which belong to no stem: the hub is level 0.
  for (int trunks : {2, 5, 16, 64}) {
    SpeciesParams p = test::steadySpecies();
    p.levels = 2;
    p.stemLevels.resize(2);
    p.stemLevels[0].branches = trunks;
    p.stemLevels[0].downAngle = 30;
    p.stemLevels[0].rotate = 137.5;
    p.angleRule = AngleRule::Classic;
    INFO(trunks << " trunks");
    const TreeMesh tree = buildTreeMesh(grow(p, 1));
    const MeshTopologyReport r = checkTopology(tree.mesh);
    CHECK(r.boundaryEdges == 0);
    CHECK(r.nonManifoldEdges == 0);
    CHECK(r.components == 1);
    CHECK(r.eulerCharacteristic == 2);
    CHECK(*std::max_element(tree.mesh.level.begin(), tree.mesh.level.end()) <= 1);
    CHECK(std::count(tree.mesh.level.begin(), tree.mesh.level.end(), 0) > 8 * trunks);
  }
}

TEST_CASE("a wide hub gives each trunk its own port cell, keeping the trunks' order across and along it", "[mesh][trunks]") {
  for (std::size_t n : {6u, 19u, 49u, 120u}) {
    INFO(n << " trunks");
    std::vector<std::array<double, 2>> wanted;
    for (std::size_t i = 0; i < n; ++i) {  // a sunflower spiral, as trunks spread about a tuft
      const double r = std::sqrt(static_cast<double>(i) + 0.5), a = 2.39996 * static_cast<double>(i);
      wanted.push_back({r * std::cos(a), r * std::sin(a)});
    }
    const HubLayout layout = layOutHub(wanted);
    REQUIRE(layout.cell.size() == n);
    CHECK(static_cast<std::size_t>(layout.slots * layout.slots) >= n);
    std::set<std::array<int, 2>> used;
    for (const auto& c : layout.cell) {
      CHECK(c[0] % 2 == 1);  // odd: no two ports share a corner
      CHECK(c[1] % 2 == 1);
      CHECK(c[0] < 2 * layout.slots);
      CHECK(c[1] < 2 * layout.slots);
      used.insert(c);
    }
    CHECK(used.size() == n);
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) {
        if (wanted[a][0] < wanted[b][0]) CHECK(layout.cell[a][0] <= layout.cell[b][0]);
        if (layout.cell[a][0] == layout.cell[b][0] && wanted[a][1] < wanted[b][1]) CHECK(layout.cell[a][1] < layout.cell[b][1]);
      }
    }
  }
}

TEST_CASE("a face grid finds a face far larger than the rest from anywhere under it", "[mesh]") {
  // Three hundred small faces set the cell size; one face spans thousands of cells (a wide hub's top).
  std::vector<Box> boxes;
  for (int i = 0; i < 300; ++i) boxes.push_back(Box{Vec3(i * 0.01, 0, 0), Vec3(i * 0.01 + 0.005, 0.005, 0.005)});
  boxes.push_back(Box{Vec3(-10, -10, -1), Vec3(10, 10, 0.001)});
  FaceGrid grid;
  grid.build(boxes);
  for (const Vec3& p : {Vec3(-9.5, -9.5, 0), Vec3(0.5, 0.5, 0), Vec3(9.5, 9.5, 0), Vec3(1.0, 0.001, 0.001)}) {
    INFO(p.x << ", " << p.y);
    const std::vector<std::uint32_t>& found = grid.candidates(Box{p, p + Vec3(0.001)});
    CHECK(std::count(found.begin(), found.end(), 300u) == 1);
    CHECK(std::is_sorted(found.begin(), found.end()));
  }
  const std::vector<std::uint32_t>& some = grid.candidates(Box{Vec3(0.1, 0, 0), Vec3(0.12, 0.001, 0.001)});
  CHECK(some == std::vector<std::uint32_t>{10, 11, 12, 300});  // 12 touches the query at x = 0.12
}

TEST_CASE("two necks from a hub that would cross are given each other's port cells, or free ones", "[mesh][trunks]") {
  // Ports in a unit grid; trunk 0 leaves the left cell for a skeleton on the right, trunk 1 the other way round.
  HubLayout layout;
  layout.slots = 2;
  layout.cell = {{1, 1}, {3, 1}};
  const std::vector<Vec3> ends = {Vec3(3.0, 1.5, 20.0), Vec3(2.0, 1.5, 20.0)};
  const std::vector<double> reach = {0.3, 0.3};
  std::vector<std::vector<Vec3>> tubes;
  for (const Vec3& e : ends) tubes.push_back({e, e + Vec3(0.0, 0.0, 20.0)});
  auto neck = [&](std::size_t t, const std::array<int, 2>& c) {
    return hubNeck(Vec3(c[0] + 0.5, c[1] + 0.5, 0.0), Vec3(0, 0, 1), ends[t], Vec3(0, 0, 1), 0.2);
  };
  auto closest = [&] {
    const HubNeck a = neck(0, layout.cell[0]), b = neck(1, layout.cell[1]);
    double d = 1e300;
    for (int i = 0; i < a.steps; ++i) {
      for (int j = 0; j < b.steps; ++j) {
        d = std::min(d, segmentDistance(a.at(static_cast<double>(i) / a.steps), a.at(static_cast<double>(i + 1) / a.steps),
                                        b.at(static_cast<double>(j) / b.steps), b.at(static_cast<double>(j + 1) / b.steps)));
      }
    }
    return d;
  };
  REQUIRE(closest() < 0.1);  // they cross
  untangleHub(layout, neck, reach, tubes);
  CHECK(layout.cell[0] != layout.cell[1]);
  for (const auto& c : layout.cell) {
    CHECK(c[0] % 2 == 1);
    CHECK(c[1] % 2 == 1);
    CHECK(c[0] < 2 * layout.slots);
    CHECK(c[1] < 2 * layout.slots);
  }
  CHECK(closest() >= reach[0] + reach[1]);
  // Necks already clear of each other stay where the grid put them.
  const HubLayout settled = layout;
  untangleHub(layout, neck, reach, tubes);
  CHECK(layout.cell == settled.cell);
}

TEST_CASE("a limb whose children leave through its long neck: the neck bows as its skeleton does", "[mesh][self-intersection][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // Mesh-made pairs, seeds 1-3, plus a tenth. A straight neck ran up to four radii off a shallow limb's curved
  // skeleton, across the limbs beside it: the aspen file 346, the cottonwood 67; bowed (never towards the parent's
  // axis), 291 and 25; then with a slab's first cross section kept ahead of the collar, 291 and 20; with a child
  // clear of its parent once past the parent's tip (the aspen's top limbs ran up beside the trunk's line), 56 and 26;
  // with a thick shallow child back on its skeleton right after its collar, 56 and 14.
  struct Measured {
    const char* file;
    std::size_t meshMade;
  };
  for (const Measured& m : {Measured{"quaking_aspen", 56}, Measured{"eastern_cottonwood", 14}}) {
    INFO(m.file);
    std::size_t meshMade = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const Skeleton s = growSpeciesFile(m.file, seed);
      meshMade += checkSelfIntersections(buildTreeMesh(s), s).meshMade;
    }
    INFO(meshMade << " mesh-made pairs");
    CHECK(meshMade * 10 <= m.meshMade * 11 + 5);
  }
}

TEST_CASE("a slab squeezed against the tube's start takes the collar as its first cross section where its band would fold", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // The sassafras file at seed 2: a limb's collar stands 3.5 of its radii off its skeleton, and its first slab
  // (a child attached before the tube begins) is 0.025 m long against a cross section 0.07 m wide: the long first
  // band arrived sideways and the slab's band folded back over it.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    const Skeleton s = growSpeciesFile("sassafras", seed);
    CHECK(checkSelfIntersections(buildTreeMesh(s), s).folds == 0);
  }
}

TEST_CASE("a steep child's cross section right after its collar is left out where the two first bands would cross", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // The fan palm file at seed 2: a frond's collar stands half a metre from where its tube is back on its
  // skeleton, and the band between them twisted into the next one (a fold, 2 mesh-made pairs with it).
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    const Skeleton s = growSpeciesFile("fanpalm", seed);
    const SelfIntersectionReport r = checkSelfIntersections(buildTreeMesh(s), s);
    CHECK(r.folds == 0);
    if (seed == 2) CHECK(r.meshMade == 0);
  }
}

TEST_CASE("a child's collar is one from which its tube clears the parent before the stem ends, where one is near", "[mesh][self-intersection][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // The larch file at seed 2: a twig 0.17 m long hooks down off its limb; from the first collar tried, its band
  // cleared the limb only at the twig's tip, and that one band ran back through the limb (6 neck crossings). The
  // cottonwood file at seed 2: a limb's tube began only at its tip, and its one 7.6 m band from the collar crossed
  // a neighbour's twigs (12 mesh-made pairs).
  const Skeleton larch = growSpeciesFile("european_larch", 2);
  CHECK(checkSelfIntersections(buildTreeMesh(larch), larch).neckCrossings == 0);
  const Skeleton cottonwood = growSpeciesFile("eastern_cottonwood", 2);
  CHECK(checkSelfIntersections(buildTreeMesh(cottonwood), cottonwood).meshMade == 0);
}

TEST_CASE("no Arbaro species file folds at seeds 1-3, split clones a few degrees apart included", "[mesh][self-intersection][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // Issue 13's floor. The last three folds were split clones leaving within 5 degrees of each other through ports
  // that share an edge (the willow file's trunk clones at seeds 1 and 3, the desert bush file's at seed 3): the
  // second clone's collar, leaning along its direction, folded over the first one's band there.
  for (const std::string& file : files) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      INFO(file << " seed " << seed);
      const Skeleton s = grow(loadSpeciesFile(file), seed);
      CHECK(checkSelfIntersections(buildTreeMesh(s), s).folds == 0);
    }
  }
}

TEST_CASE("a limb running up past its parent's tip begins its tube there, not where it leaves the parent's line", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // The aspen file's top limbs curve up beside the trunk's line past its blunt tip: measured against that line, 5
  // at seeds 1-3 began their tube (and ended their long first band) past half their length, one at 2.18 of 2.50.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    const Skeleton s = growSpeciesFile("quaking_aspen", seed);
    const TreeMesh tree = buildTreeMesh(s);
    std::vector<double> tubeStart(s.stems.size(), -1.0);
    for (const MeshRing& ring : tree.rings) {
      if (ring.stem >= 0 && ring.arc >= 0.0 && tubeStart[static_cast<std::size_t>(ring.stem)] < 0.0) tubeStart[static_cast<std::size_t>(ring.stem)] = ring.arc;
    }
    std::size_t children = 0;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      if (s.stems[i].parentStem < 0 || tubeStart[i] < 0.0) continue;
      ++children;
      INFO("stem " << i);
      CHECK(tubeStart[i] <= 0.5 * StemPolyline(s, static_cast<int>(i)).length());
    }
    CHECK(children > 1000);
  }
}

TEST_CASE("a meshed twig never passes through a neighbouring stem's joint: those twigs are fake branches", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // A twig of one branch passing the joint of the next, within two of that stem's radii of its axis (where its collar
  // stands) plus its own: the collar's neck cut it. Sassafras at seeds 1-3 had 109 mesh-made pairs and 2,382 neck
  // crossings with such twigs meshed, 56 and 868 without.
  const double lc = MeshOptions{}.limitCompensation;
  std::size_t meshMade = 0, necks = 0, passing = 0, through = 0;
  std::string first;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Skeleton s = growSpeciesFile("sassafras", seed);
    const TreeMesh tree = buildTreeMesh(s);
    const std::set<int> faked(tree.fakedStems.begin(), tree.fakedStems.end());
    const std::vector<bool> bears = bearingStems(s);
    std::vector<std::vector<int>> children(s.stems.size());  // meshed ones
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.parentStem >= 0 && st.cloneOf < 0 && !st.stub && !faked.count(static_cast<int>(i))) children[static_cast<std::size_t>(st.parentStem)].push_back(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.level < 2 || st.cloneOf >= 0 || st.stub || bears[i] || faked.count(static_cast<int>(i))) continue;
      std::vector<int> around = children[static_cast<std::size_t>(st.parentStem)];
      const int grand = s.stems[static_cast<std::size_t>(st.parentStem)].parentStem;
      if (grand >= 0) around.insert(around.end(), children[static_cast<std::size_t>(grand)].begin(), children[static_cast<std::size_t>(grand)].end());
      const StemPolyline own(s, static_cast<int>(i));
      const double from = std::min(parentClearance(s, static_cast<int>(i)), own.length());
      for (int c : around) {
        if (c == static_cast<int>(i) || c == st.parentStem) continue;
        const StemPolyline other(s, c);
        const Vec3 a = s.nodes[static_cast<std::size_t>(s.stems[static_cast<std::size_t>(c)].attachNode)].world.position;
        const Vec3 b = other.position(std::min(parentClearance(s, c), other.length()));
        const double reach = (2.0 * s.stems[static_cast<std::size_t>(c)].startRadius + st.startRadius) * lc;
        double nearest = 1e300;
        Vec3 prev = own.position(from);
        for (int k = 0; k < own.pointCount(); ++k) {
          if (own.arcLength(k) <= from) continue;
          const Vec3 next = own.position(own.arcLength(k));
          nearest = std::min(nearest, segmentDistance(prev, next, a, b));
          prev = next;
        }
        ++passing;
        if (nearest < 0.999 * reach && through++ == 0) first = "seed " + std::to_string(seed) + ", twig " + std::to_string(i) + " by stem " + std::to_string(c);
      }
    }
    const SelfIntersectionReport r = checkSelfIntersections(tree, s);
    meshMade += r.meshMade;
    necks += r.neckCrossings;
  }
  CHECK(passing > 1000);
  INFO("first twig through a joint: " << first);
  CHECK(through == 0);
  INFO(meshMade << " mesh-made pairs, " << necks << " neck crossings");
  CHECK(meshMade * 10 <= 56 * 11 + 5);
  CHECK(necks * 10 <= 868 * 11);
}

TEST_CASE("a grass's stalks leave a wide hub and meet their skeletons at one level, their necks side by side", "[mesh][trunks][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // Mesh-made pairs between stalks (or a stalk and the hub), seeds 1-3: with the box hub and its sub-boxes 2,392
  // (wheat), 294 (barley), 307 (rush); with the grid hub's cells as laid out 44, 8 and 2; untangled (untangleHub)
  // 18, 0 and 3; none once two near-parallel stalks' wood counted as overlapping along its length (it had counted
  // only around one closest point, at the root: two stalks whose skeletons coincide for 6 cm made mesh-made pairs
  // between their necks).
  struct Measured {
    const char* file;
    std::size_t pairs;
  };
  for (const Measured& m : {Measured{"wheat", 0}, Measured{"barley", 0}, Measured{"rush", 0}}) {
    INFO(m.file);
    std::size_t pairs = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const Skeleton s = growSpeciesFile(m.file, seed);
      const TreeMesh tree = buildTreeMesh(s);
      const MeshTopologyReport r = checkTopology(tree.mesh);
      CHECK(r.boundaryEdges == 0);
      CHECK(r.nonManifoldEdges == 0);
      CHECK(r.components == 1);
      // Every stalk's first cross section on its skeleton stands at the same height: where the necks end.
      std::vector<double> levels;
      std::vector<bool> seen(s.stems.size(), false);
      for (const MeshRing& ring : tree.rings) {
        if (ring.stem < 0 || ring.arc < 0.0 || seen[static_cast<std::size_t>(ring.stem)]) continue;
        seen[static_cast<std::size_t>(ring.stem)] = true;
        if (s.stems[static_cast<std::size_t>(ring.stem)].attachNode == 0) levels.push_back(ring.center.z - s.nodes[0].world.position.z);
      }
      REQUIRE(levels.size() > 5);
      const auto [lo, hi] = std::minmax_element(levels.begin(), levels.end());
      CHECK(*lo > 0.0);
      CHECK(*hi - *lo < 1e-6 * *hi);
      for (const QuadPairHit& h : checkSelfIntersections(tree, s).hits) {
        const bool stalks = h.relation == StemRelation::Hub || (h.relation == StemRelation::Siblings && s.stems[static_cast<std::size_t>(h.stemA)].level == 0);
        pairs += h.origin == PairOrigin::Mesh && stalks ? 1 : 0;
      }
    }
    INFO(pairs << " mesh-made pairs between stalks");
    CHECK(pairs <= m.pairs);
  }
}

TEST_CASE("a limb fused along its trunk up to its split leaves from one box clear of the trunk", "[mesh][joints][real-data]") {
  if (test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR).empty()) return;  // arbaroSpeciesFiles said why
  // The willow file's limbs leave their trunk clones at 12-23 degrees and split before their wood clears the trunk.
  // Their mesh-made pairs against themselves or their own trunk at seeds 2-3 were 52 (the tube's first cross section
  // and split slab squeezed beside the collar, or a metre-long neck ending inside the trunk's corners); now none.
  std::size_t fused = 0, pairs = 0;
  for (std::uint64_t seed = 2; seed <= 3; ++seed) {
    const Skeleton s = growSpeciesFile("weeping_willow", seed);
    std::set<int> limbs;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.parentStem < 0 || st.cloneOf >= 0 || st.nodeCount < 2) continue;
      const SkeletonNode& end = s.nodes[static_cast<std::size_t>(st.firstNode + st.nodeCount - 1)];
      if (end.kind != NodeKind::Split) continue;
      // Fused: the split lies within the reach of the parent's corners and its own (1.52 radii each).
      const SkeletonStem& parent = s.stems[static_cast<std::size_t>(st.parentStem)];
      for (int n = parent.firstNode; n + 1 < parent.firstNode + parent.nodeCount; ++n) {
        const SkeletonNode& a = s.nodes[static_cast<std::size_t>(n)];
        const SkeletonNode& b = s.nodes[static_cast<std::size_t>(n + 1)];
        const Vec3 ab = b.world.position - a.world.position;
        const double t = std::clamp(glm::dot(end.world.position - a.world.position, ab) / std::max(glm::dot(ab, ab), 1e-30), 0.0, 1.0);
        if (glm::distance(end.world.position, a.world.position + t * ab) < 1.52 * (a.radius + st.startRadius)) {
          limbs.insert(static_cast<int>(i));
          break;
        }
      }
    }
    fused += limbs.size();
    const TreeMesh tree = buildTreeMesh(s);
    const MeshTopologyReport r = checkTopology(tree.mesh);
    CHECK(r.boundaryEdges == 0);
    CHECK(r.nonManifoldEdges == 0);
    CHECK(r.components == 1);
    for (const QuadPairHit& h : checkSelfIntersections(tree, s).hits) {
      if (h.origin != PairOrigin::Mesh) continue;
      for (const auto& [x, y] : {std::pair{h.stemA, h.stemB}, std::pair{h.stemB, h.stemA}}) {
        if (limbs.contains(x) && (y == x || y == s.stems[static_cast<std::size_t>(x)].parentStem)) ++pairs;
      }
    }
  }
  CHECK(fused >= 4);
  CHECK(pairs == 0);
}

TEST_CASE("a mesh past its quad limit is refused before it is built, naming what to change", "[mesh][limits]") {
  const Skeleton s = grow(test::loadPreset("palm"), 1);
  MeshOptions tight;
  tight.maxQuads = 500;
  CHECK_THROWS_WITH(buildTreeMesh(s, tight), Catch::Contains("more than 500 quads") && Catch::Contains("lower Levels"));
  MeshOptions dense;
  dense.maxRingDistance = 1e-4;  // millions of cross sections on the trunk alone
  CHECK_THROWS_WITH(buildTreeMesh(s, dense), Catch::Contains("extra cross sections") && Catch::Contains("further apart"));
  MeshOptions absurd;
  absurd.ringSpacing = 1e-300;  // would overflow an int of cross sections
  CHECK_THROWS_AS(buildTreeMesh(s, absurd), LimitError);
}

TEST_CASE("a tree's sketch runs joint to joint along every stem but the twigs, with far fewer segments", "[mesh][impostors]") {
  const Skeleton s = grow(test::loadPreset("black-tupelo"), 1);
  const std::vector<ImpostorSegment> fine = impostorSegments(s, 2);
  const std::vector<ImpostorSegment> sketch = sketchSegments(s, 2, s.levels - 1);
  std::size_t stems = 0, joints = 0;
  for (const SkeletonStem& st : s.stems) {
    if (st.level != 2) continue;
    ++stems;
    for (int n = st.firstNode; n < st.firstNode + st.nodeCount - 1; ++n) joints += s.nodes[static_cast<std::size_t>(n)].kind == NodeKind::Joint ? 1 : 0;
  }
  CHECK(sketch.size() == stems + joints);  // one segment up to each joint and one to the tip
  CHECK(sketch.size() * 3 < fine.size());  // the tupelo: 9,990 against 37,374
  for (const ImpostorSegment& g : sketch) CHECK(g.level == 2);
  for (std::size_t i = 1; i < sketch.size(); ++i) {
    // Within a stem each segment starts where the one before ended, and its bark runs on.
    if (sketch[i].fromV > 0.0) {
      CHECK(glm::distance(sketch[i].from, sketch[i - 1].to) < 1e-12);
      CHECK(sketch[i].fromV == sketch[i - 1].toV);
    }
  }
}

TEST_CASE("every Arbaro species file grows and meshes to one closed piece with valid levels", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  for (const std::string& file : files) {
    INFO(file);
    const SpeciesParams p = loadSpeciesFile(file);
    const Skeleton s = grow(p, 1);
    const TreeMesh tree = buildTreeMesh(s);
    const MeshTopologyReport r = checkTopology(tree.mesh);
    CHECK(r.boundaryEdges == 0);
    CHECK(r.nonManifoldEdges == 0);
    CHECK(r.components == 1);
    CHECK(*std::max_element(tree.mesh.level.begin(), tree.mesh.level.end()) < s.levels);  // wheat's _LEVEL held 232
  }
  CHECK(files.size() == 16);
}

TEST_CASE("a child running on along its parent from the parent's last slab leaves through the slab's top", "[mesh]") {
  // The palm's crown fronds attach just below its trunk's tip; the most upright one leaves through the top of the
  // trunk's last slab, whose ring is then the trunk's last: no tip ring and cap of the trunk's own past it.
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    const Skeleton s = grow(test::loadPreset("palm"), seed);
    const TreeMesh tree = buildTreeMesh(s);
    const MeshRing* last = nullptr;
    for (const MeshRing& r : tree.rings)
      if (r.stem == 0 && r.arc >= 0.0 && (!last || r.arc > last->arc)) last = &r;
    REQUIRE(last);
    CHECK(last->arc < StemPolyline(s, 0).length());  // the trunk ends before its skeleton's tip
    std::map<int, std::set<std::uint32_t>> used;  // per stem but the trunk: which of the ring's corners its quads use
    for (std::size_t q = 0; q < tree.mesh.quads.size(); ++q)
      for (std::uint32_t v : tree.mesh.quads[q])
        if (tree.quadStem[q] != 0 && std::find(last->vertices.begin(), last->vertices.end(), v) != last->vertices.end()) used[tree.quadStem[q]].insert(v);
    std::set<int> users;
    for (const auto& [stem, corners] : used)
      if (corners.size() == 4) users.insert(stem);
    REQUIRE(users.size() == 1);  // one frond's quads join the whole ring: it leaves through it (others share a side's corners)
    const SkeletonStem& frond = s.stems[static_cast<std::size_t>(*users.begin())];
    CHECK(frond.parentStem == 0);
    CHECK(glm::dot(StemPolyline(s, *users.begin()).startDirection(), StemPolyline(s, 0).endDirection()) >= 0.9);
  }
}

TEST_CASE("a short stem's split slab moves on until the band to it runs forwards, not back through the stem's neck", "[mesh][real-data]") {
  // The larch file's twigs that split right at their parent's surface: their collar cross section lies up to
  // three radii off the skeleton, and a split slab that stopped looking after two radii fell back behind it.
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  const Skeleton s = growSpeciesFile("european_larch", 2);
  const TreeMesh tree = buildTreeMesh(s);
  // Per stem, its last cross section on the skeleton and the one before it; a split stem's is its split slab's.
  std::vector<int> lastOn(s.stems.size(), -1), before(s.stems.size(), -1);
  for (std::size_t r = 0; r < tree.rings.size(); ++r) {
    const int stem = tree.rings[r].stem;
    if (stem < 0 || tree.rings[r].arc < 0.0 || r == 0 || tree.rings[r - 1].stem != stem) continue;
    lastOn[static_cast<std::size_t>(stem)] = static_cast<int>(r);
    before[static_cast<std::size_t>(stem)] = static_cast<int>(r) - 1;
  }
  std::size_t splits = 0, backwards = 0;
  for (std::size_t i = 0; i < s.stems.size(); ++i) {
    const SkeletonStem& st = s.stems[i];
    if (st.nodeCount == 0 || lastOn[i] < 0) continue;
    if (s.nodes[static_cast<std::size_t>(st.firstNode + st.nodeCount - 1)].kind != NodeKind::Split) continue;
    ++splits;
    backwards += test::bandRunsForwards(tree, tree.rings[static_cast<std::size_t>(before[i])], tree.rings[static_cast<std::size_t>(lastOn[i])]) ? 0 : 1;
  }
  INFO(backwards << " of " << splits << " split stems' last bands run backwards");
  CHECK(splits > 500);  // 949: the twigs that split before clearing their parent, and their clones, are fake branches
  // 217 of 2,050 when the slab stopped after two radii; then 108 (twigs piled on their parent's first slab, the
  // collar far along the parent, where no point on the skeleton lies ahead of it); none since those are faked.
  CHECK(backwards == 0);
}

// The distance from p to a stem's skeleton (its attach node, then its own nodes), and the stem's radius there.
std::pair<double, double> distanceToStem(const Skeleton& s, int stem, const glm::dvec3& p) {
  const SkeletonStem& st = s.stems[static_cast<std::size_t>(stem)];
  std::pair<double, double> best{1e300, 0.0};
  int previous = st.attachNode;
  for (int n = st.firstNode; n < st.firstNode + st.nodeCount; previous = n++) {
    const SkeletonNode& a = s.nodes[static_cast<std::size_t>(previous)];
    const SkeletonNode& b = s.nodes[static_cast<std::size_t>(n)];
    const glm::dvec3 d = b.world.position - a.world.position;
    const double t = glm::dot(d, d) > 0.0 ? std::clamp(glm::dot(p - a.world.position, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
    const double distance = glm::length(a.world.position + t * d - p);
    if (distance < best.first) best = {distance, b.startRadius + t * (b.radius - b.startRadius)};
  }
  return best;
}

TEST_CASE("twigs shallow and thin along their parent, just before its split or inside a sibling clone past it, are fake branches unless every stem is meshed", "[mesh][real-data]") {
  const std::vector<std::string> files = test::arbaroSpeciesFiles(ARBOR_SPECIES_DIR);
  if (files.empty()) return;  // arbaroSpeciesFiles said why
  // Barley's awns leave their stalks at a few degrees; the CA black oak's twigs crowd its many splits, the desert
  // bush's sit on clones still inside each other.
  std::size_t insideSibling = 0;
  for (const char* name : {"barley", "ca_black_oak", "desert_bush"}) {
    INFO(name);
    const Skeleton s = growSpeciesFile(name, 1);
    const TreeMesh tree = buildTreeMesh(s);
    const std::set<int> faked(tree.fakedStems.begin(), tree.fakedStems.end());
    const std::vector<bool> bears = bearingStems(s);
    std::size_t shallow = 0, beforeSplit = 0;
    for (std::size_t i = 0; i < s.stems.size(); ++i) {
      const SkeletonStem& st = s.stems[i];
      if (st.parentStem < 0 || st.cloneOf >= 0 || st.stub || bears[i]) continue;
      const SkeletonNode& at = s.nodes[static_cast<std::size_t>(st.attachNode)];
      bool split = false;
      for (const SkeletonStem& c : s.stems) {
        if (c.cloneOf != st.parentStem || c.stub) continue;
        const double ahead = s.nodes[static_cast<std::size_t>(c.attachNode)].offset - at.offset;
        split = split || (ahead >= 0.0 && ahead <= 4.0 * at.radius);
      }
      const bool thinShallow = parentClearance(s, static_cast<int>(i)) >= 6.0 * at.radius && st.startRadius <= 0.5 * at.radius;
      // Past the split: the parent is a clone, and another clone of its source is nearer than the two cages reach.
      bool inside = false;
      const SkeletonStem& parent = s.stems[static_cast<std::size_t>(st.parentStem)];
      for (std::size_t c = 0; c < s.stems.size() && parent.cloneOf >= 0; ++c) {
        if (static_cast<int>(c) == st.parentStem || s.stems[c].cloneOf != parent.cloneOf || s.stems[c].stub) continue;
        const auto [distance, radius] = distanceToStem(s, static_cast<int>(c), at.world.position);
        inside = inside || distance < 0.999 * (radius + at.radius) * MeshOptions{}.limitCompensation;
      }
      shallow += thinShallow ? 1 : 0;
      beforeSplit += split ? 1 : 0;
      insideSibling += inside ? 1 : 0;
      if (thinShallow || split || inside) CHECK(faked.count(static_cast<int>(i)) == 1);
    }
    CHECK(shallow + beforeSplit > 20);
    MeshOptions all;
    all.fakeDisplaced = false;
    const TreeMesh meshed = buildTreeMesh(s, all);
    CHECK(meshed.fakedStems.empty());
    const MeshTopologyReport r = checkTopology(meshed.mesh);
    CHECK((r.boundaryEdges == 0 && r.nonManifoldEdges == 0 && r.components == 1));
  }
  CHECK(insideSibling > 10);
}
