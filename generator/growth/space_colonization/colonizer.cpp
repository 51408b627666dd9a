#include "colonizer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace arbor::sc {

namespace {

double distance2(const Vec3& a, const Vec3& b) {
  const Vec3 d = a - b;
  return glm::dot(d, d);
}

// A node whose attraction vectors cancel out has no direction to grow in (Patrick et al. omit the guard).
constexpr double kZeroSum = 1e-9;
// A new node this near (in segment lengths) to an existing child of its node would lie on top of it.
constexpr double kSameChild = 1e-6;
// Attraction points on both sides of a node, just past the plane halfway to its parent, pull it straight back: a
// new internode turning back more than this (cos 150 degrees) from the one it grows from would fold a twig onto itself.
constexpr double kTurnBack = -0.866;

// The segment arriving at node i: from its parent, or the root's point.
bool segmentTouches(const Obstacle& o, const std::vector<Node>& nodes, std::size_t i) {
  const Node& n = nodes[i];
  const Vec3 from = n.parent < 0 ? n.position : nodes[static_cast<std::size_t>(n.parent)].position;
  return segmentHitsObstacle(o, from, n.position);
}

}  // namespace

std::vector<std::uint32_t> nodesTouching(const Obstacle& o, const std::vector<Node>& nodes, const PointIndex& nodeIndex, double reach) {
  std::vector<std::uint32_t> out;
  const Ball ball = boundingBall(o);
  if (ball.radius < 0) return out;
  // A touching segment has a point in the ball and its node within `reach` of that point. The margin, far above
  // rounding at the coordinates' magnitude, covers segments a few ulps longer than D and exact tests that accept
  // a point a few ulps outside.
  const double far = ball.radius + reach;
  nodeIndex.within(ball.center, far + 1e-6 * (far + glm::length(ball.center)), out);
  std::sort(out.begin(), out.end());
  std::erase_if(out, [&](std::uint32_t i) { return !segmentTouches(o, nodes, i); });
  return out;
}

Vec3 growthDirection(const Vec3& sum, const Vec3& node, const Vec3& trunkBase, double gravity) {
  const Vec3 n = sum / glm::length(sum);
  if (gravity == 0) return n;  // the base algorithm, untouched
  // Gravitropism: farther from the trunk axis, more pull toward the ground (Patrick et al. §3.2).
  const double h = std::hypot(node.x - trunkBase.x, node.y - trunkBase.y);
  const Vec3 bent = n + gravity * h * Vec3(0.0, 0.0, -1.0);
  const double length = glm::length(bent);
  return length > 1e-12 ? bent / length : n;
}

Colonizer::Colonizer(const ColonizerSettings& settings) : settings_(settings) {
  const int segments = std::max(settings.trunkSegments, 1);
  for (int i = 0; i <= segments; ++i) {
    nodes_.push_back({settings.trunkBase + Vec3(0, 0, settings.segmentLength * i), i - 1, 0, true});
    children_.emplace_back();
    if (i > 0) children_[static_cast<std::size_t>(i - 1)].push_back(static_cast<std::uint32_t>(i));
  }
  settle();
}

void Colonizer::addCloud(const AttractionCloud& cloud) {
  endIterationEarly();
  clouds_.push_back(cloud);
  sampleInto(clouds_.size() - 1);
  refreshRadii();
  settle();
}

void Colonizer::replaceCloud(std::size_t index, const AttractionCloud& cloud) {
  endIterationEarly();
  clouds_.at(index) = cloud;
  dropPoints(index);
  sampleInto(index);
  refreshRadii();
  settle();
}

void Colonizer::removeCloud(std::size_t index) {
  if (index >= clouds_.size()) throw std::out_of_range("no cloud " + std::to_string(index));
  endIterationEarly();
  clouds_.erase(clouds_.begin() + static_cast<std::ptrdiff_t>(index));
  dropPoints(index);
  for (AttractionPoint& p : points_)
    if (p.cloud > index) --p.cloud;
  refreshRadii();
  settle();
}

void Colonizer::sampleInto(std::size_t cloud) {
  const auto index = static_cast<std::uint32_t>(cloud);
  for (const Vec3& p : sampleCloud(clouds_[cloud], cloudSeed(settings_.seed, cloud))) points_.push_back({p, index, kAlive});
}

void Colonizer::dropPoints(std::size_t cloud) {
  points_.erase(std::remove_if(points_.begin(), points_.end(), [&](const AttractionPoint& p) { return p.cloud == cloud; }), points_.end());
}

void Colonizer::refreshRadii() {
  maxInfluence_ = maxKill_ = 0;
  for (const AttractionCloud& c : clouds_) {
    maxInfluence_ = std::max(maxInfluence_, c.influence);
    maxKill_ = std::max(maxKill_, c.kill);
  }
}

void Colonizer::addObstacle(const Obstacle& obstacle) {
  endIterationEarly();
  obstacles_.push_back(obstacle);
  settle();
}

void Colonizer::replaceObstacle(std::size_t index, const Obstacle& obstacle) {
  endIterationEarly();
  obstacles_.at(index) = obstacle;
  settle();
}

void Colonizer::removeObstacle(std::size_t index) {
  if (index >= obstacles_.size()) throw std::out_of_range("no obstacle " + std::to_string(index));
  endIterationEarly();
  obstacles_.erase(obstacles_.begin() + static_cast<std::ptrdiff_t>(index));
  settle();
}

void Colonizer::setGravity(double gravity) {
  endIterationEarly();
  settings_.gravity = gravity;
  finished_ = false;
}

void Colonizer::settle() {
  // Touched: a node whose segment touches an obstacle, found through a k-d tree of the nodes.
  std::vector<std::uint8_t> touched(nodes_.size(), 0);
  if (!obstacles_.empty()) {
    std::vector<Vec3> positions(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) positions[i] = nodes_[i].position;
    const PointIndex nodeIndex(std::move(positions));
    for (const Obstacle& o : obstacles_)
      for (const std::uint32_t i : nodesTouching(o, nodes_, nodeIndex, settings_.segmentLength)) touched[i] = 1;
  }
  // Disabled: touched, or below a node that is. Parents come before children, so one pass closes the set under
  // descendants.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    Node& n = nodes_[i];
    const bool parentEnabled = n.parent < 0 || nodes_[static_cast<std::size_t>(n.parent)].enabled;
    n.enabled = parentEnabled && !touched[i];
  }
  reindex();
  closest_.assign(points_.size(), -1);
  closestD2_.assign(points_.size(), std::numeric_limits<double>::infinity());
  live_ = static_cast<std::size_t>(std::count_if(points_.begin(), points_.end(), [](const AttractionPoint& p) { return p.killedAt == kAlive; }));
  // In node order, as growth met them: the same attractions (ties to the older node) as incremental growth.
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (nodes_[i].enabled) noteNode(static_cast<std::uint32_t>(i), age_);
  finished_ = false;
}

void Colonizer::noteNode(std::uint32_t node, std::uint32_t killAge) {
  if (live_ == 0) return;
  const Vec3 v = nodes_[node].position;
  index_.within(v, maxInfluence_, scratch_);  // kill < influence: the kills are among them
  for (const std::uint32_t local : scratch_) {
    const std::uint32_t i = indexed_[local];
    AttractionPoint& p = points_[i];
    if (p.killedAt != kAlive) continue;
    const AttractionCloud& c = clouds_[p.cloud];
    const double d2 = distance2(p.position, v);
    if (d2 < c.kill * c.kill) {
      p.killedAt = killAge;
      closest_[i] = -1;
      --live_;
    } else if (d2 < c.influence * c.influence && d2 < closestD2_[i]) {
      closest_[i] = static_cast<std::int32_t>(node);
      closestD2_[i] = d2;
    }
  }
}

void Colonizer::reindex() {
  indexed_.clear();
  std::vector<Vec3> positions;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (points_[i].killedAt != kAlive) continue;
    indexed_.push_back(static_cast<std::uint32_t>(i));
    positions.push_back(points_[i].position);
  }
  index_ = PointIndex(std::move(positions));
}

void Colonizer::beginIteration() {
  pending_.clear();
  cursor_ = 0;
  added_ = false;
  if (live_ == 0) {
    finished_ = true;
    return;
  }
  // Dead points only slow the searches down; which points a search finds alive stays the same.
  if (2 * live_ < indexed_.size()) reindex();
  std::vector<Vec3> sum(nodes_.size(), Vec3(0.0));
  std::vector<std::uint8_t> attracted(nodes_.size(), 0);
  for (const std::uint32_t i : indexed_) {  // every live point, in point order
    const std::int32_t c = closest_[i];
    if (c < 0 || points_[i].killedAt != kAlive) continue;
    const Vec3 d = points_[i].position - nodes_[static_cast<std::size_t>(c)].position;
    sum[static_cast<std::size_t>(c)] += d / std::sqrt(glm::dot(d, d));
    attracted[static_cast<std::size_t>(c)] = 1;
  }
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (!attracted[n] || !nodes_[n].enabled || glm::length(sum[n]) < kZeroSum) continue;
    pending_.push_back({static_cast<std::uint32_t>(n), growthDirection(sum[n], nodes_[n].position, settings_.trunkBase, settings_.gravity)});
  }
  if (pending_.empty()) finished_ = true;
}

void Colonizer::grow(const Grower& g) {
  const Vec3 from = nodes_[g.node].position;
  const Vec3 to = from + settings_.segmentLength * g.direction;
  const double same = kSameChild * settings_.segmentLength;
  for (const std::uint32_t c : children_[g.node])
    if (distance2(nodes_[c].position, to) < same * same) return;
  if (const std::int32_t parent = nodes_[g.node].parent; parent >= 0) {
    const Vec3 arriving = from - nodes_[static_cast<std::size_t>(parent)].position;
    if (glm::dot(arriving, g.direction) < kTurnBack * glm::length(arriving)) return;
  }
  for (const Obstacle& o : obstacles_)
    if (segmentHitsObstacle(o, from, to)) return;
  const auto node = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({to, static_cast<std::int32_t>(g.node), age_ + 1, true});
  children_[g.node].push_back(node);
  children_.emplace_back();
  added_ = true;
  noteNode(node, age_ + 1);
}

std::size_t Colonizer::step(std::size_t maxNodes, std::uint32_t untilAge) {
  std::size_t processed = 0;
  while (processed < maxNodes && !finished_ && age_ < untilAge) {
    if (cursor_ == pending_.size()) {
      beginIteration();
      if (finished_) break;
    }
    grow(pending_[cursor_++]);
    ++processed;
    if (cursor_ == pending_.size()) {
      // The iteration is complete: it counts as an age if it grew anything; if not, nothing ever will.
      if (added_) ++age_;
      else finished_ = true;
      if (live_ == 0) finished_ = true;
      pending_.clear();
      cursor_ = 0;
      added_ = false;
    }
  }
  return processed;
}

void Colonizer::growToEnd() {
  while (!finished_) step(std::numeric_limits<std::size_t>::max());
}

void Colonizer::endIterationEarly() {
  if (added_) ++age_;
  pending_.clear();
  cursor_ = 0;
  added_ = false;
}

void Colonizer::rewind(std::uint32_t age) {
  endIterationEarly();
  age = std::min(age, age_);
  std::size_t keep = nodes_.size();
  while (keep > 0 && nodes_[keep - 1].age > age) --keep;  // ages never decrease along the node list
  nodes_.resize(keep);
  children_.resize(keep);
  for (auto& list : children_) list.erase(std::remove_if(list.begin(), list.end(), [&](std::uint32_t c) { return c >= keep; }), list.end());
  for (AttractionPoint& p : points_)
    if (p.killedAt != kAlive && p.killedAt > age) p.killedAt = kAlive;
  age_ = age;
  settle();
}

}  // namespace arbor::sc
