// Branch graph -> skeleton: validation, stems by pipe-model weight, pipe-model radii, short internodes
// merged into segments sized to their radius, Laplacian smoothing along stems, parallel-transported frames.
#include "branch_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/mix64.hpp"
#include "common/text_util.hpp"
#include "growth/tree_limits.hpp"

namespace arbor {

namespace {

// Relative tolerance within which two pipe-model weights count as equal (sums in different orders differ).
constexpr double kWeightTie = 1e-9;

std::string idText(const BranchGraph& g, std::size_t i) {
  const std::int64_t id = g.nodes[i].id >= 0 ? g.nodes[i].id : static_cast<std::int64_t>(i);
  return std::to_string(id);
}

std::string nodeField(const BranchGraph& g, std::size_t i, const char* what) {
  return "nodes[id " + idText(g, i) + "]" + (*what ? std::string(".") + what : std::string());
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The smallest rotation taking unit vector a to unit vector b (a half turn about some normal of a if opposite).
Quat minimalRotation(const Vec3& a, const Vec3& b) {
  const double c = glm::dot(a, b);
  if (c < -1.0 + 1e-12) {
    Vec3 axis = glm::cross(a, Vec3(1.0, 0.0, 0.0));
    if (glm::dot(axis, axis) < 1e-12) axis = glm::cross(a, Vec3(0.0, 1.0, 0.0));
    return glm::angleAxis(3.14159265358979323846, glm::normalize(axis));
  }
  const Vec3 axis = glm::cross(a, b);
  return glm::normalize(Quat(1.0 + c, axis.x, axis.y, axis.z));
}

double treeSize(const BranchGraph& g) {
  Vec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const BranchNode& n : g.nodes) {
    lo = glm::min(lo, n.position);
    hi = glm::max(hi, n.position);
  }
  return glm::distance(lo, hi);
}

struct Topology {
  std::size_t root = 0;
  std::vector<std::size_t> order;                // breadth first from the root: parents before children
  std::vector<std::vector<std::size_t>> children;
};

Topology topologyOf(const BranchGraph& g) {
  Topology t;
  t.children.resize(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int p = g.nodes[i].parent;
    if (p < 0) t.root = i;
    else t.children[static_cast<std::size_t>(p)].push_back(i);
  }
  t.order.reserve(g.nodes.size());
  t.order.push_back(t.root);
  for (std::size_t k = 0; k < t.order.size(); ++k) {
    for (std::size_t c : t.children[t.order[k]]) t.order.push_back(c);
  }
  return t;
}

}  // namespace

void validateBranchGraph(const BranchGraph& g, const std::string& file) {
  const std::size_t n = g.nodes.size();
  if (n < 2) throw GraphError(file, "nodes", "a tree needs at least two nodes (one internode); got " + std::to_string(n));
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 2)) {
    throw GraphError(file, "nodes", "more than " + std::to_string(std::numeric_limits<std::int32_t>::max() / 2) + " nodes");
  }
  std::size_t roots = 0, root = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const BranchNode& node = g.nodes[i];
    if (!finite(node.position)) throw GraphError(file, nodeField(g, i, "position"), "not finite; give three finite numbers");
    if (!std::isfinite(node.radius)) throw GraphError(file, nodeField(g, i, "radius"), "not finite; give a radius > 0, or none");
    if (node.parent < -1 || node.parent >= static_cast<std::int64_t>(n) || node.parent == static_cast<std::int64_t>(i)) {
      throw GraphError(file, nodeField(g, i, "parent"), "unknown parent; give the id of another node, or -1 for the root");
    }
    if (node.parent >= 0) continue;
    if (++roots == 2) {
      throw GraphError(file, nodeField(g, i, "parent"),
                       "a second root (node " + idText(g, root) + " is one); a tree has exactly one node with parent -1");
    }
    root = i;
  }
  if (roots == 0) throw GraphError(file, "nodes", "no root; exactly one node must have parent -1");

  const Topology t = topologyOf(g);
  if (t.order.size() != n) {
    // Nodes the root does not reach hang from a cycle: walk up from one of them until a node repeats.
    std::vector<bool> reached(n, false);
    for (std::size_t i : t.order) reached[i] = true;
    std::size_t i = 0;
    while (reached[i]) ++i;
    std::vector<bool> seen(n, false);
    while (!seen[i]) {
      seen[i] = true;
      i = static_cast<std::size_t>(g.nodes[i].parent);
    }
    throw GraphError(file, nodeField(g, i, "parent"), "is on a cycle of parents; a tree's parents lead to the root");
  }

  const double size = treeSize(g);
  for (std::size_t i = 0; i < n; ++i) {
    const int p = g.nodes[i].parent;
    if (p < 0) continue;
    const double length = glm::distance(g.nodes[i].position, g.nodes[static_cast<std::size_t>(p)].position);
    if (!(length > kZeroLength * size)) {
      throw GraphError(file, nodeField(g, i, "position"),
                       "the internode from its parent (node " + idText(g, static_cast<std::size_t>(p)) + ") has length " + formatNumber(length) +
                           "; internodes must be longer than 1e-9 of the tree's size (" + formatNumber(size) + ")");
    }
  }

  for (std::size_t k = 0; k < g.leaves.size(); ++k) {
    const GraphLeaf& leaf = g.leaves[k];
    const std::string field = "leaves[" + std::to_string(k) + "]";
    if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) throw GraphError(file, field + ".node", "unknown node; give a node's id");
    if (!finite(leaf.position) || !finite(leaf.direction) || !finite(leaf.normal)) {
      throw GraphError(file, field, "not finite; give finite positions and directions");
    }
    if (glm::length(leaf.direction) < 1e-12) throw GraphError(file, field + ".direction", "zero; give the direction along the blade");
    if (!(leaf.length >= 0.0) || !(leaf.width >= 0.0) || !std::isfinite(leaf.length) || !std::isfinite(leaf.width)) {
      throw GraphError(file, field, "length and width must be finite and >= 0");
    }
    if (leaf.kind > 3) throw GraphError(file, field + ".kind", "allowed 0 (broad), 1 (narrow), 2 (frond) or 3 (needle)");
  }
}

std::vector<double> pipeRadii(const BranchGraph& g, const GraphOptions& o) {
  const Topology t = topologyOf(g);
  std::vector<double> weight(g.nodes.size(), 0.0);
  for (auto it = t.order.rbegin(); it != t.order.rend(); ++it) {
    const std::size_t i = *it;
    double sum = 0.0;
    for (std::size_t c : t.children[i]) sum += weight[c];
    if (t.children[i].empty()) sum = std::pow(o.tipRadius, o.exponent);
    const double given = g.nodes[i].radius;
    weight[i] = given > 0.0 ? std::max(sum, std::pow(given, o.exponent)) : sum;
  }
  std::vector<double> radius(weight.size());
  for (std::size_t i = 0; i < weight.size(); ++i) radius[i] = std::pow(weight[i], 1.0 / o.exponent);
  return radius;
}

namespace {

class Converter {
 public:
  Converter(const BranchGraph& g, const GraphOptions& o, Skeleton& out) : g_(g), o_(o), out_(out), t_(topologyOf(g)) {}

  void run(std::vector<std::int32_t>* nodeMap) {
    const std::size_t n = g_.nodes.size();
    size_ = treeSize(g_);
    radius_ = pipeRadii(g_, o_);
    weight_.resize(n);
    for (std::size_t i = 0; i < n; ++i) weight_[i] = std::pow(radius_[i], o_.exponent);
    chooseContinuations();
    leaving_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) leavingRadii(i);
    position_.resize(n);
    for (std::size_t i = 0; i < n; ++i) position_[i] = g_.nodes[i].position;
    skeletonNode_.assign(n, -1);
    nearest_.assign(n, -1);
    buildStems();
    if (nodeMap) *nodeMap = skeletonNode_;
    addLeaves();
    double reach = 0.0;
    for (const SkeletonNode& s : out_.nodes) reach = std::max(reach, glm::distance(s.world.position, g_.nodes[t_.root].position));
    out_.treeScale = reach;
  }

 private:
  const BranchGraph& g_;
  const GraphOptions& o_;
  Skeleton& out_;
  Topology t_;
  double size_ = 0.0;
  std::vector<double> radius_, weight_;
  std::vector<std::ptrdiff_t> next_;   // per node: the child continuing its stem (-1: a tip)
  std::vector<double> leaving_;        // per node: start radius of the internode arriving here
  std::vector<Vec3> position_;         // after smoothing
  std::vector<std::int32_t> skeletonNode_, nearest_;  // own skeleton node; last kept one at or before it

  Vec3 incoming(std::size_t i) const {
    const int p = g_.nodes[i].parent;
    if (p < 0) return kUp;
    return glm::normalize(g_.nodes[i].position - g_.nodes[static_cast<std::size_t>(p)].position);
  }

  // The continuing child: largest pipe-model weight, then the smallest angle to the incoming direction.
  void chooseContinuations() {
    next_.assign(g_.nodes.size(), -1);
    for (std::size_t i = 0; i < g_.nodes.size(); ++i) {
      const auto& cs = t_.children[i];
      if (cs.empty()) continue;
      const Vec3 in = incoming(i);
      std::size_t best = cs[0];
      for (std::size_t k = 1; k < cs.size(); ++k) {
        const std::size_t c = cs[k];
        const double scale = std::max(weight_[c], weight_[best]);
        if (weight_[c] > weight_[best] + kWeightTie * scale) {
          best = c;
        } else if (weight_[c] >= weight_[best] - kWeightTie * scale) {
          const double straight = glm::dot(glm::normalize(g_.nodes[c].position - g_.nodes[i].position), in);
          const double bestStraight = glm::dot(glm::normalize(g_.nodes[best].position - g_.nodes[i].position), in);
          if (straight > bestStraight) best = c;
        }
      }
      next_[i] = static_cast<std::ptrdiff_t>(best);
    }
  }

  // Children leave a node with their own radii scaled so that r^E = sum of start radii^E holds exactly there
  // (the scale is >= 1: the node's weight is at least their sum).
  void leavingRadii(std::size_t i) {
    const auto& cs = t_.children[i];
    if (cs.size() == 1) {
      leaving_[cs[0]] = radius_[i];
      return;
    }
    double sum = 0.0;
    for (std::size_t c : cs) sum += weight_[c];
    const double scale = std::pow(weight_[i] / sum, 1.0 / o_.exponent);
    for (std::size_t c : cs) leaving_[c] = radius_[c] * scale;
  }

  bool fixedNode(std::size_t i) const { return t_.children[i].size() != 1; }  // branch point or tip

  struct PendingStem {
    std::size_t first = 0;     // first graph node of its own
    std::int32_t attach = -1;  // skeleton node it leaves from (-1: a trunk on the ground)
    std::int32_t parentStem = -1;
    int level = 0;
  };

  void buildStems() {
    std::vector<PendingStem> queue;
    const std::size_t root = t_.root;
    if (needsHub()) {
      // Several internodes leave the root, or the trunk branches right above it (where a trunk standing on the
      // ground has no tube yet to connect to): the trunks leave a Root hub.
      SkeletonNode hub;
      hub.kind = NodeKind::Root;
      hub.radius = hub.startRadius = radius_[root];
      hub.world.position = hub.local.position = position_[root];
      out_.nodes.push_back(hub);
      skeletonNode_[root] = nearest_[root] = 0;
      for (std::size_t c : t_.children[root]) queue.push_back(PendingStem{c, 0, -1, 0});
    } else {
      queue.push_back(PendingStem{root, -1, -1, 0});
    }
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const PendingStem pending = queue[k];
      buildStem(pending, queue);
    }
    int levels = 0;
    for (const SkeletonStem& s : out_.stems) levels = std::max(levels, s.level + 1);
    out_.levels = levels;
  }

  bool needsHub() const {
    const std::size_t root = t_.root;
    if (t_.children[root].size() > 1) return true;
    double arc = 0.0;
    for (std::size_t i = root; next_[i] >= 0;) {
      const auto c = static_cast<std::size_t>(next_[i]);
      arc += glm::distance(g_.nodes[c].position, g_.nodes[i].position);
      if (arc > 1.0 * radius_[root]) return false;
      if (t_.children[c].size() > 1) return true;
      i = c;
    }
    return false;
  }

  // The polyline of a stem in graph nodes: its attach node (if any), then its own nodes to the tip.
  std::vector<std::size_t> chainOf(const PendingStem& p) const {
    std::vector<std::size_t> chain;
    if (p.attach >= 0) chain.push_back(static_cast<std::size_t>(g_.nodes[p.first].parent));
    for (std::ptrdiff_t i = static_cast<std::ptrdiff_t>(p.first); i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      chain.push_back(static_cast<std::size_t>(i));
    }
    return chain;
  }

  // Jacobi passes of p_i += w ((p_{i-1} + p_{i+1}) / 2 - p_i) over the free nodes (not branch points, tips,
  // the root or the attach node); a pass that would bring two nodes together is not taken for that node.
  void smooth(const std::vector<std::size_t>& chain) {
    if (o_.smoothingPasses <= 0 || chain.size() < 3) return;
    std::vector<Vec3> p(chain.size()), q;
    for (std::size_t k = 0; k < chain.size(); ++k) p[k] = position_[chain[k]];
    for (int pass = 0; pass < o_.smoothingPasses; ++pass) {
      q = p;
      for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
        if (fixedNode(chain[k])) continue;
        const Vec3 moved = p[k] + o_.smoothingWeight * (0.5 * (p[k - 1] + p[k + 1]) - p[k]);
        const double floor = 1e-6 * size_;
        if (glm::distance(moved, q[k - 1]) > floor && glm::distance(moved, p[k + 1]) > floor) q[k] = moved;
      }
      p.swap(q);
    }
    for (std::size_t k = 1; k + 1 < chain.size(); ++k) position_[chain[k]] = p[k];
  }

  // Radius with which the stem leaves chain[k] towards chain[k + 1].
  double leavingAt(const std::vector<std::size_t>& chain, std::size_t k) const { return leaving_[chain[k + 1]]; }

  // Largest distance of chain[a + 1 .. b - 1] from the segment chain[a] -> chain[b].
  double deviation(const std::vector<std::size_t>& chain, std::size_t a, std::size_t b) const {
    const Vec3 p0 = position_[chain[a]], d = position_[chain[b]] - p0;
    const double dd = glm::dot(d, d);
    double worst = 0.0;
    for (std::size_t k = a + 1; k < b; ++k) {
      const Vec3 v = position_[chain[k]] - p0;
      const double t = dd > 0.0 ? std::clamp(glm::dot(v, d) / dd, 0.0, 1.0) : 0.0;
      worst = std::max(worst, glm::length(v - t * d));
    }
    return worst;
  }

  // Indices into the chain of the nodes kept: the first, every branch point, the tip, and between them
  // the fewest nodes that keep segments minSegment..maxSegment radii long and the dropped nodes within
  // maxDeviation radii of them (segments shorter than minSegment are always merged).
  std::vector<std::size_t> merge(const std::vector<std::size_t>& chain) const {
    std::vector<std::size_t> kept{0};
    const std::size_t last = chain.size() - 1;
    auto fixed = [&](std::size_t k) { return k == 0 || k == last || fixedNode(chain[k]); };
    std::size_t a = 0;
    while (a < last) {
      const double r = leavingAt(chain, a);
      const double lo = o_.minSegment * r, hi = o_.maxSegment * r;
      std::size_t b = a + 1;
      while (!fixed(b)) {
        if (glm::distance(position_[chain[b]], position_[chain[a]]) < lo) {
          ++b;
          continue;
        }
        const std::size_t c = b + 1;
        if (glm::distance(position_[chain[c]], position_[chain[a]]) <= hi && deviation(chain, a, c) <= o_.maxDeviation * r) {
          b = c;
          continue;
        }
        break;
      }
      // A short segment into a fixed node takes the free node before it away instead.
      if (fixed(b) && kept.size() > 1 && !fixed(a) && glm::distance(position_[chain[b]], position_[chain[a]]) < lo) {
        kept.pop_back();
      }
      kept.push_back(b);
      a = b;
    }
    return kept;
  }

  void buildStem(const PendingStem& p, std::vector<PendingStem>& queue) {
    std::vector<std::size_t> chain = chainOf(p);
    smooth(chain);
    const std::vector<std::size_t> kept = merge(chain);
    const bool grounded = p.attach < 0;
    const auto stemIndex = static_cast<std::int32_t>(out_.stems.size());

    SkeletonStem stem;
    stem.level = static_cast<std::int16_t>(p.level);
    stem.parentStem = p.parentStem;
    stem.attachNode = p.attach;
    stem.firstNode = static_cast<std::int32_t>(out_.nodes.size());
    stem.key = mix64(0x6772617068ULL + static_cast<std::uint64_t>(g_.nodes[p.first].id >= 0 ? g_.nodes[p.first].id : static_cast<std::int64_t>(p.first)));

    // Directions: each kept node's leaving edge, the tip's arriving one; frames by parallel transport.
    Quat frame{1.0, 0.0, 0.0, 0.0};
    Vec3 previousDir = kUp;
    double offset = 0.0;
    if (!grounded) {
      const SkeletonNode& attach = out_.nodes[static_cast<std::size_t>(p.attach)];
      frame = attach.world.rotation;
      previousDir = attach.world.direction();
      stem.offsetOnParent = attach.offset;
    }
    std::int32_t parentNode = p.attach;
    for (std::size_t j = grounded ? 0 : 1; j < kept.size(); ++j) {
      const std::size_t gi = chain[kept[j]];
      const Vec3 pos = position_[gi];
      const Vec3 dir = j + 1 < kept.size() ? glm::normalize(position_[chain[kept[j + 1]]] - pos)
                                            : glm::normalize(pos - position_[chain[kept[j - 1]]]);
      frame = glm::normalize(minimalRotation(previousDir, dir) * frame);
      previousDir = dir;
      if (j > 0) offset += glm::distance(pos, position_[chain[kept[j - 1]]]);

      SkeletonNode node;
      node.parent = parentNode;
      node.stem = stemIndex;
      node.level = stem.level;
      node.offset = offset;
      node.radius = radius_[gi];
      node.startRadius = j == 0 ? radius_[gi] : leaving_[chain[kept[j - 1] + 1]];
      if (j == 0) node.kind = NodeKind::Base;
      else if (j + 1 == kept.size()) node.kind = NodeKind::Tip;
      else node.kind = t_.children[gi].size() > 1 ? NodeKind::Attachment : NodeKind::Joint;
      node.world = Transform{pos, frame};
      node.local = parentNode < 0 ? node.world : compose(inverse(out_.nodes[static_cast<std::size_t>(parentNode)].world), node.world);
      parentNode = static_cast<std::int32_t>(out_.nodes.size());
      skeletonNode_[gi] = parentNode;
      out_.nodes.push_back(node);
    }
    stem.nodeCount = static_cast<std::int32_t>(out_.nodes.size()) - stem.firstNode;
    stem.length = offset;
    const SkeletonNode& first = out_.nodes[static_cast<std::size_t>(stem.firstNode)];
    stem.startRadius = first.startRadius;
    if (!grounded) {
      const SkeletonNode& attach = out_.nodes[static_cast<std::size_t>(p.attach)];
      const Vec3 firstDir = glm::normalize(first.world.position - attach.world.position);
      stem.secondaryAngle = std::acos(std::clamp(glm::dot(firstDir, attach.world.direction()), -1.0, 1.0));
      const std::size_t at = chain[0];
      if (next_[at] >= 0 && p.parentStem >= 0) stem.branchRatio = stem.startRadius / leaving_[static_cast<std::size_t>(next_[at])];
      // The root's heaviest trunk is always meshed (without it there may be no mesh); other trunks ending
      // inside the hub are stubs like children ending inside their parent.
      const bool mainTrunk = p.parentStem < 0 && static_cast<std::ptrdiff_t>(p.first) == next_[t_.root];
      if (!mainTrunk) {
        stem.stub = endsInsideParent(stem, attach) || (p.parentStem >= 0 && out_.stems[static_cast<std::size_t>(p.parentStem)].stub) ||
                    insideAnotherStem(stem, p.parentStem);
      }
    }

    // Nodes merged away hang (for leaves) from the last kept node before them; children start new stems.
    std::int32_t nearest = grounded ? -1 : p.attach;
    for (std::size_t k = grounded ? 0 : 1; k < chain.size(); ++k) {
      const std::size_t gi = chain[k];
      if (skeletonNode_[gi] >= 0) nearest = skeletonNode_[gi];
      nearest_[gi] = nearest;
      for (std::size_t c : t_.children[gi]) {
        if (static_cast<std::ptrdiff_t>(c) != next_[gi]) queue.push_back(PendingStem{c, skeletonNode_[gi], stemIndex, p.level + 1});
      }
    }
    out_.stems.push_back(std::move(stem));
  }

  // Distance from p to the stem's polyline (from its attach node on) against the stem's radius there: below 1, p
  // lies in that stem's wood.
  double woodDepth(const SkeletonStem& stem, const Vec3& p) const {
    double depth = 1e300;
    std::int32_t from = stem.attachNode >= 0 ? stem.attachNode : stem.firstNode;
    for (std::int32_t i = stem.firstNode; i < stem.firstNode + stem.nodeCount; from = i++) {
      const SkeletonNode& a = out_.nodes[static_cast<std::size_t>(from)];
      const SkeletonNode& b = out_.nodes[static_cast<std::size_t>(i)];
      const Vec3 d = b.world.position - a.world.position;
      const double dd = glm::dot(d, d);
      const double t = dd > 0.0 ? std::clamp(glm::dot(p - a.world.position, d) / dd, 0.0, 1.0) : 0.0;
      const double r = (1.0 - t) * (from == stem.attachNode ? b.startRadius : a.radius) + t * b.radius;
      if (r > 0.0) depth = std::min(depth, glm::distance(p, a.world.position + t * d) / r);
    }
    return depth;
  }

  // A stem whose every node lies in the wood of its parent (a child drawn along its parent's own continuation)
  // or of a thicker sibling leaving the same node (an L-system drawing one branch twice) has no surface of its own.
  bool insideAnotherStem(const SkeletonStem& stem, std::int32_t parentStem) const {
    auto inside = [&](const SkeletonStem& other) {
      for (std::int32_t i = stem.firstNode; i < stem.firstNode + stem.nodeCount; ++i) {
        if (woodDepth(other, out_.nodes[static_cast<std::size_t>(i)].world.position) > 1.0) return false;
      }
      return true;
    };
    if (parentStem >= 0 && inside(out_.stems[static_cast<std::size_t>(parentStem)])) return true;
    // Stems leaving one node are queued together, so its earlier siblings are the last stems made.
    for (auto it = out_.stems.rbegin(); it != out_.stems.rend() && it->attachNode == stem.attachNode; ++it) {
      if (!it->stub && it->startRadius >= stem.startRadius && inside(*it)) return true;
    }
    return false;
  }

  // A stem whose every node lies within 1.5 radii of its parent's attach node has no tube outside its
  // parent: the mesh leaves it to the fake branches, as it does Weber-Penn's stubs.
  bool endsInsideParent(const SkeletonStem& stem, const SkeletonNode& attach) const {
    const double reach = 1.5 * attach.radius;
    for (std::int32_t i = stem.firstNode; i < stem.firstNode + stem.nodeCount; ++i) {
      if (glm::distance(out_.nodes[static_cast<std::size_t>(i)].world.position, attach.world.position) > reach) return false;
    }
    return true;
  }

  void addLeaves() {
    out_.leaves.reserve(g_.leaves.size());
    for (const GraphLeaf& gl : g_.leaves) {
      const auto gi = static_cast<std::size_t>(gl.node);
      const std::int32_t node = nearest_[gi];
      Leaf leaf;
      leaf.node = node;
      leaf.stem = out_.nodes[static_cast<std::size_t>(node)].stem;
      if (leaf.stem < 0) leaf.stem = 0;  // the root hub belongs to no stem: its leaves go with the first trunk
      leaf.position = gl.position + (position_[gi] - g_.nodes[gi].position);  // leaves follow smoothing
      leaf.direction = glm::normalize(gl.direction);
      Vec3 normal = gl.normal - leaf.direction * glm::dot(gl.normal, leaf.direction);
      if (glm::length(normal) < 1e-9) normal = kUp - leaf.direction * glm::dot(kUp, leaf.direction);
      if (glm::length(normal) < 1e-9) normal = glm::cross(leaf.direction, Vec3(1.0, 0.0, 0.0));
      if (glm::length(normal) < 1e-9) normal = glm::cross(leaf.direction, Vec3(0.0, 1.0, 0.0));
      normal = glm::normalize(normal);
      leaf.normal = normal.z < 0.0 ? -normal : normal;  // the upper face shows to the sky
      leaf.length = gl.length;
      leaf.width = gl.width;
      leaf.kind = gl.kind;
      out_.leaves.push_back(leaf);
    }
  }
};

}  // namespace

Skeleton graphToSkeleton(const BranchGraph& graph, const GraphOptions& options, std::vector<std::int32_t>* nodeMap) {
  validateBranchGraph(graph);
  Skeleton out;
  out.species = options.species;
  out.exponent = options.exponent;
  out.nodes.reserve(graph.nodes.size() + 1);
  Converter(graph, options, out).run(nodeMap);
  return out;
}

}  // namespace arbor
