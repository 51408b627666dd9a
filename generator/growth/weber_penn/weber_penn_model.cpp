#include "weber_penn_model.hpp"

#include <algorithm>
#include <cmath>

#include "species_fields.hpp"
#include "species_io.hpp"
#include "tree_estimate.hpp"
#include "weber_penn.hpp"

namespace arbor {

namespace {

// One editable number: a tree field, or a field of one stem level.
struct Slot {
  const TreeField* tree = nullptr;
  const LevelField* level = nullptr;
  std::size_t levelIndex = 0;
};

class WeberPennParams final : public ModelParams {
 public:
  explicit WeberPennParams(SpeciesParams species) : species_(std::move(species)) {}

  const char* model() const override { return kWeberPennModel; }
  std::string name() const override { return species_.name; }
  int levels() const override { return species_.levels; }
  Skeleton grow(const GrowthOptions& options) const override { return generateSkeleton(species_, options); }
  TreeEstimate estimate(int levels) const override { return estimateTree(species_, levels); }
  std::string toJson() const override { return writeSpeciesJson(species_); }
  std::unique_ptr<ModelParams> clone() const override { return std::make_unique<WeberPennParams>(*this); }
  const SpeciesParams& species() const { return species_; }

  std::vector<ModelParameter> parameters() const override {
    std::vector<ModelParameter> out;
    for (const Slot& s : slots()) {
      if (s.tree) {
        out.push_back({s.tree->key, "", s.tree->min, s.tree->max, s.tree->integer != nullptr});
      } else {
        const bool trunks = isTrunkCount(s);
        out.push_back({s.level->key, "level " + std::to_string(s.levelIndex), trunks ? 1.0 : s.level->min,
                       trunks ? 64.0 : s.level->max, trunks || s.level->integer != nullptr});
      }
    }
    return out;
  }

  double value(std::size_t index) const override {
    const Slot s = slots().at(index);
    if (s.tree) return s.tree->real ? species_.*s.tree->real : species_.*s.tree->integer;
    const StemLevelParams& lp = species_.stemLevels[s.levelIndex];
    return s.level->real ? lp.*s.level->real : lp.*s.level->integer;
  }

  void setValue(std::size_t index, double value) override {
    const Slot s = slots().at(index);
    const ModelParameter p = parameters().at(index);
    value = std::clamp(value, p.min, p.max);
    if (p.integer) value = std::round(value);
    if (s.tree) {
      if (s.tree->real) species_.*s.tree->real = value;
      else species_.*s.tree->integer = static_cast<int>(value);
    } else {
      StemLevelParams& lp = species_.stemLevels[s.levelIndex];
      if (s.level->real) lp.*s.level->real = value;
      else lp.*s.level->integer = static_cast<int>(value);
    }
    // Levels past the entries given would have no parameters: at most as many as there are.
    species_.levels = std::min(species_.levels, static_cast<int>(species_.stemLevels.size()));
  }

 private:
  // The trunk count (level 0's Branches) is a whole number of trunks on a hub of at most 64 ports.
  static bool isTrunkCount(const Slot& s) { return s.levelIndex == 0 && s.level->real == &StemLevelParams::branches; }

  std::vector<Slot> slots() const {
    std::vector<Slot> out;
    for (const TreeField& f : treeFields()) {
      if (f.real || (f.integer && f.type == FieldType::Integer)) out.push_back({&f, nullptr, 0});
    }
    for (std::size_t l = 0; l < species_.stemLevels.size(); ++l) {
      for (const LevelField& f : levelFields()) {
        if (f.real || f.integer) out.push_back({nullptr, &f, l});
      }
    }
    return out;
  }

  SpeciesParams species_;
};

}  // namespace

TreeModel weberPennModel(SpeciesParams species) { return TreeModel(std::make_unique<WeberPennParams>(std::move(species))); }

TreeModel readWeberPennModel(const std::string& text, const std::string& file, bool xml, const ModelReadOptions& options) {
  SpeciesParams species = xml ? readSpeciesXml(text, file, options.notes) : readSpeciesJson(text, file);
  if (options.naturalAngles) species.angleRule = AngleRule::Natural;
  return weberPennModel(std::move(species));
}

TreeModel randomWeberPennModel(std::uint64_t seed) { return weberPennModel(randomSpecies(seed)); }

const SpeciesParams* speciesOf(const TreeModel& model) {
  const auto* wp = dynamic_cast<const WeberPennParams*>(&model.params());
  return wp ? &wp->species() : nullptr;
}

}  // namespace arbor
