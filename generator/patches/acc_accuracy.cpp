#include "acc_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "acc.hpp"
#include "limit_reference.hpp"

namespace arbor {

AccAccuracy measureAccAccuracy(const QuadMesh& mesh, const PatchSet& patches, std::size_t maxPatches, int samplesPerSide) {
  if (samplesPerSide < 2) throw std::invalid_argument("measureAccAccuracy: at least 2 samples per side (the corners)");
  const LimitSurface limit(mesh);
  const std::size_t stride = maxPatches == 0 ? 1 : std::max<std::size_t>(1, (patches.size() + maxPatches - 1) / maxPatches);
  AccAccuracy r;
  double regularSquares = 0, extraordinarySquares = 0;
  std::size_t regularSamples = 0, extraordinarySamples = 0;
  for (std::size_t p = 0; p < patches.size(); p += stride) {
    if (patches.kind[p] == PatchKind::Fallback) continue;
    const bool regular = patches.kind[p] == PatchKind::Regular;
    const AccPatch acc = buildAccPatch(mesh, patches, p);
    // Twigs end in points: a floor keeps the ratio finite where the mesh radius is (nearly) zero.
    const double radius = std::max(1e-6, static_cast<double>(mesh.radius[mesh.quads[p][0]]));
    double& worst = regular ? r.regularMax : r.extraordinaryMax;
    double& squares = regular ? regularSquares : extraordinarySquares;
    std::size_t& count = regular ? regularSamples : extraordinarySamples;
    for (int j = 0; j < samplesPerSide; ++j) {
      for (int i = 0; i < samplesPerSide; ++i) {
        const double u = static_cast<double>(i) / (samplesPerSide - 1), v = static_cast<double>(j) / (samplesPerSide - 1);
        const double e = glm::distance(evaluateBezier(acc.geometry, u, v), limit.position(static_cast<int>(p), u, v)) / radius;
        worst = std::max(worst, e);
        squares += e * e;
        ++count;
      }
    }
    ++(regular ? r.regularPatches : r.extraordinaryPatches);
  }
  r.samples = regularSamples + extraordinarySamples;
  r.regularRms = regularSamples ? std::sqrt(regularSquares / static_cast<double>(regularSamples)) : 0.0;
  r.extraordinaryRms = extraordinarySamples ? std::sqrt(extraordinarySquares / static_cast<double>(extraordinarySamples)) : 0.0;
  return r;
}

}  // namespace arbor
