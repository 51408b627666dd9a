#include "build_tree.hpp"

namespace arbor {

TreeGeometry buildTree(const Skeleton& skeleton, const BuildOptions& options) {
  TreeGeometry g;
  const int meshLevels = options.mesh.levels > 0 ? options.mesh.levels : skeleton.levels;
  MeshOptions mesh = options.mesh;
  mesh.levels = meshLevels < skeleton.levels ? meshLevels : 0;
  g.mesh = buildTreeMesh(skeleton, mesh);
  // Stubs are fake branches at every level, also when every level is meshed (they had gone undrawn then).
  g.impostors = leftOutSegments(skeleton, mesh.levels > 0 ? meshLevels : skeleton.levels, g.mesh.fakedStems);
  if (mesh.levels > 0) g.sketch = sketchSegments(skeleton, meshLevels, skeleton.levels - 1);
  if (options.patches) g.patches = buildPatches(g.mesh.mesh);
  if (options.wind) g.wind = treeWind(skeleton, g.mesh, g.impostors, g.sketch);
  return g;
}

}  // namespace arbor
