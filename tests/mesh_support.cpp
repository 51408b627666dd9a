#include "mesh_support.hpp"

#include "growth/weber_penn/weber_penn.hpp"
#include "test_support.hpp"

namespace arbor::test {

TreeMesh meshOf(const std::string& preset, std::uint64_t seed, int levels) {
  GrowthOptions o;
  o.seed = seed;
  o.levels = levels;
  return buildTreeMesh(generateSkeleton(loadPreset(preset), o));
}

WindyTree windyTree(const std::string& preset, int levels, int meshLevels) {
  GrowthOptions growth;
  growth.seed = 1;
  growth.levels = levels;
  WindyTree tree;
  tree.skeleton = generateSkeleton(loadPreset(preset), growth);
  BuildOptions build;
  build.wind = true;
  build.mesh.levels = meshLevels;
  tree.geometry = buildTree(tree.skeleton, build);
  return tree;
}

}  // namespace arbor::test
