#pragma once
// The limits fuzzed trees are held to. Under the sanitizers and coverage a tree meshes 7 to 60 times slower than in
// a release build (dense clone thickets are the slowest: a fuzzed palm of 65,520 trunk clones, 917,000 quads, took
// 3.6 s released and 203 s fuzzed), so the product's limits (about 10 s on two cores) would let a valid tree pass
// the 60 s hang timeout. A fiftieth of its quads keeps the largest tree a fuzzer can grow well inside it (the
// densest palm found under it: 13 s); the parsers and the mesher's paths are the same at any size.
#include "growth/growth_model.hpp"
#include "mesh/mesh_options.hpp"

namespace arbor::fuzz {

inline TreeLimits fuzzLimits() {
  TreeLimits limits;
  limits.nodes = 100'000;
  limits.leaves = 100'000;
  limits.quads = 50'000;
  // An L-system's own default (50 million modules: fig-1-31a at n 60 reaches it in 3.9 s and 1.2 GB released, past
  // 60 s fuzzed) held to a fiftieth too.
  limits.modules = 1'000'000;
  return limits;
}

inline GrowthOptions fuzzGrowth() {
  GrowthOptions options;
  options.limits = fuzzLimits();
  return options;
}

inline MeshOptions fuzzMesh() {
  MeshOptions options;
  options.maxQuads = fuzzLimits().quads;
  return options;
}

}  // namespace arbor::fuzz
