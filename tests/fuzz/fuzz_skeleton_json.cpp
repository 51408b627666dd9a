// Skeleton JSON (arbor-skeleton/1): parsed, and when valid meshed under the fuzz limits (fuzz_limits.hpp); a
// skeleton the reader accepts must be one the mesher can mesh or refuse.
#include "fuzz_limits.hpp"
#include "fuzz_target.hpp"
#include "growth/skeleton_json.hpp"
#include "mesh/tree_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) { arbor::buildTreeMesh(arbor::readSkeletonJson(text, "fuzz.json"), arbor::fuzz::fuzzMesh()); });
}
