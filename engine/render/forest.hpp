#pragma once
// A forest for the walkthrough: a few distinct trees, built elsewhere (tree/forest_trees) at three levels of
// detail, uploaded once and instanced many times; placed without overlapping crowns; each frame the visible
// instances with the level of detail their distance asks for.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gpu_tree.hpp"
#include "renderer.hpp"
#include "tree/forest_trees.hpp"

namespace arbor::render {

// Levels of detail of each distinct tree: every stem level meshed; the deepest level as fake branches; the
// two deepest (the mesh keeps at least the trunk).
constexpr std::uint32_t kDetailLevels = 3;

// Up to `full` metres (to the crown's nearest point) the whole mesh, up to `reduced` one level faked, beyond
// two; 0 skips a tier. Beyond `far` a tree is drawn far (TreeInstance::far).
struct DetailDistances {
  float full = 40.0f, reduced = 150.0f;
  float far = 400.0f;  // beyond, the mesh is drawn without the tessellator and the fake branches as a sketch
};

struct ForestTree {
  std::string label;
  std::array<GpuTree, kDetailLevels> detail;
  float crownRadius = 0.0f;   // horizontal reach of mesh and leaves from the trunk
  Bounds bounds;              // planted, object space, with the leaves
};

struct ForestPlacement {
  std::uint32_t tree = 0;  // index into the distinct trees
  glm::vec2 position{0.0f};
  float rotation = 0.0f;   // about z, radians
};

struct ForestFrame {
  std::vector<TreeInstance> instances;   // tree index: kDetailLevels t + detail
  std::uint32_t visible = 0, culled = 0;
  std::array<std::uint32_t, kDetailLevels> perDetail{};
  std::uint32_t far = 0;
};

class Forest {
 public:
  // Uploads the distinct trees (each with kDetailLevels details) and places `instances` of them, in turn,
  // deterministically for `seed`; one instance stands unrotated at the origin.
  Forest(const vk::VulkanContext& context, const std::vector<DetailedTree>& trees, std::uint32_t instances, std::uint64_t seed);

  // For TreeRenderer::setTrees: the details of each distinct tree, in that order.
  std::vector<const GpuTree*> gpuTrees() const;
  const std::vector<ForestTree>& trees() const { return trees_; }
  const std::vector<ForestPlacement>& placements() const { return placements_; }
  float radius() const { return radius_; }  // of the planted area

  // The instances inside the view frustum, each with the detail its distance asks for.
  ForestFrame frame(const Camera& camera, float aspect, const DetailDistances& distances) const;

  // A camera that sees the whole forest (or the single tree) from the default side.
  Camera overview(float aspect) const;
  // Stops of a short tour: the overview, then (a forest) its edge and its middle at eye height, or (one
  // tree) two more sides of it.
  std::vector<Camera> tour(float aspect) const;

 private:
  std::vector<ForestTree> trees_;
  std::vector<ForestPlacement> placements_;
  float radius_ = 0.0f;
};

// Positions for `count` crowns of the given radii (one per tree kind, chosen in turn) inside a disc, no two
// crowns overlapping; deterministic for a seed. The first stands at the origin.
std::vector<ForestPlacement> placeTrees(const std::vector<float>& crownRadii, std::uint32_t count, std::uint64_t seed, float& areaRadius);

}  // namespace arbor::render
