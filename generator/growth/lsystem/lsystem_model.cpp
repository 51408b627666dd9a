#include "lsystem_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "common/text_util.hpp"
#include "derivation.hpp"
#include "growth/graph/branch_graph.hpp"
#include "turtle.hpp"

namespace arbor {

namespace {

using lsys::Lsystem;

// Scales the graph so that the largest extent of its bounding box is `size` (positions, radii, leaves).
void scaleGraph(BranchGraph& graph, double size) {
  Vec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (const BranchNode& n : graph.nodes) low = glm::min(low, n.position), high = glm::max(high, n.position);
  const double extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
  if (!(extent > 0)) return;
  const double k = size / extent;
  for (BranchNode& n : graph.nodes) n.position *= k, n.radius *= k;
  for (GraphLeaf& l : graph.leaves) l.position *= k, l.length *= k, l.width *= k;
}

// The seed a grow uses: the file's for GrowthOptions::seed 1 (the default), the next ones for 2, 3, ...
std::uint64_t derivationSeed(const Lsystem& system, std::uint64_t seed) { return system.seed + seed - 1; }

class LsystemParams final : public ModelParams {
 public:
  LsystemParams(Lsystem system, std::string text) : system_(std::move(system)), text_(std::move(text)) {}

  const char* model() const override { return kLsystemModel; }
  std::string name() const override { return system_.name; }
  int levels() const override { return 4; }  // the trunk and three branching orders meshed; deeper ones as fake branches

  Skeleton grow(const GrowthOptions& options) const override {
    GraphOptions graph;
    graph.species = system_.name;
    graph.tipRadius = system_.tipRadius;
    // Internodes are counted before the turtle runs: the conversion merges about ten into one skeleton node.
    Skeleton s = graphToSkeleton(lsystemGraph(system_, options.seed, 10 * options.limits.nodes, options.limits.modules), graph);
    s.seed = options.seed;
    if (s.nodes.size() > options.limits.nodes)
      throw GenerationError("l-system '" + system_.name + "': " + std::to_string(s.nodes.size()) + " skeleton nodes, more than the limit of " +
                            std::to_string(options.limits.nodes) + " (lower n)");
    if (s.leaves.size() > options.limits.leaves)
      throw GenerationError("l-system '" + system_.name + "': " + std::to_string(s.leaves.size()) + " leaves, more than the limit of " +
                            std::to_string(options.limits.leaves) + " (lower n)");
    return s;
  }

  TreeEstimate estimate(int) const override {
    // Derives under a small module limit; past it, the last step's growth ratio extrapolates.
    constexpr std::size_t kLimit = 200'000;
    std::mt19937_64 random(system_.seed);
    lsys::ModuleString str = lsys::axiomString(system_);
    double ratio = 1, scale = 1;
    for (int step = 1; step <= system_.derivationLength; ++step) {
      try {
        lsys::ModuleString next = lsys::deriveStep(system_, str, random, step, kLimit);
        ratio = str.size() ? static_cast<double>(next.size()) / static_cast<double>(str.size()) : 1;
        str = std::move(next);
      } catch (const LimitError&) {
        scale = std::pow(std::max(ratio, 1.0), system_.derivationLength - step + 1);
        break;
      }
    }
    double drawn = 0, branches = 1, polygons = 0;
    for (const lsys::Module& m : str.modules) {
      drawn += m.symbol == 'F';
      branches += m.symbol == '[';
      polygons += m.symbol == '{';
    }
    TreeEstimate e;
    e.nodes = drawn * scale + 1;  // every F an internode: an upper bound, the conversion merges short ones
    e.stems = branches * scale;
    e.leaves = polygons * scale;
    e.quads = 4 * e.nodes + 12 * e.stems;
    e.nodesPerLevel = {e.nodes};
    e.stemsPerLevel = {e.stems};
    e.drivers = "about " + formatNumber(std::round(static_cast<double>(str.size()) * scale)) + " modules after " +
                std::to_string(system_.derivationLength) + " derivation steps";
    e.lowerNodes = e.lowerLeaves = "lower n";
    return e;
  }

  // Not JSON: the grammar's own text with the edited values written into it.
  std::string toJson() const override {
    std::istringstream in(text_);
    std::string line, out;
    std::vector<bool> written(slotCount(), false);
    while (std::getline(in, line)) {
      const std::size_t slot = slotOfLine(line);
      if (slot != kNone) {
        written[slot] = true;
        line = lineFor(slot) + trailingComment(line);
      }
      out += line + "\n";
    }
    std::string missing;
    for (std::size_t i = 0; i < written.size(); ++i)
      if (!written[i]) missing += lineFor(i) + "\n";
    return missing + out;
  }

  std::vector<ModelParameter> parameters() const override {
    const auto range = [](double v) { return v >= 0 ? std::pair{0.0, std::max(4 * v, 1.0)} : std::pair{std::min(4 * v, -1.0), 0.0}; };
    std::vector<ModelParameter> out;
    out.push_back({"n", "", 0, static_cast<double>(std::max(12, 2 * original_.derivationLength)), true});
    out.push_back({"delta", "", 0, 180, false});
    out.push_back({"d", "", range(original_.step).first, range(original_.step).second, false});
    out.push_back({"width", "", 0, std::max(4 * original_.width, 1.0), false});
    out.push_back({"seed", "", 0, std::max(1e6, static_cast<double>(original_.seed)), true});
    for (std::size_t i = 0; i < original_.constants.size(); ++i) {
      const auto [low, high] = range(original_.constants[i]);
      out.push_back({original_.constantNames[i], "constants", low, high, false});
    }
    return out;
  }

  double value(std::size_t index) const override {
    switch (index) {
      case 0: return system_.derivationLength;
      case 1: return system_.angle;
      case 2: return system_.step;
      case 3: return system_.width;
      case 4: return static_cast<double>(system_.seed);
      default: return system_.constants.at(index - 5);
    }
  }

  void setValue(std::size_t index, double value) override {
    const ModelParameter p = parameters().at(index);
    value = std::clamp(value, p.min, p.max);
    if (p.integer) value = std::round(value);
    switch (index) {
      case 0: system_.derivationLength = static_cast<int>(value); break;
      case 1: system_.angle = value; break;
      case 2: system_.step = value == 0 ? system_.step : value; break;  // d = 0 would draw nothing
      case 3: system_.width = value; break;
      case 4: system_.seed = static_cast<std::uint64_t>(value); break;
      default: system_.constants.at(index - 5) = value;
    }
  }

  std::unique_ptr<ModelParams> clone() const override { return std::make_unique<LsystemParams>(*this); }
  const Lsystem& system() const { return system_; }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t slotCount() const { return 5 + system_.constants.size(); }

  // The parameter a line of the grammar sets (header or #define), or kNone.
  std::size_t slotOfLine(const std::string& line) const {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "#define") {
      const auto it = std::find(system_.constantNames.begin(), system_.constantNames.end(), second);
      return it == system_.constantNames.end() ? kNone : 5 + static_cast<std::size_t>(it - system_.constantNames.begin());
    }
    const std::size_t colon = first.find(':');
    const std::string key = first.substr(0, colon);
    if (colon == std::string::npos && second.rfind(':', 0) != 0) return kNone;
    if (line.find("->") != std::string::npos) return kNone;
    static const char* const kKeys[] = {"n", "delta", "d", "width", "seed"};
    for (std::size_t i = 0; i < 5; ++i)
      if (key == kKeys[i]) return i;
    return kNone;
  }

  std::string lineFor(std::size_t slot) const {
    static const char* const kKeys[] = {"n", "delta", "d", "width", "seed"};
    if (slot < 5) return std::string(kKeys[slot]) + ": " + formatNumber(value(slot));
    return "#define " + system_.constantNames[slot - 5] + " " + formatNumber(value(slot));
  }

  static std::string trailingComment(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t");
    const bool define = first != std::string::npos && line.compare(first, 7, "#define") == 0;
    const std::size_t start = define ? line.find('#', first + 1) : line.find('#');
    return start == std::string::npos ? "" : "  " + line.substr(start);
  }

  Lsystem system_;
  Lsystem original_ = system_;  // ranges stay those of the file, whatever the edits
  std::string text_;
};

}  // namespace

BranchGraph lsystemGraph(const Lsystem& system, std::uint64_t seed, std::size_t maxInternodes, std::size_t moduleCap) {
  lsys::DeriveOptions options;
  options.seed = derivationSeed(system, seed);
  if (moduleCap > 0) options.moduleLimit = std::min(system.moduleLimit, moduleCap);
  const lsys::ModuleString str = lsys::derive(system, options);
  const auto internodes = static_cast<std::size_t>(
      std::count_if(str.modules.begin(), str.modules.end(), [](const lsys::Module& m) { return m.symbol == 'F'; }));
  if (internodes > maxInternodes)
    throw GenerationError("l-system '" + system.name + "': " + std::to_string(internodes) + " internodes (F), more than " +
                          std::to_string(maxInternodes) + " (ten per skeleton node of the limit; lower n)");
  lsys::Interpretation drawn = lsys::interpret(str, lsys::turtleSettings(system));
  if (drawn.segments == 0) throw InputError(system.file, "axiom", "the derived string draws no internode (no F outside a polygon)");
  BranchGraph graph = std::move(drawn.graph);
  if (system.size > 0) scaleGraph(graph, system.size);
  return graph;
}

TreeModel readLsystemModel(const std::string& text, const std::string& file, const ModelReadOptions& options) {
  if (options.naturalAngles) throw InputError(file, "--natural-angles", "an l-system has no angle rules: its productions give the angles");
  Lsystem system = lsys::parseLsystem(text, file);
  if (system.name.empty()) system.name = std::filesystem::path(file).stem().string();
  return TreeModel(std::make_unique<LsystemParams>(std::move(system), text));
}

const lsys::Lsystem* lsystemOf(const TreeModel& model) {
  const auto* p = dynamic_cast<const LsystemParams*>(&model.params());
  return p ? &p->system() : nullptr;
}

}  // namespace arbor
