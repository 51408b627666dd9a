#pragma once
// Space colonization (Runions, Lane & Prusinkiewicz 2007) with Patrick, Rege & Bailey's artistic control: a
// growth state that pauses after any number of nodes, takes new clouds and obstacles, and rewinds to any age.
#include <cstdint>
#include <limits>
#include <vector>

#include "attraction_cloud.hpp"
#include "obstacle.hpp"
#include "point_index.hpp"

namespace arbor::sc {

struct ColonizerSettings {
  double segmentLength = 1.0;  // D: every segment this long
  double gravity = 0.0;        // gravitropism weight per unit of horizontal distance from the trunk axis
  Vec3 trunkBase{0.0};         // the trunk grows straight up from here; its vertical line is the trunk axis
  int trunkSegments = 1;
  std::uint64_t seed = 1;      // the clouds' points
};

struct Node {
  Vec3 position{0.0};
  std::int32_t parent = -1;
  std::uint32_t age = 0;  // the growth iteration that added it (the trunk: 0)
  bool enabled = true;    // false inside an obstacle or below a node that is
};

inline constexpr std::uint32_t kAlive = std::numeric_limits<std::uint32_t>::max();

struct AttractionPoint {
  Vec3 position{0.0};
  std::uint32_t cloud = 0;
  std::uint32_t killedAt = kAlive;  // the iteration whose node killed it; kAlive while it attracts
};

// The direction a node grows: the normalised sum of unit vectors to its points (`sum`), bent down by
// gravitropism `gravity` x the node's horizontal distance from the trunk axis, normalised. Weight 0 returns
// the normalised sum untouched (the base algorithm, bit for bit).
Vec3 growthDirection(const Vec3& sum, const Vec3& node, const Vec3& trunkBase, double gravity);

// The nodes whose segment (from its parent; the root's is the node itself) touches the obstacle, ascending: the
// obstacle tests answered by a k-d tree of nodes. `nodeIndex` indexes the nodes' positions by node number;
// `reach` is the longest segment. A node farther than that from the obstacle's bounding ball cannot touch it,
// so only the nodes the index finds within that distance get the exact test: the answer is brute force's.
std::vector<std::uint32_t> nodesTouching(const Obstacle& obstacle, const std::vector<Node>& nodes, const PointIndex& nodeIndex, double reach);

class Colonizer {
 public:
  explicit Colonizer(const ColonizerSettings& settings);

  // Edits. Each ends an iteration in progress where it stands and leaves the invariants holding (no live point
  // within kill distance of an enabled node; the disabled set closed under descendants).
  void addCloud(const AttractionCloud& cloud);  // its points from cloudSeed(seed, its index)
  // The modeller's moves and resizes: the cloud's points sampled anew (same stream, so a moved cloud's points
  // move with it); the nodes stay where they are.
  void replaceCloud(std::size_t index, const AttractionCloud& cloud);
  void removeCloud(std::size_t index);  // its points go; later clouds move down one index
  void replaceObstacle(std::size_t index, const Obstacle& obstacle);
  void addObstacle(const Obstacle& obstacle);
  void removeObstacle(std::size_t index);
  void setGravity(double gravity);

  // Grows until `maxNodes` nodes have been processed (Patrick et al.'s step size), iteration `untilAge` has
  // completed, or growth has ended; returns the nodes processed. Pausing anywhere gives the same tree as one run.
  std::size_t step(std::size_t maxNodes, std::uint32_t untilAge = std::numeric_limits<std::uint32_t>::max());
  void growToEnd();
  bool finished() const { return finished_; }

  // Back to the state after iteration `age`: later nodes dropped, points they killed alive again.
  void rewind(std::uint32_t age);

  std::uint32_t age() const { return age_; }  // iterations completed
  const ColonizerSettings& settings() const { return settings_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<AttractionPoint>& points() const { return points_; }
  const std::vector<AttractionCloud>& clouds() const { return clouds_; }
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  const std::vector<std::vector<std::uint32_t>>& children() const { return children_; }
  std::size_t livePoints() const { return live_; }
  // The enabled node a live point attracts (the closest within its influence radius), or -1.
  std::int32_t attractedNode(std::size_t point) const { return closest_[point]; }

 private:
  struct Grower {
    std::uint32_t node;
    Vec3 direction;
  };

  void beginIteration();
  void grow(const Grower& g);
  void endIterationEarly();
  void settle();                 // after an edit or a rewind: flags, kills and attractions from scratch
  void noteNode(std::uint32_t node, std::uint32_t killAge);  // kills and attracts the points around it
  void reindex();                // the index over the live points only
  void sampleInto(std::size_t cloud);  // appends the cloud's points, alive
  void dropPoints(std::size_t cloud);  // removes the cloud's points
  void refreshRadii();                 // the largest influence and kill radii over the clouds

  ColonizerSettings settings_;
  std::vector<Node> nodes_;
  std::vector<std::vector<std::uint32_t>> children_;
  std::vector<AttractionCloud> clouds_;
  std::vector<AttractionPoint> points_;
  std::vector<Obstacle> obstacles_;
  PointIndex index_;                     // over the points alive when it was built ...
  std::vector<std::uint32_t> indexed_;   // ... these, by the index's own numbering
  std::vector<std::int32_t> closest_;    // per point: its node, or -1
  std::vector<double> closestD2_;        // per point: squared distance to it
  double maxInfluence_ = 0, maxKill_ = 0;
  std::size_t live_ = 0;
  std::uint32_t age_ = 0;
  std::vector<Grower> pending_;  // the iteration in progress: its growers and directions, fixed at its start
  std::size_t cursor_ = 0;
  bool added_ = false;           // the iteration in progress has added a node
  bool finished_ = false;
  std::vector<std::uint32_t> scratch_;
};

}  // namespace arbor::sc
