#include "graph_json.hpp"

#include <unordered_map>

#include "common/json_writer.hpp"
#include "growth/json_fields.hpp"

namespace arbor {

namespace {

using namespace json_fields;

constexpr const char* kFormat = "arbor-graph/1";
constexpr std::int64_t kMaxId = (std::int64_t{1} << 53) - 1;  // ids stay exact wherever JSON is read as doubles

std::string idField(std::int64_t id, const char* what) { return "nodes[id " + std::to_string(id) + "]." + what; }

}  // namespace

BranchGraph readBranchGraphJson(const std::string& text, const std::string& file) {
  const json doc = parseDocument(text, file, 8);
  object(doc, file, "(document)");
  onlyKeys(doc, {"format", "nodes", "leaves"}, file, "");
  const std::string format = string(member(doc, "format", file, "", "\"arbor-graph/1\""), file, "format");
  if (format != kFormat) throw InputError(file, "format", "'" + format + "' is not allowed; use \"" + kFormat + "\"");

  const json& nodes = array(member(doc, "nodes", file, "", "an array of nodes"), file, "nodes");
  BranchGraph g;
  g.nodes.reserve(nodes.size());
  std::vector<std::int64_t> parentId;
  parentId.reserve(nodes.size());
  std::unordered_map<std::int64_t, std::int32_t> index;
  index.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string at = "nodes[" + std::to_string(i) + "]";
    const json& n = object(nodes[i], file, at);
    onlyKeys(n, {"id", "parent", "position", "radius"}, file, at + ".");
    BranchNode node;
    node.id = integer(member(n, "id", file, at + ".", "a whole number 0 to 2^53 - 1"), file, at + ".id", 0, kMaxId,
                      "a whole number 0 to 2^53 - 1");
    if (!index.emplace(node.id, static_cast<std::int32_t>(i)).second) {
      throw GraphError(file, at + ".id", "id " + std::to_string(node.id) + " is given twice; every node needs its own id");
    }
    const std::string allowedParent = "the id of another node, or -1 for the root";
    parentId.push_back(integer(member(n, "parent", file, idField(node.id, ""), allowedParent), file, idField(node.id, "parent"), -1, kMaxId,
                               allowedParent));
    node.position = position(member(n, "position", file, idField(node.id, ""), "[x, y, z]"), file, idField(node.id, "position"));
    if (n.contains("radius") && !n.at("radius").is_null()) {
      node.radius = number(n.at("radius"), file, idField(node.id, "radius"), -1e300, 1e300, "a finite number (<= 0: none given)");
    }
    g.nodes.push_back(node);
  }
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (parentId[i] < 0) continue;
    const auto it = index.find(parentId[i]);
    if (it == index.end()) {
      throw GraphError(file, idField(g.nodes[i].id, "parent"),
                       "unknown parent " + std::to_string(parentId[i]) + "; give the id of another node, or -1 for the root");
    }
    g.nodes[i].parent = it->second;
  }

  if (doc.contains("leaves")) {
    const json& leaves = array(doc.at("leaves"), file, "leaves");
    for (std::size_t k = 0; k < leaves.size(); ++k) {
      const std::string at = "leaves[" + std::to_string(k) + "]";
      const json& l = object(leaves[k], file, at);
      onlyKeys(l, {"node", "position", "direction", "normal", "length", "width", "kind"}, file, at + ".");
      GraphLeaf leaf;
      const std::int64_t id = integer(member(l, "node", file, at + ".", "a node's id"), file, at + ".node", 0, kMaxId, "a node's id");
      const auto it = index.find(id);
      if (it == index.end()) throw GraphError(file, at + ".node", "unknown node " + std::to_string(id) + "; give a node's id");
      leaf.node = it->second;
      leaf.position = l.contains("position") ? vec3(l.at("position"), file, at + ".position") : g.nodes[static_cast<std::size_t>(leaf.node)].position;
      leaf.direction = vec3(member(l, "direction", file, at + ".", "[x, y, z] along the blade"), file, at + ".direction");
      if (l.contains("normal")) leaf.normal = vec3(l.at("normal"), file, at + ".normal");
      leaf.length = number(member(l, "length", file, at + ".", "a length >= 0"), file, at + ".length", 0.0, 1e300, "a length >= 0");
      leaf.width = number(member(l, "width", file, at + ".", "a width >= 0"), file, at + ".width", 0.0, 1e300, "a width >= 0");
      if (l.contains("kind")) {
        leaf.kind = static_cast<std::uint8_t>(integer(l.at("kind"), file, at + ".kind", 0, 3, "0 (broad), 1 (narrow), 2 (frond) or 3 (needle)"));
      }
      g.leaves.push_back(leaf);
    }
  }
  validateBranchGraph(g, file);
  return g;
}

std::string writeBranchGraphJson(const BranchGraph& g) {
  JsonWriter w(2);
  w.beginObject();
  w.field("format", kFormat);
  auto idOf = [&](std::size_t i) { return g.nodes[i].id >= 0 ? g.nodes[i].id : static_cast<std::int64_t>(i); };
  w.key("nodes").beginArray();
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const BranchNode& n = g.nodes[i];
    w.beginObject();
    w.field("id", idOf(i));
    w.field("parent", n.parent < 0 ? std::int64_t{-1} : idOf(static_cast<std::size_t>(n.parent)));
    w.key("position").vec3(n.position.x, n.position.y, n.position.z);
    if (n.radius > 0.0) w.field("radius", n.radius);
    w.endObject();
  }
  w.endArray();
  if (!g.leaves.empty()) {
    w.key("leaves").beginArray();
    for (const GraphLeaf& l : g.leaves) {
      w.beginObject();
      w.field("node", idOf(static_cast<std::size_t>(l.node)));
      w.key("position").vec3(l.position.x, l.position.y, l.position.z);
      w.key("direction").vec3(l.direction.x, l.direction.y, l.direction.z);
      if (l.normal != Vec3(0.0)) w.key("normal").vec3(l.normal.x, l.normal.y, l.normal.z);
      w.field("length", l.length);
      w.field("width", l.width);
      w.field("kind", static_cast<int>(l.kind));
      w.endObject();
    }
    w.endArray();
  }
  w.endObject();
  return w.str();
}

}  // namespace arbor
