#include <filesystem>

#include "common/input_file.hpp"
#include "growth/json_fields.hpp"
#include "space_colonization.hpp"

namespace arbor::sc {

namespace {

using nlohmann::json;
namespace jf = json_fields;

constexpr double kBig = 1e6;
constexpr std::size_t kMaxObjBytes = 64 * 1024 * 1024;

double positive(const json& object, const char* key, const std::string& file, const std::string& prefix) {
  const std::string field = prefix + key;
  const double x = jf::number(jf::member(object, key, file, prefix, "a number > 0"), file, field, -kBig, kBig, "a number > 0");
  if (!(x > 0)) throw InputError(file, field, formatNumber(x) + ": must be > 0");
  return x;
}

Vec3 positiveVec3(const json& object, const char* key, const std::string& file, const std::string& prefix) {
  const std::string field = prefix + key;
  const Vec3 v = jf::vec3(jf::member(object, key, file, prefix, "[x, y, z], each > 0"), file, field);
  if (!(v.x > 0 && v.y > 0 && v.z > 0)) throw InputError(file, field, "a volume needs every extent > 0");
  return v;
}

AttractionCloud readCloud(const json& c, const std::string& file, const std::string& prefix) {
  jf::object(c, file, prefix.substr(0, prefix.size() - 1));
  AttractionCloud cloud;
  const std::string shape = jf::string(jf::member(c, "shape", file, prefix, "sphere, ellipsoid, cone or box"), file, prefix + "shape");
  cloud.center = jf::position(jf::member(c, "center", file, prefix, "[x, y, z]"), file, prefix + "center");
  if (shape == "sphere") {
    jf::onlyKeys(c, {"shape", "center", "radius", "points", "influence", "kill"}, file, prefix);
    cloud.shape = CloudShape::Sphere;
    cloud.size = Vec3(positive(c, "radius", file, prefix));
  } else if (shape == "ellipsoid") {
    jf::onlyKeys(c, {"shape", "center", "radii", "points", "influence", "kill"}, file, prefix);
    cloud.shape = CloudShape::Ellipsoid;
    cloud.size = positiveVec3(c, "radii", file, prefix);
  } else if (shape == "cone") {
    jf::onlyKeys(c, {"shape", "center", "radius", "height", "points", "influence", "kill"}, file, prefix);
    cloud.shape = CloudShape::Cone;
    const double r = positive(c, "radius", file, prefix);
    cloud.size = Vec3(r, r, positive(c, "height", file, prefix));
  } else if (shape == "box") {
    jf::onlyKeys(c, {"shape", "center", "size", "points", "influence", "kill"}, file, prefix);
    cloud.shape = CloudShape::Box;
    cloud.size = positiveVec3(c, "size", file, prefix);
  } else {
    throw InputError(file, prefix + "shape", "'" + shape + "' is not a cloud shape; allowed sphere, ellipsoid, cone, box");
  }
  cloud.points = static_cast<std::uint32_t>(
      jf::integer(jf::member(c, "points", file, prefix, "1 to 10000000"), file, prefix + "points", 1, 10'000'000, "1 to 10000000"));
  cloud.influence = positive(c, "influence", file, prefix);
  cloud.kill = positive(c, "kill", file, prefix);
  if (cloud.kill >= cloud.influence)
    throw InputError(file, prefix + "kill", formatNumber(cloud.kill) + " is not below the influence radius " + formatNumber(cloud.influence) +
                                                ": a point must attract nodes before it dies");
  return cloud;
}

Obstacle readObstacle(const json& o, const std::string& file, const std::string& prefix) {
  jf::object(o, file, prefix.substr(0, prefix.size() - 1));
  Obstacle obstacle;
  const std::string shape = jf::string(jf::member(o, "shape", file, prefix, "box, sphere or mesh"), file, prefix + "shape");
  if (shape == "box") {
    jf::onlyKeys(o, {"shape", "center", "size"}, file, prefix);
    obstacle.shape = ObstacleShape::Box;
    obstacle.center = jf::position(jf::member(o, "center", file, prefix, "[x, y, z]"), file, prefix + "center");
    obstacle.size = positiveVec3(o, "size", file, prefix);
  } else if (shape == "sphere") {
    jf::onlyKeys(o, {"shape", "center", "radius"}, file, prefix);
    obstacle.shape = ObstacleShape::Sphere;
    obstacle.center = jf::position(jf::member(o, "center", file, prefix, "[x, y, z]"), file, prefix + "center");
    obstacle.size = Vec3(positive(o, "radius", file, prefix));
  } else if (shape == "mesh") {
    jf::onlyKeys(o, {"shape", "file"}, file, prefix);
    obstacle.shape = ObstacleShape::Mesh;
    obstacle.file = jf::string(jf::member(o, "file", file, prefix, "an OBJ file, relative to this file"), file, prefix + "file");
    const std::filesystem::path path = std::filesystem::path(file).parent_path() / obstacle.file;
    const std::string text = readInputFile(path.string(), kMaxObjBytes, prefix + "file");
    obstacle.mesh = std::make_shared<const TriangleMesh>(readObjMesh(text, file, prefix + "file"));
  } else {
    throw InputError(file, prefix + "shape", "'" + shape + "' is not an obstacle shape; allowed box, sphere, mesh");
  }
  return obstacle;
}

}  // namespace

SpaceColonization readSpaceColonization(const std::string& text, const std::string& file) {
  const json root = jf::parseDocument(text, file, 16);
  jf::object(root, file, "(document)");
  jf::onlyKeys(root, {"model", "name", "seed", "segmentLength", "gravity", "trunk", "clouds", "obstacles", "radii", "leaves"}, file, "");
  SpaceColonization m;
  m.file = file;
  if (root.contains("name")) m.name = jf::string(root.at("name"), file, "name");
  if (root.contains("seed")) m.seed = static_cast<std::uint64_t>(jf::integer(root.at("seed"), file, "seed", 0, 1LL << 53, "0 to 2^53"));
  m.segmentLength = positive(root, "segmentLength", file, "");
  if (root.contains("gravity")) m.gravity = jf::number(root.at("gravity"), file, "gravity", 0, kBig, "a number >= 0");

  const json& trunk = jf::object(jf::member(root, "trunk", file, "", "an object: base, segments, width"), file, "trunk");
  jf::onlyKeys(trunk, {"base", "segments", "width"}, file, "trunk.");
  if (trunk.contains("base")) m.trunkBase = jf::position(trunk.at("base"), file, "trunk.base");
  m.trunkSegments = static_cast<int>(jf::integer(jf::member(trunk, "segments", file, "trunk.", "1 to 10000"), file, "trunk.segments", 1, 10000, "1 to 10000"));
  m.trunkWidth = positive(trunk, "width", file, "trunk.");

  const json& clouds = jf::array(jf::member(root, "clouds", file, "", "an array of clouds"), file, "clouds");
  if (clouds.empty()) throw InputError(file, "clouds", "no cloud: a tree grows toward attraction points, give at least one cloud");
  for (std::size_t i = 0; i < clouds.size(); ++i) m.clouds.push_back(readCloud(clouds[i], file, "clouds[" + std::to_string(i) + "]."));

  if (root.contains("obstacles")) {
    const json& obstacles = jf::array(root.at("obstacles"), file, "obstacles");
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const std::string prefix = "obstacles[" + std::to_string(i) + "].";
      m.obstacles.push_back(readObstacle(obstacles[i], file, prefix));
      for (int s = 0; s < m.trunkSegments; ++s) {
        const Vec3 a = m.trunkBase + Vec3(0, 0, m.segmentLength * s), b = a + Vec3(0, 0, m.segmentLength);
        if (segmentHitsObstacle(m.obstacles.back(), a, b))
          throw InputError(file, "trunk", "segment " + std::to_string(s + 1) + " of the trunk lies in obstacles[" + std::to_string(i) + "]; move one of them");
      }
    }
  }
  if (root.contains("radii")) {
    const json& radii = jf::object(root.at("radii"), file, "radii");
    jf::onlyKeys(radii, {"tip", "exponent"}, file, "radii.");
    if (radii.contains("tip")) m.tipRadius = positive(radii, "tip", file, "radii.");
    if (radii.contains("exponent")) m.exponent = jf::number(radii.at("exponent"), file, "radii.exponent", 1, 4, "1 to 4");
  }
  if (root.contains("leaves")) {
    const json& leaves = jf::object(root.at("leaves"), file, "leaves");
    jf::onlyKeys(leaves, {"depth", "length", "width"}, file, "leaves.");
    if (leaves.contains("depth")) m.leafDepth = static_cast<int>(jf::integer(leaves.at("depth"), file, "leaves.depth", -1, 1000, "-1 (none) to 1000"));
    if (leaves.contains("length")) m.leafLength = positive(leaves, "length", file, "leaves.");
    if (leaves.contains("width")) m.leafWidth = positive(leaves, "width", file, "leaves.");
  }
  return m;
}

std::string writeSpaceColonization(const SpaceColonization& m) {
  using ojson = nlohmann::ordered_json;
  const auto vec = [](const Vec3& v) { return ojson::array({v.x, v.y, v.z}); };
  ojson root;
  root["model"] = "space-colonization";
  root["name"] = m.name;
  root["seed"] = m.seed;
  root["segmentLength"] = m.segmentLength;
  root["gravity"] = m.gravity;
  root["trunk"] = {{"base", vec(m.trunkBase)}, {"segments", m.trunkSegments}, {"width", m.trunkWidth}};
  root["clouds"] = ojson::array();
  for (const AttractionCloud& c : m.clouds) {
    ojson o;
    o["shape"] = cloudShapeName(c.shape);
    o["center"] = vec(c.center);
    switch (c.shape) {
      case CloudShape::Sphere: o["radius"] = c.size.x; break;
      case CloudShape::Ellipsoid: o["radii"] = vec(c.size); break;
      case CloudShape::Cone: o["radius"] = c.size.x, o["height"] = c.size.z; break;
      case CloudShape::Box: o["size"] = vec(c.size); break;
    }
    o["points"] = c.points;
    o["influence"] = c.influence;
    o["kill"] = c.kill;
    root["clouds"].push_back(o);
  }
  root["obstacles"] = ojson::array();
  for (const Obstacle& ob : m.obstacles) {
    ojson o;
    o["shape"] = obstacleShapeName(ob.shape);
    if (ob.shape == ObstacleShape::Mesh) o["file"] = ob.file;
    else o["center"] = vec(ob.center);
    if (ob.shape == ObstacleShape::Box) o["size"] = vec(ob.size);
    if (ob.shape == ObstacleShape::Sphere) o["radius"] = ob.size.x;
    root["obstacles"].push_back(o);
  }
  root["radii"] = {{"tip", m.tipRadius}, {"exponent", m.exponent}};
  root["leaves"] = {{"depth", m.leafDepth}, {"length", m.leafLength}, {"width", m.leafWidth}};
  return root.dump(2) + "\n";
}

}  // namespace arbor::sc
