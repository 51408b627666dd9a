#include "skeleton_json.hpp"

#include <cstdio>
#include <sstream>

#include "common/json_writer.hpp"

namespace arbor {

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
