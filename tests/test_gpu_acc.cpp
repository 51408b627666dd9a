// The GPU's ACC against the CPU reference and OpenSubdiv: the evaluation stage writes the points it
// evaluates (before displacement) into a buffer; each is compared with the same (u, v) on the CPU.
#include <catch2/catch.hpp>
#include <algorithm>

#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/tree_mesh.hpp"
#include "patches/acc.hpp"
#include "patches/limit_reference.hpp"
#include "mesh_support.hpp"
#include "render_support.hpp"
#include "test_support.hpp"

using namespace arbor;

TEST_CASE("the tessellation shaders evaluate the ACC patches of the CPU reference", "[render][acc]") {
  REQUIRE(test::vulkan().features().vertexPipelineStoresAndAtomics);
  const TreeMesh tree = test::meshOf("quaking-aspen", 1, 2);
  const PatchSet patches = buildPatches(tree.mesh);
  render::RenderSession session(test::vulkan(), 96, 96, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(tree.mesh, patches);
  const float level = 3.0f;
  const auto perPatch = static_cast<std::uint32_t>((level + 1) * (level + 1));
  session.renderer().setCapture(perPatch * static_cast<std::uint32_t>(patches.size()));
  render::RenderSettings settings;
  settings.tessLevel = level;
  settings.cull = false;  // every patch, seen or not
  const std::uint32_t errorsBefore = test::vulkan().validationErrors();
  session.render(render::frameBounds(render::plantedBounds(*session.tree()), 0.0f, 0.0f, 1.0f), settings);
  CHECK(test::vulkan().validationErrors() == errorsBefore);

  const auto points = session.renderer().captured();
  // Lavapipe may evaluate shared domain vertices more than once; at least every distinct (u, v) arrives.
  REQUIRE(points.size() >= perPatch * patches.size());
  const LimitSurface limit(tree.mesh);
  double worstCpu = 0.0, worstRegular = 0.0;
  std::size_t regularSamples = 0;
  std::vector<std::array<glm::dvec3, 16>> geometry(patches.size());
  std::vector<bool> built(patches.size(), false);
  for (std::size_t i = 0; i < points.size(); i += 7) {
    const render::CapturedPoint& c = points[i];
    REQUIRE(c.patch < patches.size());
    if (!built[c.patch]) {
      geometry[c.patch] = buildAccPatch(tree.mesh, patches, c.patch).geometry;
      built[c.patch] = true;
    }
    const double radius = std::max(1e-4, static_cast<double>(tree.mesh.radius[tree.mesh.quads[c.patch][0]]));
    const glm::dvec3 gpu(c.position);
    const glm::dvec3 cpu = evaluateBezier(geometry[c.patch], c.u, c.v);
    // Single precision: a few ulp of the coordinates, measured against the branch radius.
    const double tolerance = 1e-5 * radius + 4e-7 * glm::length(cpu);
    worstCpu = std::max(worstCpu, glm::distance(gpu, cpu) / tolerance);
    if (patches.kind[c.patch] == PatchKind::Regular && regularSamples < 3000) {
      const glm::dvec3 exact = limit.position(static_cast<int>(c.patch), c.u, c.v);
      worstRegular = std::max(worstRegular, glm::distance(gpu, exact) / tolerance);
      ++regularSamples;
    }
  }
  CHECK(worstCpu <= 1.0);      // the GPU patch is the CPU's, to float precision
  CHECK(regularSamples > 500);
  CHECK(worstRegular <= 1.0);  // and regular patches are OpenSubdiv's exact limit surface
}
