#include "skeleton_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "common/json_writer.hpp"
#include "json_fields.hpp"

namespace arbor {

// How far a file's radii may stray from da Vinci's rule (relative): Arbor writes them within 1e-15.
constexpr double kRadiusRule = 1e-3;

namespace {

void writeVec(JsonWriter& w, const char* name, const Vec3& v) {
  w.key(name);
  w.vec3(v.x, v.y, v.z);
}

std::string hexKey(std::uint64_t key) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(key));
  return buf;
}

}  // namespace

std::string writeSkeletonJson(const Skeleton& s) {
  std::ostringstream out;
  writeSkeletonJson(s, out);
  return out.str();
}

void writeSkeletonJson(const Skeleton& s, std::ostream& out) {
  constexpr std::size_t kChunk = 1 << 20;
  JsonWriter w(2);
  w.beginObject();
  w.field("format", "arbor-skeleton/1");
  w.field("species", s.species);
  w.field("seed", static_cast<std::int64_t>(s.seed));
  w.field("levels", s.levels);
  w.field("treeScale", s.treeScale);
  w.field("treeShapeExponent", s.exponent);
  w.field("lobes", s.lobes);
  w.field("lobeDepth", s.lobeDepth);

  w.key("nodes").beginArray();
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const SkeletonNode& n = s.nodes[i];
    w.beginObject();
    w.field("id", static_cast<std::int64_t>(i));
    w.field("parent", n.parent);
    w.field("stem", n.stem);
    w.field("level", n.level);
    w.field("kind", nodeKindName(n.kind));
    w.field("offset", n.offset);
    writeVec(w, "position", n.world.position);
    writeVec(w, "direction", n.world.direction());
    w.field("radius", n.radius);
    w.field("startRadius", n.startRadius);
    w.endObject();
    if (w.pending() > kChunk) w.flushTo(out);
  }
  w.endArray();

  w.key("stems").beginArray();
  for (std::size_t i = 0; i < s.stems.size(); ++i) {
    const SkeletonStem& st = s.stems[i];
    w.beginObject();
    w.field("id", static_cast<std::int64_t>(i));
    w.field("key", hexKey(st.key));
    w.field("level", st.level);
    w.field("parent", st.parentStem);
    w.field("cloneOf", st.cloneOf);
    w.field("attachNode", st.attachNode);
    w.field("firstNode", st.firstNode);
    w.field("nodeCount", st.nodeCount);
    w.field("length", st.length);
    w.field("offsetOnParent", st.offsetOnParent);
    w.field("startRadius", st.startRadius);
    w.field("branchRatio", st.branchRatio);
    w.field("secondaryAngle", degrees(st.secondaryAngle));
    w.field("primaryDeflection", degrees(st.primaryDeflection));
    w.field("stub", st.stub);
    w.endObject();
  }
  w.endArray();

  w.key("leaves").beginArray();
  for (const Leaf& l : s.leaves) {
    w.beginObject();
    w.field("stem", l.stem);
    w.field("node", l.node);
    writeVec(w, "position", l.position);
    writeVec(w, "direction", l.direction);
    writeVec(w, "normal", l.normal);
    w.field("length", l.length);
    w.field("width", l.width);
    w.field("kind", static_cast<int>(l.kind));
    w.endObject();
    if (w.pending() > kChunk) w.flushTo(out);
  }
  w.endArray();
  w.endObject();
  w.flushTo(out);
}

}  // namespace arbor

// ---- reading ----

namespace arbor {

namespace {

using namespace json_fields;

double ulpStep(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, 1e300);
  for (; k < 0; ++k) v = std::nextafter(v, -1e300);
  return v;
}

int alternating(int i) { return (i + 1) / 2 * (i % 2 ? 1 : -1); }  // 0, 1, -1, 2, -2, ...

// A rotation taking +z to the unit vector d, roll-free where its direction() reads back d bit for bit. The
// file has no roll, so where it does not, rotations with a small roll are searched for one that does (this
// finds one for all but about 3 directions in 10,000; those keep the roll-free one, off by an ulp or two).
Quat rotationTo(const Vec3& d) {
  const Vec3 z(0.0, 0.0, 1.0);
  if (d.z < -1.0 + 1e-12) return Quat(0.0, 1.0, 0.0, 0.0);  // a half turn about x
  const Quat rollFree = glm::normalize(Quat(1.0 + d.z, -d.y, d.x, 0.0));
  if (rollFree * z == d) return rollFree;
  // x^2 + y^2 = (1 - d.z) / 2 split unevenly (the smaller part fine-tunes the rounding), then w and the roll
  // component solved from d.x and d.y and searched ulp by ulp.
  const double s = 0.5 * (1.0 - d.z);
  for (int k = 1; k <= 64; ++k) {
    for (int swap = 0; swap < 2; ++swap) {
      const double big = std::sqrt(s * (1.0 - 0.001 * k));
      const double small = std::sqrt(std::max(s - big * big, 0.0));
      const double x = swap ? small : big, y = swap ? big : small;
      const double det = x * x + y * y;
      if (det <= 0.0) continue;
      const double w = (y * d.x - x * d.y) / (2.0 * det), roll = (x * d.x + y * d.y) / (2.0 * det);
      for (int a = 0; a <= 8; ++a) {
        for (int b = 0; b <= 8; ++b) {
          const Quat q(ulpStep(w, alternating(a)), x, y, ulpStep(roll, alternating(b)));
          if (q * z == d) return q;
        }
      }
    }
  }
  return rollFree;
}

// The radians whose degrees() is exactly `deg` (the file holds degrees; the skeleton radians).
double radiansExact(double deg) {
  const double r = radians(deg);
  double up = r, down = r;
  for (int k = 0; k < 8; ++k) {
    if (degrees(up) == deg) return up;
    if (degrees(down) == deg) return down;
    up = std::nextafter(up, 1e300);
    down = std::nextafter(down, -1e300);
  }
  return r;
}

NodeKind kindNamed(const std::string& name, const std::string& file, const std::string& field) {
  for (NodeKind k : {NodeKind::Root, NodeKind::Base, NodeKind::Joint, NodeKind::Attachment, NodeKind::Split, NodeKind::Before,
                     NodeKind::After, NodeKind::Tip}) {
    if (name == nodeKindName(k)) return k;
  }
  throw InputError(file, field, "'" + name + "' is not allowed; use root, base, joint, attachment, split, before, after or tip");
}

constexpr double kBig = 1e300;

// Da Vinci's rule, which the format states and every growth model keeps: the edges leaving a node start at radii whose
// E-th powers sum to its radius's (one edge: its radius). A fuzzed trunk swelling to 1 m between two nodes of 2 cm,
// with a child leaving it at 1 nm, meshed into NaN vertices.
void requireDaVinci(const Skeleton& s, const std::string& file) {
  std::vector<double> leaving(s.nodes.size(), 0.0);
  std::vector<std::int64_t> firstChild(s.nodes.size(), -1);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const int parent = s.nodes[i].parent;
    if (parent < 0) continue;
    const double r = s.nodes[static_cast<std::size_t>(parent)].radius;
    leaving[static_cast<std::size_t>(parent)] += r > 0.0 ? std::pow(s.nodes[i].startRadius / r, s.exponent) : s.nodes[i].startRadius;
    if (firstChild[static_cast<std::size_t>(parent)] < 0) firstChild[static_cast<std::size_t>(parent)] = static_cast<std::int64_t>(i);
  }
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    if (firstChild[i] < 0) continue;
    const bool kept = s.nodes[i].radius > 0.0 ? std::abs(leaving[i] - 1.0) <= kRadiusRule : leaving[i] == 0.0;
    if (!kept) {
      throw InputError(file, "nodes[" + std::to_string(firstChild[i]) + "].startRadius",
                       "the edges leaving node " + std::to_string(i) + " (radius " + formatNumber(s.nodes[i].radius) +
                           ") start at radii whose " + formatNumber(s.exponent) + "th powers sum to " + formatNumber(leaving[i]) +
                           " times its own; they must sum to it within 0.1 % (da Vinci's rule: one edge starts at the node's radius)");
    }
  }
}

}  // namespace

Skeleton readSkeletonJson(const std::string& text, const std::string& file) {
  const json doc = parseDocument(text, file, 8);
  object(doc, file, "(document)");
  onlyKeys(doc, {"format", "species", "seed", "levels", "treeScale", "treeShapeExponent", "lobes", "lobeDepth", "nodes", "stems", "leaves"},
           file, "");
  const std::string format = string(member(doc, "format", file, "", "\"arbor-skeleton/1\""), file, "format");
  if (format != "arbor-skeleton/1") throw InputError(file, "format", "'" + format + "' is not allowed; use \"arbor-skeleton/1\"");
  auto num = [&](const json& o, const char* key, const std::string& prefix, double min, double max, const std::string& allowed) {
    return number(member(o, key, file, prefix, allowed), file, prefix + key, min, max, allowed);
  };
  auto whole = [&](const json& o, const char* key, const std::string& prefix, std::int64_t min, std::int64_t max, const std::string& allowed) {
    return integer(member(o, key, file, prefix, allowed), file, prefix + key, min, max, allowed);
  };
  constexpr std::int64_t kMaxCount = std::numeric_limits<std::int32_t>::max();

  Skeleton s;
  s.species = string(member(doc, "species", file, "", "a string"), file, "species");
  s.seed = static_cast<std::uint64_t>(whole(doc, "seed", "", std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(),
                                            "a whole number"));
  s.levels = static_cast<int>(whole(doc, "levels", "", 0, 1000, "0 to 1000"));
  s.treeScale = num(doc, "treeScale", "", 0.0, kBig, "a number >= 0");
  s.exponent = num(doc, "treeShapeExponent", "", 1e-3, 1e3, "a number > 0");
  s.lobes = static_cast<int>(whole(doc, "lobes", "", 0, 1000, "0 to 1000"));
  s.lobeDepth = num(doc, "lobeDepth", "", -kBig, kBig, "a finite number");

  const json& nodes = array(member(doc, "nodes", file, "", "an array of nodes"), file, "nodes");
  const json& stems = array(member(doc, "stems", file, "", "an array of stems"), file, "stems");
  const json& leaves = array(member(doc, "leaves", file, "", "an array of leaves"), file, "leaves");
  const auto nodeCount = static_cast<std::int64_t>(nodes.size()), stemCount = static_cast<std::int64_t>(stems.size());

  s.nodes.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string at = "nodes[" + std::to_string(i) + "].";
    const json& n = object(nodes[i], file, at.substr(0, at.size() - 1));
    onlyKeys(n, {"id", "parent", "stem", "level", "kind", "offset", "position", "direction", "radius", "startRadius"}, file, at);
    const auto id = static_cast<std::int64_t>(i);
    whole(n, "id", at, id, id, std::to_string(i) + " (ids are indices into nodes)");
    SkeletonNode node;
    node.parent = static_cast<std::int32_t>(whole(n, "parent", at, -1, id - 1, "-1 or the id of an earlier node (parents come first)"));
    node.stem = static_cast<std::int32_t>(whole(n, "stem", at, -1, stemCount - 1, "-1 or a stem's id"));
    node.level = static_cast<std::int16_t>(whole(n, "level", at, 0, 1000, "0 to 1000"));
    node.kind = kindNamed(string(member(n, "kind", file, at, "a node kind"), file, at + "kind"), file, at + "kind");
    node.offset = num(n, "offset", at, -kBig, kBig, "a finite number");
    node.radius = num(n, "radius", at, 0.0, kBig, "a radius >= 0");
    node.startRadius = num(n, "startRadius", at, 0.0, kBig, "a radius >= 0");
    const Vec3 position = json_fields::position(member(n, "position", file, at, "[x, y, z]"), file, at + "position");
    const Vec3 direction = vec3(member(n, "direction", file, at, "a unit vector [x, y, z]"), file, at + "direction");
    if (std::abs(glm::length(direction) - 1.0) > 1e-6) throw InputError(file, at + "direction", "not a unit vector; give one of length 1");
    node.world = Transform{position, rotationTo(direction)};
    node.local = node.parent < 0 ? node.world : compose(inverse(s.nodes[static_cast<std::size_t>(node.parent)].world), node.world);
    s.nodes.push_back(node);
  }

  requireDaVinci(s, file);

  // Points of a stem closer than this have no direction between them (a fuzzed trunk's first edge normalised to NaN).
  Vec3 low(0.0), high(0.0);
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    low = i == 0 ? s.nodes[i].world.position : glm::min(low, s.nodes[i].world.position);
    high = i == 0 ? s.nodes[i].world.position : glm::max(high, s.nodes[i].world.position);
  }
  const double size = glm::distance(low, high), apart = kZeroLength * size;

  s.stems.reserve(stems.size());
  for (std::size_t i = 0; i < stems.size(); ++i) {
    const std::string at = "stems[" + std::to_string(i) + "].";
    const json& st = object(stems[i], file, at.substr(0, at.size() - 1));
    onlyKeys(st, {"id", "key", "level", "parent", "cloneOf", "attachNode", "firstNode", "nodeCount", "length", "offsetOnParent", "startRadius",
                  "branchRatio", "secondaryAngle", "primaryDeflection", "stub"},
             file, at);
    const auto id = static_cast<std::int64_t>(i);
    whole(st, "id", at, id, id, std::to_string(i) + " (ids are indices into stems)");
    SkeletonStem stem;
    const std::string key = string(member(st, "key", file, at, "16 hex digits"), file, at + "key");
    if (key.size() != 16 || key.find_first_not_of("0123456789abcdef") != std::string::npos) {
      throw InputError(file, at + "key", "'" + key + "' is not allowed; give 16 lower-case hex digits");
    }
    stem.key = std::stoull(key, nullptr, 16);
    stem.level = static_cast<std::int16_t>(whole(st, "level", at, 0, 1000, "0 to 1000"));
    // Stems that come first, as nodes do: a stem's parents then lead to a trunk (a parent cycle hung the mesher).
    stem.parentStem = static_cast<std::int32_t>(whole(st, "parent", at, -1, id - 1, "-1 or the id of an earlier stem (stems come after what they grow from)"));
    stem.cloneOf = static_cast<std::int32_t>(whole(st, "cloneOf", at, -1, id - 1, "-1 or the id of an earlier stem (stems come after what they grow from)"));
    stem.attachNode = static_cast<std::int32_t>(whole(st, "attachNode", at, -1, nodeCount - 1, "-1 or a node's id"));
    // A child leaves a node of its parent, a clone one of the stem it splits from, a trunk the root (or no node).
    if (stem.attachNode >= 0) {
      const std::int32_t from = stem.cloneOf >= 0 ? stem.cloneOf : stem.parentStem;
      const std::int32_t owner = s.nodes[static_cast<std::size_t>(stem.attachNode)].stem;
      if (owner != from) {
        throw InputError(file, at + "attachNode",
                         "node " + std::to_string(stem.attachNode) + " is " + (owner < 0 ? "on no stem" : "on stem " + std::to_string(owner)) + "; " +
                             (stem.cloneOf >= 0   ? "a clone leaves a node of the stem it splits from (" + std::to_string(from) + ")"
                              : from >= 0         ? "a child leaves a node of its parent (" + std::to_string(from) + ")"
                                                  : std::string("a trunk leaves the root, a node on no stem, or -1")));
      }
    }
    stem.firstNode = static_cast<std::int32_t>(whole(st, "firstNode", at, 0, nodeCount, "a node's id"));
    stem.nodeCount = static_cast<std::int32_t>(whole(st, "nodeCount", at, 0, std::min(kMaxCount, nodeCount - stem.firstNode),
                                                     "0 to the number of nodes from firstNode on"));
    if (stem.attachNode >= stem.firstNode && stem.nodeCount > 0) {
      throw InputError(file, at + "attachNode", "not before firstNode; a stem leaves a node that comes before its own");
    }
    for (std::int32_t k = stem.firstNode; k < stem.firstNode + stem.nodeCount; ++k) {
      if (s.nodes[static_cast<std::size_t>(k)].stem != static_cast<std::int32_t>(i)) {
        throw InputError(file, "nodes[" + std::to_string(k) + "].stem", "not " + std::to_string(i) + ", the stem whose nodes it is among");
      }
    }
    for (std::int32_t k = stem.firstNode, before = stem.attachNode; k < stem.firstNode + stem.nodeCount; before = k++) {
      if (before < 0) continue;
      const double d = glm::distance(s.nodes[static_cast<std::size_t>(before)].world.position, s.nodes[static_cast<std::size_t>(k)].world.position);
      if (!(d > apart)) {
        throw InputError(file, "nodes[" + std::to_string(k) + "].position",
                         formatNumber(d) + " m from node " + std::to_string(before) + " before it on stem " + std::to_string(i) +
                             "; a stem's points must be more than 1e-9 of the tree's size (" + formatNumber(size) + " m) apart");
      }
    }
    stem.length = num(st, "length", at, 0.0, kBig, "a length >= 0");
    stem.offsetOnParent = num(st, "offsetOnParent", at, -kBig, kBig, "a finite number");
    stem.startRadius = num(st, "startRadius", at, 0.0, kBig, "a radius >= 0");
    stem.branchRatio = num(st, "branchRatio", at, 0.0, kBig, "a number >= 0");
    stem.secondaryAngle = radiansExact(num(st, "secondaryAngle", at, -360.0, 360.0, "-360 to 360 degrees"));
    stem.primaryDeflection = radiansExact(num(st, "primaryDeflection", at, -360.0, 360.0, "-360 to 360 degrees"));
    // Optional (files written before it had none): without it a stub would be meshed as a tube, not drawn as a card.
    if (const auto it = st.find("stub"); it != st.end()) {
      if (!it->is_boolean()) throw InputError(file, at + "stub", typeName(*it) + " is not allowed; give true or false");
      stem.stub = it->get<bool>();
    }
    // A tube of no width has no surface: its cross sections collapse into one point (a palm's skeleton with every radius 0 meshed into six quads on one point).
    if (!stem.stub && !(stem.startRadius > 0.0)) {
      throw InputError(file, at + "startRadius", "0 on a stem the mesh makes a tube of; give a radius > 0, or \"stub\": true to draw it as a card");
    }
    if (stem.nodeCount > 0) {
      const double first = s.nodes[static_cast<std::size_t>(stem.firstNode)].startRadius;
      if (std::abs(stem.startRadius - first) > kRadiusRule * std::max(stem.startRadius, first)) {
        throw InputError(file, at + "startRadius",
                         formatNumber(stem.startRadius) + ", but its first node (" + std::to_string(stem.firstNode) + ") starts at " + formatNumber(first) +
                             "; give the same radius");
      }
    }
    s.stems.push_back(std::move(stem));
  }
  // What grows from a stub is drawn with it as cards; a tube there would have no parent surface to leave from.
  for (std::size_t i = 0; i < s.stems.size(); ++i) {
    const SkeletonStem& st = s.stems[i];
    for (const std::int32_t from : {st.parentStem, st.cloneOf}) {
      if (from >= 0 && s.stems[static_cast<std::size_t>(from)].stub && !st.stub) {
        throw InputError(file, "stems[" + std::to_string(i) + "].stub",
                         "false, but it grows from stem " + std::to_string(from) + ", a stub; a stub's children and clones are stubs too (give true)");
      }
    }
  }

  s.leaves.reserve(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    const std::string at = "leaves[" + std::to_string(i) + "].";
    const json& l = object(leaves[i], file, at.substr(0, at.size() - 1));
    onlyKeys(l, {"stem", "node", "position", "direction", "normal", "length", "width", "kind"}, file, at);
    Leaf leaf;
    leaf.stem = static_cast<std::int32_t>(whole(l, "stem", at, 0, stemCount - 1, "a stem's id"));
    leaf.node = static_cast<std::int32_t>(whole(l, "node", at, 0, nodeCount - 1, "a node's id"));
    leaf.position = vec3(member(l, "position", file, at, "[x, y, z]"), file, at + "position");
    leaf.direction = vec3(member(l, "direction", file, at, "[x, y, z]"), file, at + "direction");
    leaf.normal = vec3(member(l, "normal", file, at, "[x, y, z]"), file, at + "normal");
    leaf.length = num(l, "length", at, 0.0, kBig, "a length >= 0");
    leaf.width = num(l, "width", at, 0.0, kBig, "a width >= 0");
    leaf.kind = static_cast<std::uint8_t>(whole(l, "kind", at, 0, 3, "0 (broad), 1 (narrow), 2 (frond) or 3 (needle)"));
    s.leaves.push_back(leaf);
  }
  return s;
}

}  // namespace arbor
