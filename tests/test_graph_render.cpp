// A tree no Weber-Penn species makes, given as a branch graph: a whorl of six branches at one node, a branch
// running almost along the trunk (a fake branch unless every stem is meshed), one leaving backwards and a fork of
// three at a branch's end, with leaves: one closed mesh, tessellated with ACC on lavapipe, against its golden image.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "growth/graph/branch_graph.hpp"
#include "mesh/mesh_checks.hpp"
#include "render_support.hpp"
#include "tree/build_tree.hpp"

using namespace arbor;

namespace {

// A chain of `count` internodes of `step` from node `from` along `direction`, bending up by `rise` a step.
int chain(BranchGraph& g, int from, Vec3 direction, int count, double step, double rise) {
  int at = from;
  for (int k = 0; k < count; ++k) {
    direction = glm::normalize(direction + Vec3(0, 0, rise));
    BranchNode n;
    n.parent = at;
    n.position = g.nodes[static_cast<std::size_t>(at)].position + direction * step;
    g.nodes.push_back(n);
    at = static_cast<int>(g.nodes.size()) - 1;
  }
  return at;
}

void leafAt(BranchGraph& g, int node, const Vec3& direction) {
  GraphLeaf leaf;
  leaf.node = node;
  leaf.position = g.nodes[static_cast<std::size_t>(node)].position;
  leaf.direction = glm::normalize(direction);
  leaf.length = 0.6;
  leaf.width = 0.35;
  g.leaves.push_back(leaf);
}

BranchGraph whorlTree() {
  BranchGraph g;
  g.nodes.push_back(BranchNode{});  // the root, on the ground
  const int whorl = chain(g, 0, Vec3(0, 0, 1), 6, 0.5, 0.0);
  const int crown = chain(g, whorl, Vec3(0.05, 0, 1), 6, 0.4, 0.0);
  for (int k = 0; k < 6; ++k) {  // six branches leaving one node
    const double a = 2.0 * std::numbers::pi * k / 6.0;
    const int tip = chain(g, whorl, Vec3(std::cos(a), std::sin(a), 0.15), 7, 0.3, 0.06);
    for (int f = 0; f < 3; ++f) {  // each ends in a fork of three
      const double b = a + (f - 1) * 0.6;
      const int twig = chain(g, tip, Vec3(std::cos(b), std::sin(b), 0.5), 3, 0.2, 0.1);
      leafAt(g, twig, Vec3(std::cos(b), std::sin(b), 0.3));
    }
  }
  chain(g, 2, Vec3(0.12, 0.05, 1), 8, 0.3, 0.0);      // nearly along the trunk
  chain(g, crown - 2, Vec3(-0.6, 0.3, -0.7), 5, 0.25, 0.0);  // backwards, down from the crown
  return g;
}

}  // namespace

TEST_CASE("golden image: a branch graph with a whorl of six, a near-parallel and a backward branch, with leaves", "[render][graph][golden]") {
  GraphOptions options;
  options.tipRadius = 0.04;
  const Skeleton skeleton = graphToSkeleton(whorlTree(), options);
  const TreeGeometry tree = buildTree(skeleton);
  const MeshTopologyReport topology = checkTopology(tree.mesh.mesh);
  CHECK(topology.boundaryEdges == 0);
  CHECK(topology.nonManifoldEdges == 0);
  CHECK(topology.components == 1);
  // The branch along the trunk is thin and shallow, so a fake branch by default: meshed on request, it stays closed.
  CHECK(tree.mesh.fakedStems.size() == 1);
  BuildOptions meshAll;
  meshAll.mesh.fakeDisplaced = false;
  const TreeGeometry meshed = buildTree(skeleton, meshAll);
  CHECK(meshed.mesh.fakedStems.empty());
  const MeshTopologyReport all = checkTopology(meshed.mesh.mesh);
  CHECK((all.boundaryEdges == 0 && all.nonManifoldEdges == 0 && all.components == 1));
  render::RenderSession session(test::vulkan(), 240, 240, VK_SAMPLE_COUNT_1_BIT, test::textures());
  session.setTree(tree.mesh.mesh, tree.patches, skeleton.leaves, tree.impostors);
  const VkExtent2D e = session.extent();
  const render::Camera camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 12.0f, static_cast<float>(e.width) / static_cast<float>(e.height));
  render::RenderSettings settings;
  settings.mode = render::RenderMode::ACC;
  settings.tessLevel = 4.0f;
  settings.leaves = true;
  settings.impostors = true;
  session.render(camera, settings);
  const test::GoldenCheck golden = test::checkGolden("graph-whorl", session.image());
  INFO(golden.report);
  CHECK(golden.ok);
}
