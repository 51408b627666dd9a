// Raw tree -> skeleton (Nystad 4.2): nodes at segment ends and attachments, intermediate nodes around
// each attachment, natural-rule radii, and the primary deflection applied to relative transforms.
#include <algorithm>
#include <cmath>

#include "common/parallel.hpp"
#include "weber_penn.hpp"

namespace arbor {

namespace {

// Intermediate nodes sit at 10 % of a segment from the attachment (Nystad's 10 % rule), and only where
// the neighbouring node is more than three times that away, so they never crowd each other.
constexpr double kIntermediateFraction = 0.1;
constexpr double kIntermediateRoom = 3.0;

struct Station {
  double z = 0;
  NodeKind kind = NodeKind::Joint;
  int index = -1;  // joint index or attachment index
};

class Builder {
 public:
  Builder(const RawTree& raw, const SpeciesParams& p, Skeleton& out) : raw_(raw), p_(p), out_(out) {}

  void run() {
    attachNode_.assign(raw_.stems.size(), -1);
    rawFrame_.reserve(out_.nodes.capacity());
    maybeAddRoot();
    for (std::size_t i = 0; i < raw_.stems.size(); ++i) buildStem(static_cast<int>(i));
    addLeaves();
  }

 private:
  const RawTree& raw_;
  const SpeciesParams& p_;
  Skeleton& out_;
  std::vector<Transform> rawFrame_;  // undeflected object-space frame of each node
  std::vector<int> attachNode_;      // per raw stem: the node its first edge leaves from
  int root_ = -1;

  int addNode(SkeletonNode node, const Transform& rawFrame, const Quat* deflection) {
    const int index = static_cast<int>(out_.nodes.size());
    if (node.parent < 0) {
      node.local = rawFrame;
      node.world = rawFrame;
    } else {
      const auto parent = static_cast<std::size_t>(node.parent);
      node.local = compose(inverse(rawFrame_[parent]), rawFrame);
      if (deflection) node.local = Transform{*deflection * node.local.position, *deflection * node.local.rotation};
      node.world = compose(out_.nodes[parent].world, node.local);
    }
    out_.nodes.push_back(node);
    rawFrame_.push_back(rawFrame);
    return index;
  }

  void maybeAddRoot() {
    int trunks = 0;
    double sum = 0.0;
    for (const RawStem& s : raw_.stems) {
      if (s.level == 0 && s.cloneOf < 0) {
        ++trunks;
        sum += std::pow(s.startRadius, p_.treeShapeExponent);
      }
    }
    if (trunks < 2) return;
    // Several trunks meet in one root node so the tree stays one connected piece.
    SkeletonNode root;
    root.kind = NodeKind::Root;
    root.radius = root.startRadius = std::pow(sum, 1.0 / p_.treeShapeExponent);
    root_ = addNode(root, Transform{}, nullptr);
  }

  std::vector<Station> stationsOf(const RawStem& st) const {
    std::vector<Station> primary;
    const double seg = st.segmentLength();
    for (std::size_t j = 0; j < st.joints.size(); ++j) {
      const bool last = j + 1 == st.joints.size();
      const NodeKind kind = last ? (st.endsInSplit ? NodeKind::Split : NodeKind::Tip) : NodeKind::Joint;
      primary.push_back(Station{(st.firstSegment + static_cast<double>(j) + 1.0) * seg, kind, static_cast<int>(j)});
    }
    for (std::size_t k = 0; k < st.attachments.size(); ++k) {
      primary.push_back(Station{st.attachments[k].z, NodeKind::Attachment, static_cast<int>(k)});
    }
    std::stable_sort(primary.begin(), primary.end(), [](const Station& a, const Station& b) { return a.z < b.z; });

    const double delta = kIntermediateFraction * seg;
    std::vector<Station> all;
    const bool ownBase = st.level == 0 && st.cloneOf < 0 && root_ < 0;
    if (ownBase) {
      all.push_back(Station{0.0, NodeKind::Base, -1});
    } else {
      // First node of a child or clone: just outside the parent's surface, unless something is closer.
      const double d = std::max(delta, st.parentRadius);
      if (!primary.empty() && d < 0.7 * (primary.front().z - st.startZ())) {
        all.push_back(Station{st.startZ() + d, NodeKind::After, -1});
      }
    }
    for (std::size_t i = 0; i < primary.size(); ++i) {
      const Station& s = primary[i];
      if (s.kind != NodeKind::Attachment) { all.push_back(s); continue; }
      const double previous = i > 0 ? primary[i - 1].z : st.startZ();
      const double next = i + 1 < primary.size() ? primary[i + 1].z : st.length;
      const double lastPlaced = all.empty() ? st.startZ() : all.back().z;
      if (s.z - previous > kIntermediateRoom * delta && s.z - delta > lastPlaced) {
        all.push_back(Station{s.z - delta, NodeKind::Before, -1});
      }
      all.push_back(s);
      if (next - s.z > kIntermediateRoom * delta) all.push_back(Station{s.z + delta, NodeKind::After, -1});
    }
    return all;
  }

  Transform frameOf(const RawStem& st, const Station& s) const {
    if (s.kind == NodeKind::Joint || s.kind == NodeKind::Tip || s.kind == NodeKind::Split) {
      return st.joints[static_cast<std::size_t>(s.index)];
    }
    if (s.kind == NodeKind::Base) return st.base;
    return st.frameAt(st.segmentOf(s.z), s.z);
  }

  void buildStem(int stemIndex) {
    const RawStem& st = raw_.stems[static_cast<std::size_t>(stemIndex)];
    SkeletonStem stem;
    stem.key = st.key;
    stem.level = static_cast<std::int16_t>(st.level);
    stem.parentStem = st.parent;
    stem.cloneOf = st.cloneOf;
    stem.length = st.length;
    stem.startOffset = st.startZ();
    stem.offsetOnParent = st.offsetOnParent;
    stem.startRadius = st.startRadius;
    stem.branchRatio = st.branchRatio;
    stem.secondaryAngle = st.secondaryAngle;
    stem.primaryDeflection = st.deflection;
    stem.firstSegment = st.firstSegment;
    stem.stub = st.stub;
    stem.rawJoints.reserve(st.joints.size() + 1);
    stem.rawJoints.push_back(st.base);
    stem.rawJoints.insert(stem.rawJoints.end(), st.joints.begin(), st.joints.end());

    int previous = attachNode_[static_cast<std::size_t>(stemIndex)];
    if (st.level == 0 && st.cloneOf < 0) previous = root_;
    stem.attachNode = previous;
    stem.firstNode = static_cast<int>(out_.nodes.size());

    double natural = st.naturalStart;
    double leaving = st.startRadius;   // radius with which the next edge leaves the previous node
    const RawAttachment* pendingDeflection = nullptr;
    for (const Station& s : stationsOf(st)) {
      SkeletonNode node;
      node.parent = previous;
      node.stem = static_cast<int>(out_.stems.size());
      node.level = static_cast<std::int16_t>(st.level);
      node.kind = s.kind;
      node.offset = s.z;
      node.radius = natural * st.profile.at(s.z);
      node.startRadius = previous < 0 ? node.radius : leaving;
      if (s.kind == NodeKind::Base) node.startRadius = node.radius = st.startRadius;

      Quat deflection{1, 0, 0, 0};
      if (pendingDeflection) {
        // The primary turns away from the child by Murray's x, about the axis the child tilted around.
        const Vec3 axis = rotationZ(pendingDeflection->azimuth) * Vec3(1, 0, 0);
        deflection = glm::angleAxis(-pendingDeflection->deflection, axis);
      }
      const int index = addNode(node, frameOf(st, s), pendingDeflection ? &deflection : nullptr);
      pendingDeflection = nullptr;
      leaving = out_.nodes[static_cast<std::size_t>(index)].radius;

      if (s.kind == NodeKind::Attachment) {
        const RawAttachment& a = st.attachments[static_cast<std::size_t>(s.index)];
        attachNode_[static_cast<std::size_t>(a.child)] = index;
        natural *= a.primaryFactor;
        leaving = natural * st.profile.at(s.z);
        if (a.deflection != 0.0) pendingDeflection = &a;
      }
      if (s.kind == NodeKind::Split) {
        for (int c : st.clones) attachNode_[static_cast<std::size_t>(c)] = index;
      }
      previous = index;
    }
    stem.nodeCount = static_cast<int>(out_.nodes.size()) - stem.firstNode;
    out_.stems.push_back(std::move(stem));
  }

  // Leaves hang from the last node at or below them on their stem, so they follow its deflections. A needle tree's
  // hundred thousand and more are placed in runs shared by the cores (the larch file's took 12 of its 45 ms).
  void addLeaves() {
    out_.leaves.resize(raw_.leaves.size());
    inParallelRuns(raw_.leaves.size(), 8192, [&](std::size_t from, std::size_t to) { placeLeaves(from, to); });
  }

  // Leaves [from, to). A run may start within a stem: its walk starts afresh there and ends on the same node.
  void placeLeaves(std::size_t from, std::size_t to) {
    int cursorStem = -1, cursor = -1;  // leaves of a stem arrive in z order: walk its nodes once
    int deltaNode = -1;
    Transform delta;
    for (std::size_t li = from; li < to; ++li) {
      const RawLeaf& rl = raw_.leaves[li];
      const RawStem& st = raw_.stems[static_cast<std::size_t>(rl.stem)];
      const SkeletonStem& stem = out_.stems[static_cast<std::size_t>(rl.stem)];
      if (rl.stem != cursorStem || (cursor >= stem.firstNode && out_.nodes[static_cast<std::size_t>(cursor)].offset > rl.z)) {
        cursorStem = rl.stem;
        cursor = stem.attachNode;
      }
      const int end = stem.firstNode + stem.nodeCount;
      for (int i = std::max(cursor + 1, stem.firstNode); i < end && out_.nodes[static_cast<std::size_t>(i)].offset <= rl.z; ++i) {
        cursor = i;
      }
      const int node = cursor;
      const Transform segment = st.frameAt(st.segmentOf(rl.z), rl.z);
      const Quat rotation = segment.rotation * rl.rotation;
      const Vec3 blade = rotation * Vec3(0, 0, 1);
      const Vec3 axis = segment.direction();
      Vec3 radial = blade - axis * glm::dot(blade, axis);
      const double radialLength = glm::length(radial);
      radial = radialLength > 1e-12 ? radial / radialLength : Vec3(0.0);
      const double stemRadius = st.naturalStart * st.profile.at(rl.z);
      const Transform rawLeaf{segment.position + radial * stemRadius + blade * rl.stemLength, rotation};

      Leaf leaf;
      leaf.stem = rl.stem;
      leaf.node = node;
      if (node != deltaNode) {  // how deflections moved this node: applied to every leaf hanging from it
        deltaNode = node;
        delta = compose(out_.nodes[static_cast<std::size_t>(node)].world, inverse(rawFrame_[static_cast<std::size_t>(node)]));
      }
      Transform world = compose(delta, rawLeaf);
      // Show the upper face to the sky: half a turn about the blade where the normal points down.
      if ((world.rotation * Vec3(0, 1, 0)).z < 0.0) world.rotation = world.rotation * Quat(0.0, 0.0, 0.0, 1.0);
      leaf.position = world.position;
      leaf.direction = world.rotation * Vec3(0, 0, 1);
      leaf.normal = world.rotation * Vec3(0, 1, 0);
      leaf.length = rl.length;
      leaf.width = rl.width;
      leaf.kind = static_cast<std::uint8_t>(p_.leafShape);
      out_.leaves[li] = leaf;
    }
  }
};

}  // namespace

Skeleton buildSkeleton(const RawTree& raw, const SpeciesParams& params, const GrowthOptions& options) {
  Skeleton out;
  out.species = params.name;
  out.seed = options.seed;
  out.levels = options.levels > 0 ? options.levels : params.levels;
  out.treeScale = raw.treeScale;
  out.exponent = params.treeShapeExponent;
  out.lobes = params.lobes;
  out.lobeDepth = params.lobeDepth;
  out.nodes.reserve(raw.stems.size() * 6);
  Builder(raw, params, out).run();
  return out;
}

}  // namespace arbor
