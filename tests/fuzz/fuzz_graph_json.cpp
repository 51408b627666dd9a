// Branch graph JSON (arbor-graph/1): parsed, and when valid converted to a skeleton and meshed under the fuzz
// limits (fuzz_limits.hpp); a graph that is no tree must be refused, never crash the converter or the mesher.
#include "fuzz_limits.hpp"
#include "fuzz_target.hpp"
#include "growth/graph/branch_graph.hpp"
#include "growth/graph/graph_json.hpp"
#include "mesh/tree_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    arbor::buildTreeMesh(arbor::graphToSkeleton(arbor::readBranchGraphJson(text, "fuzz.json")), arbor::fuzz::fuzzMesh());
  });
}
