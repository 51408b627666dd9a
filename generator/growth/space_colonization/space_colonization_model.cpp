#include "space_colonization_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "common/text_util.hpp"
#include "growth/graph/graph_json.hpp"
#include "growth/random.hpp"

namespace arbor {

namespace {

using sc::AttractionCloud;
using sc::CloudShape;
using sc::SpaceColonization;

// What an editable number of a cloud is.
enum class CloudValue { Points, Influence, Kill, SizeX, SizeY, SizeZ };

struct Slot {
  int cloud = -1;  // -1: the tree as a whole (segmentLength, gravity, seed)
  CloudValue what = CloudValue::Points;
  ModelParameter parameter;
};

std::vector<Slot> slotsOf(const SpaceColonization& m) {
  std::vector<Slot> out;
  out.push_back({-1, CloudValue::Points, {"segmentLength", "", 0.01, std::max(4 * m.segmentLength, 1.0), false}});
  out.push_back({-1, CloudValue::Influence, {"gravity", "", 0, std::max(4 * m.gravity, 1.0), false}});
  out.push_back({-1, CloudValue::Kill, {"seed", "", 0, std::max(1e6, static_cast<double>(m.seed)), true}});
  for (std::size_t i = 0; i < m.clouds.size(); ++i) {
    const AttractionCloud& c = m.clouds[i];
    const std::string group = "cloud " + std::to_string(i + 1) + " (" + sc::cloudShapeName(c.shape) + ")";
    const int k = static_cast<int>(i);
    const double extent = std::max({c.size.x, c.size.y, c.size.z});
    const auto size = [&](CloudValue what, const char* key) { out.push_back({k, what, {key, group, 0.01, std::max(4 * extent, 1.0), false}}); };
    out.push_back({k, CloudValue::Points, {"points", group, 1, std::max(4.0 * c.points, 1000.0), true}});
    out.push_back({k, CloudValue::Influence, {"influence", group, 0.001, std::max(4 * c.influence, 1.0), false}});
    out.push_back({k, CloudValue::Kill, {"kill", group, 0.001, std::max(4 * c.influence, 1.0), false}});
    switch (c.shape) {
      case CloudShape::Sphere: size(CloudValue::SizeX, "radius"); break;
      case CloudShape::Ellipsoid: size(CloudValue::SizeX, "radii[0]"), size(CloudValue::SizeY, "radii[1]"), size(CloudValue::SizeZ, "radii[2]"); break;
      case CloudShape::Cone: size(CloudValue::SizeX, "radius"), size(CloudValue::SizeZ, "height"); break;
      case CloudShape::Box: size(CloudValue::SizeX, "size[0]"), size(CloudValue::SizeY, "size[1]"), size(CloudValue::SizeZ, "size[2]"); break;
    }
  }
  return out;
}

class SpaceColonizationParams final : public ModelParams {
 public:
  explicit SpaceColonizationParams(SpaceColonization m) : model_(std::move(m)) {}

  const char* model() const override { return kSpaceColonizationModel; }
  std::string name() const override { return model_.name; }
  int levels() const override { return 4; }  // the trunk and three branching orders meshed; deeper ones as fake branches

  Skeleton grow(const GrowthOptions& options) const override {
    sc::Colonizer colonizer = startColonizer(model_, options.seed);
    while (!colonizer.finished()) {
      colonizer.step(20'000);
      requireNodeLimit(colonizer, model_, options.limits);
    }
    return colonizationSkeleton(colonizer, model_, options.seed, options.limits);
  }

  TreeEstimate estimate(int) const override {
    // About one node per point killed; every point dies or is left over, so the points bound the nodes.
    double points = 0;
    for (const AttractionCloud& c : model_.clouds) points += c.points;
    TreeEstimate e;
    e.nodes = model_.trunkSegments + 1 + points;
    e.stems = 0.3 * e.nodes;
    e.leaves = model_.leafDepth < 0 ? 0 : 0.5 * e.nodes;
    e.quads = 4 * e.nodes + 12 * e.stems;
    e.nodesPerLevel = {e.nodes};
    e.stemsPerLevel = {e.stems};
    e.drivers = "at most " + formatNumber(points) + " attraction points in " + std::to_string(model_.clouds.size()) + " clouds";
    e.lowerNodes = "lower the clouds' points";
    e.lowerLeaves = "lower leaves.depth";
    return e;
  }

  std::string toJson() const override { return sc::writeSpaceColonization(model_); }

  std::vector<ModelParameter> parameters() const override {
    std::vector<ModelParameter> out;
    for (const Slot& s : slotsOf(original_)) out.push_back(s.parameter);
    return out;
  }

  double value(std::size_t index) const override {
    const Slot s = slotsOf(original_).at(index);
    if (s.cloud < 0) return index == 0 ? model_.segmentLength : index == 1 ? model_.gravity : static_cast<double>(model_.seed);
    const AttractionCloud& c = model_.clouds.at(static_cast<std::size_t>(s.cloud));
    switch (s.what) {
      case CloudValue::Points: return c.points;
      case CloudValue::Influence: return c.influence;
      case CloudValue::Kill: return c.kill;
      case CloudValue::SizeX: return c.size.x;
      case CloudValue::SizeY: return c.size.y;
      case CloudValue::SizeZ: return c.size.z;
    }
    return 0;
  }

  void setValue(std::size_t index, double value) override {
    const Slot s = slotsOf(original_).at(index);
    value = std::clamp(value, s.parameter.min, s.parameter.max);
    if (s.parameter.integer) value = std::round(value);
    if (s.cloud < 0) {
      if (index == 0) model_.segmentLength = value;
      else if (index == 1) model_.gravity = value;
      else model_.seed = static_cast<std::uint64_t>(value);
      return;
    }
    AttractionCloud& c = model_.clouds.at(static_cast<std::size_t>(s.cloud));
    switch (s.what) {
      case CloudValue::Points: c.points = static_cast<std::uint32_t>(value); break;
      case CloudValue::Influence: c.influence = value; break;
      case CloudValue::Kill: c.kill = value; break;
      case CloudValue::SizeX:
        c.size.x = value;
        if (c.shape == CloudShape::Sphere) c.size = Vec3(value);
        if (c.shape == CloudShape::Cone) c.size.y = value;
        break;
      case CloudValue::SizeY: c.size.y = value; break;
      case CloudValue::SizeZ: c.size.z = value; break;
    }
    c.kill = std::min(c.kill, 0.99 * c.influence);  // a point must attract before it dies
  }

  std::unique_ptr<ModelParams> clone() const override { return std::make_unique<SpaceColonizationParams>(*this); }
  const SpaceColonization& parameters_() const { return model_; }

 private:
  SpaceColonization model_;
  SpaceColonization original_ = model_;  // ranges and the list of numbers stay those of the file, whatever the edits
};

// A unit vector perpendicular to d.
Vec3 perpendicular(const Vec3& d) {
  const Vec3 a = std::abs(d.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
  return glm::normalize(glm::cross(d, a));
}

}  // namespace

sc::Colonizer startColonizer(const SpaceColonization& m, std::uint64_t seed) {
  sc::ColonizerSettings settings;
  settings.segmentLength = m.segmentLength;
  settings.gravity = m.gravity;
  settings.trunkBase = m.trunkBase;
  settings.trunkSegments = m.trunkSegments;
  settings.seed = m.seed + seed - 1;  // the file's seed for GrowthOptions::seed 1, the next ones for 2, 3, ...
  sc::Colonizer colonizer(settings);
  for (const sc::Obstacle& o : m.obstacles) colonizer.addObstacle(o);
  for (const AttractionCloud& c : m.clouds) colonizer.addCloud(c);
  return colonizer;
}

void requireNodeLimit(const sc::Colonizer& colonizer, const SpaceColonization& m, const TreeLimits& limits) {
  if (colonizer.nodes().size() > limits.nodes)
    throw GenerationError("space colonization '" + m.name + "': more than " + std::to_string(limits.nodes) +
                          " nodes (the limit; lower the clouds' points or raise segmentLength)");
}

Skeleton colonizationSkeleton(const sc::Colonizer& colonizer, const SpaceColonization& m, std::uint64_t seed, const TreeLimits& limits) {
  Skeleton s = graphToSkeleton(colonizationGraph(colonizer, m), colonizationGraphOptions(m));
  s.seed = seed;
  if (s.leaves.size() > limits.leaves)
    throw GenerationError("space colonization '" + m.name + "': " + std::to_string(s.leaves.size()) + " leaves, more than the limit of " +
                          std::to_string(limits.leaves) + " (lower leaves.depth)");
  return s;
}

GraphOptions colonizationGraphOptions(const SpaceColonization& m) {
  GraphOptions o;
  o.exponent = m.exponent;
  o.tipRadius = m.tipRadius;
  o.species = m.name;
  return o;
}

BranchGraph colonizationGraph(const sc::Colonizer& colonizer, const SpaceColonization& m) {
  const auto& nodes = colonizer.nodes();
  BranchGraph graph;
  std::vector<std::int32_t> index(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].enabled) continue;  // disabled nodes are kept by the colonizer, not drawn
    index[i] = static_cast<std::int32_t>(graph.nodes.size());
    BranchNode n;
    n.position = nodes[i].position;
    n.parent = nodes[i].parent < 0 ? -1 : index[static_cast<std::size_t>(nodes[i].parent)];
    n.radius = i >= 1 && static_cast<int>(i) <= m.trunkSegments ? 0.5 * m.trunkWidth : 0;
    graph.nodes.push_back(n);
  }
  if (m.leafDepth < 0) return graph;
  // Segments to the nearest tip below each node; children come after their parents.
  std::vector<int> aboveTip(graph.nodes.size(), 1 << 30);
  std::vector<bool> hasChild(graph.nodes.size(), false);
  for (const BranchNode& n : graph.nodes)
    if (n.parent >= 0) hasChild[static_cast<std::size_t>(n.parent)] = true;
  for (std::size_t i = graph.nodes.size(); i-- > 0;) {
    if (!hasChild[i]) aboveTip[i] = 0;
    const std::int32_t p = graph.nodes[i].parent;
    if (p >= 0) aboveTip[static_cast<std::size_t>(p)] = std::min(aboveTip[static_cast<std::size_t>(p)], aboveTip[i] + 1);
  }
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const std::int32_t p = graph.nodes[i].parent;
    if (p < 0 || static_cast<int>(i) <= m.trunkSegments || aboveTip[i] > m.leafDepth) continue;
    const Vec3 d = glm::normalize(graph.nodes[i].position - graph.nodes[static_cast<std::size_t>(p)].position);
    Rng rng(childKey(colonizer.settings().seed, 0x1eaf, i), kStreamLeaves);
    const double turn = 2 * std::numbers::pi * rng.uniform();
    const Vec3 u = perpendicular(d), v = glm::cross(d, u);
    GraphLeaf leaf;
    leaf.node = static_cast<std::int32_t>(i);
    leaf.position = graph.nodes[i].position;
    leaf.direction = glm::normalize(d + 1.2 * (std::cos(turn) * u + std::sin(turn) * v));  // about 50 degrees off the twig
    leaf.length = m.leafLength;
    leaf.width = m.leafWidth;
    graph.leaves.push_back(leaf);
  }
  return graph;
}

std::string writeColonizationGraph(const sc::Colonizer& colonizer, const SpaceColonization& m) {
  BranchGraph graph = colonizationGraph(colonizer, m);
  const std::vector<double> radii = pipeRadii(graph, colonizationGraphOptions(m));
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) graph.nodes[i].radius = radii[i];
  return writeBranchGraphJson(graph);
}

TreeModel readSpaceColonizationModel(const std::string& text, const std::string& file, const ModelReadOptions& options) {
  if (options.naturalAngles) throw InputError(file, "--natural-angles", "space colonization has no angle rules: the attraction points give the directions");
  SpaceColonization m = sc::readSpaceColonization(text, file);
  if (m.name.empty()) m.name = std::filesystem::path(file).stem().string();
  return TreeModel(std::make_unique<SpaceColonizationParams>(std::move(m)));
}

TreeModel randomSpaceColonizationModel(std::uint64_t seed) {
  Rng rng(seed, kStreamTree);
  const auto between = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  SpaceColonization m;
  m.name = "Random space colonization " + std::to_string(seed);
  m.file = "random:" + std::to_string(seed);
  m.seed = seed;
  m.segmentLength = between(0.05, 0.2);
  m.gravity = rng.uniform() < 0.5 ? 0.0 : between(0.0, 0.1);
  m.trunkSegments = static_cast<int>(between(5, 30));
  m.trunkWidth = between(0.1, 0.4);
  const double top = m.segmentLength * m.trunkSegments;
  const int clouds = static_cast<int>(between(1, 5));
  for (int k = 0; k < clouds; ++k) {
    AttractionCloud c;
    c.shape = static_cast<CloudShape>(static_cast<int>(between(0, 4)));
    const double e = between(0.8, 3.0);  // about the cloud's half extent
    const Vec3 stretch(between(0.6, 1.2), between(0.6, 1.2), between(0.6, 1.2));
    double below = 0;  // how far the volume reaches below its centre
    switch (c.shape) {
      case CloudShape::Sphere: c.size = Vec3(e), below = e; break;
      case CloudShape::Ellipsoid: c.size = e * stretch, below = c.size.z; break;
      case CloudShape::Cone: c.size = Vec3(e, e, between(1.5, 3.0) * e); break;
      case CloudShape::Box: c.size = 2 * e * stretch, below = 0.5 * c.size.z; break;
    }
    // The first cloud holds the trunk's top, the others lean out from it: growth reaches every one.
    const double off = k == 0 ? 0.0 : between(0.3, 1.0) * e;
    const double turn = 2 * std::numbers::pi * rng.uniform();
    c.center = m.trunkBase + Vec3(off * std::cos(turn), off * std::sin(turn), top + below * between(0.2, 0.9) - (c.shape == CloudShape::Cone ? 0.2 * e : 0));
    c.points = static_cast<std::uint32_t>(between(200, 2000));
    const double volume = c.shape == CloudShape::Box ? c.size.x * c.size.y * c.size.z
                          : c.shape == CloudShape::Cone ? std::numbers::pi * e * e * c.size.z / 3
                                                        : 4.0 / 3.0 * std::numbers::pi * c.size.x * c.size.y * c.size.z;
    const double spacing = std::cbrt(volume / c.points);
    c.kill = m.segmentLength * between(1.0, 2.5);
    c.influence = std::max(2 * c.kill, spacing * between(2.0, 4.0));  // a point reaches the nodes around it before it dies
    m.clouds.push_back(c);
  }
  const int obstacles = static_cast<int>(between(0, 3));
  for (int k = 0; k < obstacles; ++k) {
    for (int attempt = 0; attempt < 10; ++attempt) {
      sc::Obstacle o;
      o.shape = rng.uniform() < 0.5 ? sc::ObstacleShape::Box : sc::ObstacleShape::Sphere;
      const double r = between(0.1, 0.8);
      o.size = o.shape == sc::ObstacleShape::Sphere ? Vec3(r) : Vec3(between(0.1, 2) * r, between(0.1, 2) * r, between(0.1, 2) * r);
      const double off = between(0.3, 2.5), turn = 2 * std::numbers::pi * rng.uniform();
      o.center = m.trunkBase + Vec3(off * std::cos(turn), off * std::sin(turn), top + between(-0.5, 2.5));
      bool onTrunk = false;  // the reader refuses a trunk inside an obstacle; tested as it tests
      for (int s = 0; s < m.trunkSegments; ++s) {
        const Vec3 a = m.trunkBase + Vec3(0, 0, m.segmentLength * s);
        onTrunk |= sc::segmentHitsObstacle(o, a, a + Vec3(0, 0, m.segmentLength));
      }
      if (!onTrunk) {
        m.obstacles.push_back(o);
        break;
      }
    }
  }
  m.tipRadius = between(0.003, 0.01);
  m.exponent = between(2.0, 3.0);
  m.leafDepth = static_cast<int>(between(-1, 5));
  m.leafLength = between(0.05, 0.2);
  m.leafWidth = m.leafLength * between(0.3, 0.6);
  return TreeModel(std::make_unique<SpaceColonizationParams>(std::move(m)));
}

const SpaceColonization* spaceColonizationOf(const TreeModel& model) {
  const auto* p = dynamic_cast<const SpaceColonizationParams*>(&model.params());
  return p ? &p->parameters_() : nullptr;
}

}  // namespace arbor
