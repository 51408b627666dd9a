// Random species for stress tests: every field drawn evenly from its documented range, as a user dragging
// every slider to a random place would set it. Most such trees are strange; all must grow or be refused.
#include <cmath>

#include "common/mix64.hpp"
#include "species_fields.hpp"
#include "species_io.hpp"

namespace arbor {

namespace {

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : state_(mix64(seed ^ 0x5eed5eed5eed5eedULL)) {}
  double unit() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return static_cast<double>(mix64(state_) >> 11) * 0x1.0p-53;
  }
  double real(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int whole(double lo, double hi) { return static_cast<int>(std::floor(lo + (hi - lo + 1.0) * unit())); }

 private:
  std::uint64_t state_;
};

}  // namespace

SpeciesParams randomSpecies(std::uint64_t seed) {
  Draw draw(seed);
  SpeciesParams p;
  p.name = "Random species " + std::to_string(seed);
  p.source = "random:" + std::to_string(seed);
  for (const TreeField& f : treeFields()) {
    if (f.real) p.*f.real = draw.real(f.min, f.max);
    if (f.integer) p.*f.integer = draw.whole(f.min, f.max);
    if (f.type == FieldType::AngleRule) p.angleRule = draw.unit() < 0.5 ? AngleRule::Natural : AngleRule::Classic;
    if (f.type == FieldType::LeafShape) p.leafShape = static_cast<LeafKind>(draw.whole(0, 3));
  }
  for (int level = 0; level < p.levels; ++level) {
    StemLevelParams lp;
    for (const LevelField& f : levelFields()) {
      if (f.real) lp.*f.real = draw.real(f.min, f.max);
      if (f.integer) lp.*f.integer = draw.whole(f.min, f.max);
    }
    lp.branchRatioGiven = draw.unit() < 0.5;
    if (level == 0) lp.branches = draw.whole(1, 64);  // trunks: the one cross-field rule (validateSpecies)
    if (level == 0 && lp.length <= 0.0) lp.length = 1.0;
    p.stemLevels.push_back(lp);
  }
  validateSpecies(p, p.source);
  return p;
}

}  // namespace arbor
