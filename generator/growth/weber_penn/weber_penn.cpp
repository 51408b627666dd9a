// Weber & Penn's stem algorithm, grown level by level. Each stem draws from its own random streams keyed
// by its place in the tree, so levels below the deepest one never see the random draws of deeper levels.
#include "weber_penn.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/parallel.hpp"
#include "natural_rules.hpp"
#include "growth/random.hpp"
#include "weber_penn_rules.hpp"

namespace arbor {

int RawStem::segmentOf(double z) const {
  const int s = static_cast<int>(std::floor(z / segmentLength()));
  return std::clamp(s, firstSegment, lastSegment());
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::uint64_t kStreamPlacement = 4;
constexpr double kMinStemLength = 1e-5;  // Arbaro's shortest stem: every child longer than this grows
constexpr double kEstimateMargin = 16.0;   // refuse before growing only trees estimated this far past a limit

// Geometry of one stem and its clones for a trial length (pruning grows several before keeping one).
struct Grown {
  std::uint64_t key = 0;
  int firstSegment = 0;
  Transform base;
  std::vector<Transform> joints;
  bool split = false;
  std::vector<Grown> clones;
};

// Round half up: the rule used for error diffusion of fractional counts.
long roundHalfUp(double x) { return static_cast<long>(std::floor(x + 0.5)); }

class Grower {
 public:
  Grower(const SpeciesParams& p, const GrowthOptions& o, RawTree& tree)
      : p_(p), options_(o), tree_(tree), levels_(o.levels > 0 ? o.levels : p.levels), E_(p.treeShapeExponent),
        splitError_(static_cast<std::size_t>(levels_ + 1), 0.0), childError_(static_cast<std::size_t>(levels_ + 1), 0.0) {}

  void run() {
    // Hopeless trees are refused from their parameters; the estimate runs high (it cannot see the children
    // that pruning and the slenderness rules drop), so only trees far past the limits go here.
    const TreeEstimate estimate = estimateTree(p_, levels_);
    const std::string excess = estimate.excess(options_.limits, kEstimateMargin);
    if (!excess.empty()) throw GenerationError(excess);
    // Room for the estimate (within 15 % on Arbaro's files) and a quarter more: grown by doubling, the willow's
    // 250,000 leaves and 28,000 stems touched twice their memory. Pages past what is grown are never touched.
    // At least `least`, at most the limit (which may be the smaller: a test's limits are tiny).
    auto room = [](double expected, std::size_t limit, std::size_t least) {
      const std::size_t wanted = expected > 0.0 ? static_cast<std::size_t>(std::min(1.25 * expected, 1e12)) : 0;
      return std::min(std::max(wanted, least), limit);
    };
    tree_.stems.reserve(room(estimate.stems, options_.limits.nodes, 1024));
    tree_.leaves.reserve(room(estimate.leaves, options_.limits.leaves, 4096));
    growTrunks();
    // Breadth-first: every stem of level n exists before any of level n + 1.
    std::size_t levelBegin = 0;
    for (int level = 1; level <= levels_; ++level) {
      const std::size_t levelEnd = tree_.stems.size();
      for (std::size_t i = levelBegin; i < levelEnd; ++i) {
        if (level < levels_) growChildrenOf(static_cast<int>(i));
        else growLeavesOn(static_cast<int>(i));  // also settles the radii of the deepest clones
      }
      levelBegin = levelEnd;
    }
    turnLeaves();
  }

 private:
  const SpeciesParams& p_;
  const GrowthOptions& options_;
  RawTree& tree_;
  const int levels_;
  const double E_;
  std::size_t nodesMade_ = 0;
  std::size_t walked_ = 0;  // joints visited by the envelope walk under way
  // Rounding errors of fractional counts, one per level and shared by all its stems in the order they are made
  // (as Arbaro's LevelParams keeps them): a level splits SegSplits times per joint on average, whatever the stem.
  std::vector<double> splitError_;
  std::vector<double> childError_;  // children of the level's stems, per segment
  double leafError_ = 0.0;

  // Nodes are counted as they are made, clones included, so memory never runs past the limit's share.
  void countNodes(std::size_t n) {
    nodesMade_ += n;
    if (nodesMade_ > options_.limits.nodes) throw GenerationError(tooManyNodes());
  }

  // Names what was grown when the limit was reached, level by level: the levels to look at.
  std::string tooManyNodes() const {
    std::vector<std::size_t> stems;
    for (const RawStem& s : tree_.stems) {
      if (stems.size() <= static_cast<std::size_t>(s.level)) stems.resize(static_cast<std::size_t>(s.level) + 1);
      ++stems[static_cast<std::size_t>(s.level)];
    }
    std::string grown;
    for (std::size_t l = 0; l < stems.size(); ++l) grown += (l ? ", " : "") + std::to_string(stems[l]) + " on level " + std::to_string(l);
    return "the tree would have more than " + std::to_string(options_.limits.nodes) + " nodes (stems grown when it was reached: " +
           grown + "); lower Levels, Branches, SegSplits or CurveRes";
  }

  // Bend applied when entering segment s (Weber-Penn Curve / CurveBack / CurveV), radians.
  static double curveAngle(const StemLevelParams& lp, int s, Rng& rng) {
    double degreesPerSegment = 0.0;
    if (lp.curveBack == 0.0) {
      degreesPerSegment = lp.curve / lp.curveRes;
    } else {
      const double half = lp.curveRes / 2.0;
      degreesPerSegment = (s < half ? lp.curve : lp.curveBack) / half;
    }
    return radians(degreesPerSegment + lp.curveV / lp.curveRes * rng.signedUnit());
  }

  // Turn a direction towards the sky (AttractionUp > 0) or the ground, never past the vertical.
  Quat attract(const Quat& q, int curveRes) const {
    const Vec3 d = q * Vec3(0, 0, 1);
    const double declination = std::acos(std::clamp(d.z, -1.0, 1.0));
    const Vec3 axis = glm::cross(d, kUp);
    const double axisLength = glm::length(axis);
    if (axisLength < 1e-12) return q;
    double angle = p_.attractionUp * declination * std::sin(declination) / curveRes;
    angle = std::clamp(angle, -(kPi - declination), declination);
    return glm::angleAxis(angle, axis / axisLength) * q;
  }

  // Walks one stem's segments: curvature, attraction and clone splits. onJoint(s, frame) sees the end of each
  // segment s and may stop the walk by returning false; onClone(key, base, firstSegment) sees each clone, which
  // must walk at once: the split error is the level's, drawn from in the order the pieces are walked.
  template <class OnJoint, class OnClone>
  bool walkStem(std::uint64_t key, int level, const Transform& base, double length, int firstSegment,
                double& splitError, OnJoint&& onJoint, OnClone&& onClone) const {
    const StemLevelParams& lp = p_.level(level);
    Rng rng(key, kStreamGeometry);
    const double segLength = length / lp.curveRes;
    Transform frame = base;
    for (int s = firstSegment; s < lp.curveRes; ++s) {
      const Vec3 end = frame.position + frame.direction() * segLength;
      if (s == lp.curveRes - 1) return onJoint(s, Transform{end, frame.rotation});  // tip keeps the arriving direction
      Quat next = frame.rotation * rotationX(curveAngle(lp, s + 1, rng));
      if (level >= 2 && p_.attractionUp != 0.0) next = attract(next, lp.curveRes);
      if (!onJoint(s, Transform{end, next})) return false;

      int splits = 0;
      if (level == 0 && s == 0 && firstSegment == 0 && p_.baseSplits > 0) {
        splits = p_.baseSplits;
      } else if (lp.segSplits > 0.0) {
        splits = static_cast<int>(roundHalfUp(lp.segSplits + splitError));
        splitError += lp.segSplits - splits;
      }
      if (splits > 0) {
        const int n = splits + 1;
        const double spin = rng.uniform() * 2.0 * kPi;
        for (int i = 0; i < n; ++i) {
          const double theta = p_.angleRule == AngleRule::Natural
                                   ? natural::cloneAngle(n, E_)
                                   : radians(lp.splitAngle + lp.splitAngleV * rng.signedUnit());
          const double psi = spin + 2.0 * kPi * i / n;
          // Tilt by theta towards azimuth psi without spinning the clone's frame about its own axis.
          const Quat tilt = rotationZ(psi) * rotationX(theta) * rotationZ(-psi);
          const std::uint64_t cloneKey = childKey(key, kKeyClone, static_cast<std::uint64_t>(s) * 64 + i);
          if (!onClone(cloneKey, Transform{end, next * tilt}, s + 1)) return false;
        }
        return true;
      }
      frame = Transform{end, next};
    }
    return true;
  }

  Grown growGeometry(std::uint64_t key, int level, const Transform& base, double length, int firstSegment) {
    Grown g;
    g.key = key;
    g.firstSegment = firstSegment;
    g.base = base;
    g.joints.reserve(static_cast<std::size_t>(p_.level(level).curveRes - firstSegment));
    walkStem(
        key, level, base, length, firstSegment, splitError_[static_cast<std::size_t>(level)],
        [&](int, const Transform& joint) {
          countNodes(1);
          g.joints.push_back(joint);
          return true;
        },
        [&](std::uint64_t cloneKey, const Transform& cloneBase, int cloneFirst) {
          g.split = true;
          g.clones.push_back(growGeometry(cloneKey, level, cloneBase, length, cloneFirst));
          return true;
        });
    return g;
  }

  // The first segment whose end leaves the envelope, of the stem or any of its clones; -1 if all lie inside.
  // A walk visits at most the nodes the stem will be grown with, so it is bounded by what the limit leaves.
  int firstOutside(std::uint64_t key, int level, const Transform& base, double length, int firstSegment,
                   double& splitError) {
    int outside = -1;
    walkStem(
        key, level, base, length, firstSegment, splitError,
        [&](int s, const Transform& joint) {
          if (++walked_ + nodesMade_ > options_.limits.nodes) throw GenerationError(tooManyNodes());
          if (wp::insideEnvelope(p_, tree_.treeScale, joint.position.x, joint.position.y, joint.position.z)) return true;
          outside = s;
          return false;
        },
        [&](std::uint64_t cloneKey, const Transform& cloneBase, int cloneFirst) {
          outside = firstOutside(cloneKey, level, cloneBase, length, cloneFirst, splitError);
          return outside < 0;
        });
    return outside;
  }

  // Arbaro's pruning: while the stem (on the very same draws, and the level's split error as it stands) leaves
  // the envelope, cut it back to the segments that fit, by at least 1/15 and at most half of it at a time; then
  // keep PruneRatio of the cut.
  double prunedLength(std::uint64_t key, int level, const Transform& base, double length) {
    if (p_.pruneRatio <= 0.0 || level == 0) return length;
    const int curveRes = p_.level(level).curveRes;
    auto outside = [&](double trial) {
      walked_ = 0;
      double error = splitError_[static_cast<std::size_t>(level)];  // a trial must not use up the level's error
      return firstOutside(key, level, base, trial, 0, error);
    };
    double trial = length;
    int segment = outside(trial);
    while (segment >= 0 && trial > 0.001 * tree_.treeScale) {  // at least length / 15 off per step: it ends
      trial = std::min(std::max(trial / curveRes * segment, 0.5 * trial), trial - length / 15.0);
      if (trial > kMinStemLength) segment = outside(trial);
    }
    return length - (length - trial) * p_.pruneRatio;
  }

  // Appends a grown stem and, after it, its clones (so sources always precede their clones).
  int commit(const Grown& g, const RawStem& proto) {
    const int index = static_cast<int>(tree_.stems.size());
    RawStem stem = proto;
    stem.key = g.key;
    stem.firstSegment = g.firstSegment;
    stem.base = g.base;
    stem.joints = g.joints;
    stem.endsInSplit = g.split;
    tree_.stems.push_back(std::move(stem));
    countNodes(1);  // its base; the joints were counted as they were grown
    for (const Grown& c : g.clones) {
      RawStem cloneProto = proto;
      cloneProto.cloneOf = index;
      const int ci = commit(c, cloneProto);
      tree_.stems[static_cast<std::size_t>(index)].clones.push_back(ci);
    }
    return index;
  }

  void growTrunks() {
    Rng treeRng(mix64(options_.seed), kStreamTree);
    // Arbaro files allow ScaleV == Scale; a tree of size ~0 helps nobody, so sizes stop at 5 % of Scale.
    tree_.treeScale = std::max(0.05 * p_.scale, p_.scale + p_.scaleV * treeRng.signedUnit());
    tree_.baseLength = p_.baseSize * tree_.treeScale;
    const StemLevelParams& lp = p_.level(0);
    const int trunks = static_cast<int>(lp.branches);
    double azimuth = 0.0, side = 1.0;
    for (int t = 0; t < trunks; ++t) {
      const std::uint64_t key = childKey(options_.seed, kKeyTrunk, static_cast<std::uint64_t>(t));
      Rng place(key, kStreamPlacement);
      const double length = std::max(1e-6, (lp.length + lp.lengthV * place.signedUnit()) * tree_.treeScale);
      const double trunkScale = std::max(0.05 * p_.trunkScale, p_.trunkScale + p_.trunkScaleV * place.signedUnit());
      const double radius = length * p_.ratio * trunkScale;
      Transform base;
      if (trunks > 1) {
        azimuth = nextAzimuth(lp.rotate, lp.rotateV, azimuth, side, treeRng);
        base.rotation = rotationZ(azimuth) * rotationX(radians(lp.downAngle + lp.downAngleV * place.signedUnit()));
      }
      RawStem proto;
      proto.level = 0;
      proto.length = length;
      proto.curveRes = lp.curveRes;
      proto.profile = makeStemProfile(lp.taper, length, radius, p_.flare);
      proto.naturalStart = radius;
      proto.startRadius = radius * proto.profile.at(0.0);
      // One of several trunks thinner than the mesher's floor (LengthV can shrink it to 1e-6 m) is a stub, drawn
      // as a card with its children: its hub port was a point, and the tube's corners came out not a number.
      proto.stub = trunks > 1 && proto.startRadius < 1e-5 * tree_.treeScale;
      commit(growGeometry(key, 0, base, length, 0), proto);
    }
  }

  // Weber-Penn rotation about the parent: a running spiral, or alternating sides when Rotate < 0.
  static double nextAzimuth(double rotate, double rotateV, double azimuth, double& side, Rng& rng) {
    const double variation = rotateV * rng.signedUnit();
    if (rotate >= 0.0) return azimuth + radians(rotate + variation);
    side = -side;
    return side * radians(180.0 + rotate + variation);
  }

  // Classic DownAngle; a negative DownAngleV varies it along the parent instead of at random.
  double classicDownAngle(const StemLevelParams& lp, double variation, double parentLength, double parentBase,
                          double z) const {
    if (lp.downAngleV >= 0.0) return radians(lp.downAngle + lp.downAngleV * variation);
    const double span = parentLength - parentBase;
    const double ratio = span > 0.0 ? (parentLength - z) / span : 0.0;
    return radians(lp.downAngle + lp.downAngleV * (1.0 - 2.0 * wp::shapeRatio(0, ratio)));
  }

  // Clones continue their source's natural radius, divided among the n clones.
  void inheritNaturalStart(int index) {
    RawStem& stem = tree_.stems[static_cast<std::size_t>(index)];
    if (stem.cloneOf < 0) return;
    const RawStem& source = tree_.stems[static_cast<std::size_t>(stem.cloneOf)];
    const double factor = natural::cloneRadiusFactor(static_cast<int>(source.clones.size()), E_);
    stem.naturalStart = source.naturalEnd * factor;
    stem.startRadius = stem.naturalStart * stem.profile.at(stem.startZ());
  }

  // Segment s's stretch [a, b] of arc length where children may grow.
  void childRange(const RawStem& stem, int s, double& a, double& b) const {
    const double seg = stem.segmentLength();
    a = s * seg;
    b = (s + 1) * seg;
    if (stem.level == 0) a = std::max(a, tree_.baseLength);
  }

  void growChildrenOf(int parentIndex) {
    inheritNaturalStart(parentIndex);
    const auto pi = static_cast<std::size_t>(parentIndex);
    const int level = tree_.stems[pi].level + 1;
    const StemLevelParams& lp = p_.level(level);
    Rng rng(tree_.stems[pi].key, kStreamChildren);

    {
      RawStem& parent = tree_.stems[pi];
      if (parent.cloneOf < 0) {
        parent.lengthChildMax = lp.length + lp.lengthV * rng.signedUnit();
        double count = 0.0;
        if (parent.level == 0) count = wp::childCountOfTrunk(lp.branches);
        else if (parent.level == 1)
          count = wp::childCountOfLevel1(lp.branches, parent.length, parent.parentLength, parent.parentLengthChildMax);
        else count = wp::childCountOfDeeper(lp.branches, parent.offsetOnParent, parent.parentLength);
        count = std::floor(count);  // a whole number of children per stem, as Arbaro counts them
        double coverage = 0.0;
        for (int s = 0; s < parent.curveRes; ++s) {
          double a = 0, b = 0;
          childRange(parent, s, a, b);
          coverage += std::max(0.0, b - a) / parent.segmentLength();
        }
        parent.childRate = coverage > 0.0 ? count / coverage : 0.0;
      } else {
        const RawStem& source = tree_.stems[static_cast<std::size_t>(parent.cloneOf)];
        parent.lengthChildMax = source.lengthChildMax;
        // The pieces of a split stem share its children: as many grow on them together as on the unsplit stem.
        parent.childRate = source.childRate / static_cast<double>(source.clones.size());
        parent.childAzimuth = source.childAzimuth + kPi;
        parent.childSide = source.childSide;
      }
    }

    const bool natural = p_.angleRule == AngleRule::Natural;
    const double S = p_.branchRatio(level);
    const double Cp = natural::primaryRadiusFactor(S, E_);
    const double Cs = natural::secondaryRadiusFactor(S, E_);
    const double murrayY = natural::secondaryAngle(1.0, Cp, Cs);
    const double murrayX = natural::primaryAngle(1.0, Cp, Cs);

    double naturalRadius = tree_.stems[pi].naturalStart;
    double& error = childError_[static_cast<std::size_t>(level - 1)];
    double azimuth = tree_.stems[pi].childAzimuth;
    double side = tree_.stems[pi].childSide;
    const int firstSegment = tree_.stems[pi].firstSegment, lastSegment = tree_.stems[pi].lastSegment();

    for (int s = firstSegment; s <= lastSegment; ++s) {
      double a = 0, b = 0;
      childRange(tree_.stems[pi], s, a, b);
      if (b <= a) continue;
      const double expected = tree_.stems[pi].childRate * (b - a) / tree_.stems[pi].segmentLength();
      const long n = std::max(0L, roundHalfUp(expected + error));
      error += expected - static_cast<double>(n);
      for (long j = 0; j < n; ++j) {
        const double z = a + (static_cast<double>(j) + 0.5) / static_cast<double>(n) * (b - a);
        const std::uint64_t slot = tree_.stems[pi].childSlots++;
        azimuth = nextAzimuth(lp.rotate, lp.rotateV, azimuth, side, rng);
        const double downVariation = rng.signedUnit();

        const RawStem& parent = tree_.stems[pi];
        const Transform segment = parent.frameAt(s, z);
        const double incoming = naturalRadius * parent.profile.at(z);
        const double length0 = level == 1 ? wp::childLengthOfTrunk(p_, parent.lengthChildMax, parent.length,
                                                                    tree_.baseLength, z)
                                          : wp::childLengthOfDeeper(parent.lengthChildMax, parent.length, z);
        const double angle = natural ? murrayY
                                     : classicDownAngle(lp, downVariation, parent.length,
                                                        parent.level == 0 ? tree_.baseLength : 0.0, z);
        const std::uint64_t key = childKey(parent.key, kKeyChild, slot);
        const Transform base{segment.position, segment.rotation * rotationZ(azimuth) * rotationX(angle)};
        const double length = prunedLength(key, level, base, length0);
        const double childRadius = Cs * incoming;
        if (!wp::childGrows(length, childRadius)) continue;

        RawStem proto;
        proto.level = level;
        proto.parent = parentIndex;
        proto.length = length;
        proto.curveRes = lp.curveRes;
        proto.offsetOnParent = z;
        proto.parentLength = parent.length;
        proto.parentLengthChildMax = parent.lengthChildMax;
        proto.profile = makeStemProfile(lp.taper, length, childRadius, 0.0);
        proto.naturalStart = childRadius;
        proto.startRadius = childRadius;
        proto.parentRadius = incoming;
        proto.branchRatio = S;
        proto.secondaryAngle = angle;
        proto.deflection = natural ? murrayX : 0.0;
        proto.stub = parent.stub || wp::stubby(length, incoming, childRadius, tree_.treeScale);
        const int child = commit(growGeometry(key, level, base, length, 0), proto);
        tree_.stems[pi].attachments.push_back(
            RawAttachment{z, child, azimuth, incoming, Cp, natural ? murrayX : 0.0});
        countNodes(3);
        naturalRadius *= Cp;
      }
    }
    RawStem& parent = tree_.stems[pi];
    settleTail(parent);
    parent.childAzimuth = azimuth;
    parent.childSide = side;
    parent.naturalEnd = naturalRadius;
  }

  // Blade frame relative to the segment: along the blade z, face normal y turned towards the sky by LeafBend.
  Quat leafRotation(const Quat& segment, double azimuth, double down) const {
    Quat local = rotationZ(azimuth) * rotationX(down);
    const Quat world = segment * local;
    const Vec3 blade = world * Vec3(0, 0, 1);
    Vec3 normal = world * Vec3(0, 1, 0);
    if (normal.z < 0.0) normal = -normal;  // bend the face that will show to the sky
    Vec3 target = kUp - blade * glm::dot(kUp, blade);
    const double targetLength = glm::length(target);
    if (p_.leafBend <= 0.0 || targetLength < 1e-9) return local;
    target /= targetLength;
    const double angle = std::acos(std::clamp(glm::dot(normal, target), -1.0, 1.0));
    const double sign = glm::dot(glm::cross(normal, target), blade) >= 0.0 ? 1.0 : -1.0;
    return local * rotationZ(sign * p_.leafBend * angle);
  }

  // The taper shapes what follows the last child; a stem that splits has no tail (its clones go on).
  static void settleTail(RawStem& stem) {
    const double lastChild = stem.attachments.empty() ? stem.startZ() : stem.attachments.back().z;
    stem.profile.tailStart = stem.endsInSplit ? stem.length : std::max(stem.startZ(), lastChild);
  }

  // The blades' turns from the draws (three sines and cosines and an arc cosine a leaf: the larch file has 172,000),
  // shared by the cores once every draw is made in order.
  // Until then a leaf's rotation holds its draws (drawsOf): a second array of them changed the heap enough that the
  // viewer's frames afterwards took 70 % more page faults.
  void turnLeaves() {
    inParallelRuns(tree_.leaves.size(), 8192, [&](std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        RawLeaf& leaf = tree_.leaves[i];
        const Quat draws = leaf.rotation;
        const Quat segment = tree_.stems[static_cast<std::size_t>(leaf.stem)].frameAt(static_cast<int>(draws.y), leaf.z).rotation;
        leaf.rotation = leafRotation(segment, draws.w, draws.x);
      }
    });
  }

  // A leaf's draws kept in its rotation until turnLeaves: azimuth, down angle and segment (exact as doubles).
  static Quat drawsOf(double azimuth, double down, int segment) { return Quat(azimuth, down, static_cast<double>(segment), 0.0); }

  void growLeavesOn(int stemIndex) {
    inheritNaturalStart(stemIndex);
    RawStem& stem = tree_.stems[static_cast<std::size_t>(stemIndex)];
    stem.naturalEnd = stem.naturalStart;
    settleTail(stem);
    if (stem.level == 0 || p_.leaves == 0.0) return;
    Rng rng(stem.key, kStreamLeaves);
    const double q = p_.leafQuality;
    const double leafLength = p_.leafScale / std::sqrt(q);
    const double leafWidth = leafLength * p_.leafScaleX;
    const double count = wp::leafCount(p_, stem.offsetOnParent, stem.parentLength);

    if (stem.cloneOf < 0) {
      stem.leafRate = count / stem.curveRes;
    } else {
      const RawStem& source = tree_.stems[static_cast<std::size_t>(stem.cloneOf)];
      stem.leafRate = source.leafRate;  // unlike children, each piece of a split stem has the whole stem's leaves
      stem.leafAzimuth = source.leafAzimuth + kPi;
      stem.leafSide = source.leafSide;
    }

    auto addLeaf = [&](int s, double z, double azimuth, double down) {
      tree_.leaves.push_back(RawLeaf{stemIndex, z, drawsOf(azimuth, down, s), leafLength, leafWidth, p_.leafStemLen * leafLength});
      if (tree_.leaves.size() > options_.limits.leaves) {
        throw GenerationError("the tree would have more than " + std::to_string(options_.limits.leaves) +
                              " leaves; lower Leaves or LeafQuality, or the stems of the deepest level");
      }
    };

    if (p_.leaves < 0.0) {  // a fan at the tip of each stem that does not split
      if (stem.endsInSplit) return;
      const long n = roundHalfUp(count);
      for (long i = 0; i < n; ++i) {
        addLeaf(stem.lastSegment(), stem.length, 2.0 * kPi * static_cast<double>(i) / static_cast<double>(n),
                radians(p_.leafDownAngle));
      }
      return;
    }

    double azimuth = stem.leafAzimuth, side = stem.leafSide;
    for (int s = stem.firstSegment; s <= stem.lastSegment(); ++s) {
      const long n = std::max(0L, roundHalfUp(stem.leafRate + leafError_));  // the tree's error, shared as in Arbaro
      leafError_ += stem.leafRate - static_cast<double>(n);
      const double a = s * stem.segmentLength();
      for (long j = 0; j < n; ++j) {
        const double z = a + (static_cast<double>(j) + 0.5) / static_cast<double>(n) * stem.segmentLength();
        azimuth = nextAzimuth(p_.leafRotate, p_.leafRotateV, azimuth, side, rng);
        const double variation = rng.signedUnit();
        double down = radians(p_.leafDownAngle + p_.leafDownAngleV * variation);
        if (p_.leafDownAngleV < 0.0) {
          const double ratio = (stem.length - z) / stem.length;
          down = radians(p_.leafDownAngle + p_.leafDownAngleV * (1.0 - 2.0 * wp::shapeRatio(0, ratio)));
        }
        addLeaf(s, z, azimuth, down);
      }
    }
    stem.leafAzimuth = azimuth;
    stem.leafSide = side;
  }
};

}  // namespace

RawTree growRawTree(const SpeciesParams& params, const GrowthOptions& options) {
  RawTree tree;
  Grower(params, options, tree).run();
  return tree;
}

Skeleton generateSkeleton(const SpeciesParams& params, const GrowthOptions& options) {
  return buildSkeleton(growRawTree(params, options), params, options);
}

}  // namespace arbor
