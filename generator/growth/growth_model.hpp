#pragma once
// The growth-model interface: a model turns its own parameters and a seed into a Skeleton, the one thing the
// mesh stage takes. Each model lives in its own folder under growth/ and is listed in growth_models.cpp;
// nothing above generator/growth knows which model grew a tree.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "skeleton.hpp"
#include "tree_limits.hpp"

namespace arbor {

struct GrowthOptions {
  std::uint64_t seed = 1;
  int levels = 0;   // 0: the model's own stem levels; otherwise 1..8 (the levels past the mesh become fake branches)
  TreeLimits limits;  // refuse trees beyond these instead of exhausting memory or time
};

// A tree that cannot be grown as asked (too large); callers exit with code 2.
class GenerationError : public LimitError {
 public:
  using LimitError::LimitError;
};

// What reading a model file noticed and the user should hear (never silent defaults).
struct ImportNotes {
  std::vector<std::string> defaulted;  // parameters absent from the file and the default each took
  std::vector<std::string> ignored;    // parameters read but not used
};

// How a model file is read: the notes to fill, and whether a model with angle rules (Weber-Penn) takes
// Murray's natural angles instead of the file's own (a model without angle rules refuses that).
struct ModelReadOptions {
  bool naturalAngles = false;
  ImportNotes* notes = nullptr;
};

// One number of a model's parameters a user may edit (the viewer's panel), with its documented range.
struct ModelParameter {
  std::string key;    // as the model file names it
  std::string group;  // "" for the tree as a whole, else a heading ("level 1")
  double min = 0, max = 0;
  bool integer = false;
};

// One model's parameters behind the interface; each model implements it in its own folder.
class ModelParams {
 public:
  virtual ~ModelParams() = default;
  virtual const char* model() const = 0;     // the name model files give ("weber-penn")
  virtual std::string name() const = 0;      // the tree's name ("Black Tupelo")
  virtual int levels() const = 0;            // stem levels grown when GrowthOptions::levels is 0
  virtual Skeleton grow(const GrowthOptions& options) const = 0;
  virtual TreeEstimate estimate(int levels) const = 0;  // from the parameters alone, in microseconds
  virtual std::string toJson() const = 0;    // the model file, every parameter written
  virtual std::vector<ModelParameter> parameters() const = 0;
  virtual double value(std::size_t index) const = 0;
  virtual void setValue(std::size_t index, double value) = 0;  // clamped to the parameter's range
  virtual std::unique_ptr<ModelParams> clone() const = 0;
};

// A growth model with its parameters, passed by value: copies share until one is edited.
class TreeModel {
 public:
  explicit TreeModel(std::unique_ptr<ModelParams> params);

  const char* model() const { return params_->model(); }
  std::string name() const { return params_->name(); }
  int levels() const { return params_->levels(); }
  // The model's tree, refused (GenerationError) where a node lies past kMaxCoordinate or is not finite.
  Skeleton grow(const GrowthOptions& options) const;
  TreeEstimate estimate(int levels = 0) const { return params_->estimate(levels); }
  std::string toJson() const { return params_->toJson(); }
  std::vector<ModelParameter> parameters() const { return params_->parameters(); }
  double value(std::size_t index) const { return params_->value(index); }
  void setValue(std::size_t index, double value);
  const ModelParams& params() const { return *params_; }

 private:
  std::shared_ptr<ModelParams> params_;
};

}  // namespace arbor
