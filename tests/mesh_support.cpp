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

}  // namespace arbor::test
