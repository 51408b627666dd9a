// Space-colonization models (JSON): parsed, and when valid grown and meshed under the fuzz limits
// (fuzz_limits.hpp); clouds, obstacles and growth settings must be refused or finish, never hang.
#include "fuzz_limits.hpp"
#include "fuzz_target.hpp"
#include "growth/space_colonization/space_colonization_model.hpp"
#include "mesh/tree_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    const arbor::TreeModel model = arbor::readSpaceColonizationModel(text, "fuzz.json");
    arbor::buildTreeMesh(model.grow(arbor::fuzz::fuzzGrowth()), arbor::fuzz::fuzzMesh());
  });
}
