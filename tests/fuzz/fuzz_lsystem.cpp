// L-system grammars (.lsys): parsed, and when valid derived, interpreted and meshed under the fuzz limits
// (fuzz_limits.hpp); a grammar that grows without bound must be refused at a limit, never hang or exhaust memory.
#include "fuzz_limits.hpp"
#include "fuzz_target.hpp"
#include "growth/lsystem/lsystem_model.hpp"
#include "mesh/tree_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    const arbor::TreeModel model = arbor::readLsystemModel(text, "fuzz.lsys");
    arbor::buildTreeMesh(model.grow(arbor::fuzz::fuzzGrowth()), arbor::fuzz::fuzzMesh());
  });
}
