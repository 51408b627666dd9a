// Patches: a quad and its counter-clockwise 1-ring, at most 32 points, read back exactly as the shader
// reads them; regular patches are bicubic B-splines equal to OpenSubdiv's exact Catmull-Clark limit.
#include <catch2/catch.hpp>
#include <algorithm>

#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/osd_topology.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/limit_reference.hpp"
#include "patches/patch_set.hpp"
#include "mesh_support.hpp"
#include "test_support.hpp"

using namespace arbor;
using test::meshOf;

namespace {

// The ring of vertex c counter-clockwise from outside, starting at `from`, found from the faces alone.
std::vector<std::uint32_t> independentRing(const QuadMesh& mesh, std::uint32_t c, std::uint32_t from) {
  std::vector<std::uint32_t> ring;
  std::uint32_t edge = from;
  for (int guard = 0; guard < 64; ++guard) {
    bool found = false;
    for (const auto& q : mesh.quads) {
      for (int k = 0; k < 4; ++k) {
        // The face whose corner c is followed by `edge` continues the fan counter-clockwise.
        if (q[static_cast<std::size_t>(k)] == c && q[static_cast<std::size_t>((k + 1) % 4)] == edge) {
          ring.push_back(edge);
          ring.push_back(q[static_cast<std::size_t>((k + 2) % 4)]);
          edge = q[static_cast<std::size_t>((k + 3) % 4)];
          found = true;
          break;
        }
      }
      if (found) break;
    }
    if (!found || edge == from) break;
  }
  return ring;
}

}  // namespace

TEST_CASE("every preset's patches hold at most 32 points and none falls back", "[patches]") {
  for (const std::string& name : test::presetNames()) {
    INFO(name);
    const TreeMesh tree = meshOf(name);
    const PatchSet set = buildPatches(tree.mesh);
    REQUIRE(set.size() == tree.mesh.quads.size());
    for (std::size_t p = 0; p < set.size(); ++p) {
      const auto& n = set.valence[p];
      CHECK(set.kind[p] != PatchKind::Fallback);
      CHECK(set.pointCount(p) <= static_cast<std::size_t>(kMaxPatchPoints));
      CHECK(set.pointCount(p) == static_cast<std::size_t>(2 * (n[0] + n[1] + n[2] + n[3]) - 16));
      CHECK(std::equal(tree.mesh.quads[p].begin(), tree.mesh.quads[p].end(), set.pointsOf(p)));
      const bool regular = n[0] == 4 && n[1] == 4 && n[2] == 4 && n[3] == 4;
      CHECK((set.kind[p] == PatchKind::Regular) == regular);
    }
  }
}

TEST_CASE("corner rings read from the layout are the counter-clockwise 1-rings of the mesh", "[patches]") {
  const TreeMesh tree = meshOf("palm");
  const PatchSet set = buildPatches(tree.mesh);
  std::size_t checked = 0, extraordinary = 0;
  for (std::size_t p = 0; p < set.size(); p += 3) {
    for (int i = 0; i < 4; ++i) {
      const auto& q = tree.mesh.quads[p];
      const auto ring = cornerRing(set, p, i);
      CHECK(ring.size() == 2u * set.valence[p][static_cast<std::size_t>(i)]);
      CHECK(ring == independentRing(tree.mesh, q[static_cast<std::size_t>(i)], q[static_cast<std::size_t>((i + 1) % 4)]));
      ++checked;
    }
    extraordinary += set.kind[p] == PatchKind::Extraordinary ? 1 : 0;
  }
  CHECK(checked > 1000);
  CHECK(extraordinary > 50);
}

TEST_CASE("OpenSubdiv accepts every preset's mesh without a diagnostic", "[patches][opensubdiv]") {
  for (const std::string& name : test::presetNames()) {
    INFO(name);
    CHECK_NOTHROW(makeTopologyRefiner(meshOf(name, 2, 3).mesh, "test"));
  }
}

TEST_CASE("regular patches are OpenSubdiv's exact limit surface", "[patches][opensubdiv]") {
  for (const char* name : {"quaking-aspen", "palm", "lombardy-poplar"}) {
    INFO(name);
    const TreeMesh tree = meshOf(name);
    const PatchSet set = buildPatches(tree.mesh);
    const LimitSurface limit(tree.mesh);
    double worst = 0.0;
    std::size_t tested = 0;
    for (std::size_t p = 0; p < set.size() && tested < 400; p += 5) {
      if (set.kind[p] != PatchKind::Regular) continue;
      const auto indices = regularGrid(set, p);
      std::array<glm::dvec3, 16> grid;
      for (std::size_t k = 0; k < 16; ++k) grid[k] = glm::dvec3(tree.mesh.positions[indices[k]]);
      const double radius = std::max(1e-6f, tree.mesh.radius[tree.mesh.quads[p][0]]);
      for (double u : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        for (double v : {0.0, 0.4, 1.0}) {
          const glm::dvec3 a = evaluateBSpline(grid, u, v), b = limit.position(static_cast<int>(p), u, v);
          worst = std::max(worst, glm::distance(a, b) / radius);
        }
      }
      ++tested;
    }
    CHECK(tested > 50);
    CHECK(worst < 1e-5);
  }
}

TEST_CASE("patches next to an open base fall back instead of being dropped", "[patches]") {
  MeshOptions options;
  options.openBase = true;
  GrowthOptions o;
  const TreeMesh tree = buildTreeMesh(generateSkeleton(test::loadPreset("palm"), o), options);
  const PatchSet set = buildPatches(tree.mesh);
  REQUIRE(set.size() == tree.mesh.quads.size());
  const auto fallback = std::count(set.kind.begin(), set.kind.end(), PatchKind::Fallback);
  CHECK(fallback == 4);  // the band above the open ring
  for (std::size_t p = 0; p < set.size(); ++p) {
    if (set.kind[p] == PatchKind::Fallback) CHECK(set.pointCount(p) == 4);
  }
}
