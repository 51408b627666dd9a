// Species JSON: parsed, and when valid grown and meshed under the fuzz limits (fuzz_limits.hpp); a valid file must
// also finish or be refused: hangs and memory past the limits are findings too.
#include "fuzz_limits.hpp"
#include "fuzz_target.hpp"
#include "growth/weber_penn/weber_penn.hpp"
#include "mesh/tree_mesh.hpp"
#include "growth/weber_penn/species_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    const arbor::SpeciesParams p = arbor::readSpeciesJson(text, "fuzz.json");
    const arbor::Skeleton s = arbor::generateSkeleton(p, arbor::fuzz::fuzzGrowth());
    arbor::buildTreeMesh(s, arbor::fuzz::fuzzMesh());
  });
}
