// The viewer's parts that need no device: the modeller's wireframes, its --events (parsed, applied to the model,
// checked against it before the viewer starts).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "common/input_error.hpp"
#include "growth/space_colonization/space_colonization_model.hpp"
#include "growth_scene.hpp"
#include "view_script.hpp"
#include "wireframes.hpp"

using namespace arbor;
using namespace arbor::viewer;

namespace {

Vec3 at(const render::LineVertex& v) { return Vec3(v.position[0], v.position[1], v.position[2]); }

// Each distinct line as a pair of rounded end points, whichever way it was drawn.
std::size_t distinctLines(const Lines& lines) {
  std::map<std::pair<std::array<long, 3>, std::array<long, 3>>, int> seen;
  const auto key = [](const Vec3& p) { return std::array<long, 3>{std::lround(p.x * 1e4), std::lround(p.y * 1e4), std::lround(p.z * 1e4)}; };
  for (std::size_t i = 0; i + 1 < lines.size(); i += 2) seen[std::minmax(key(at(lines[i])), key(at(lines[i + 1])))]++;
  return seen.size();
}

sc::SpaceColonization twoClouds() {
  return sc::readSpaceColonization(R"({"model": "space-colonization", "segmentLength": 0.1, "trunk": {"segments": 10, "width": 0.2},
    "clouds": [{"shape": "sphere", "center": [0, 0, 3], "radius": 1, "points": 300, "influence": 0.6, "kill": 0.2},
               {"shape": "box", "center": [1.5, 0, 3], "size": [1, 1, 1], "points": 200, "influence": 0.6, "kill": 0.2}],
    "obstacles": [{"shape": "box", "center": [-2, 0, 2], "size": [0.5, 2, 4]}]})",
                                     "two-clouds.json");
}

WindowEvent event(const std::string& text) { return parseEvents(text).front(); }

}  // namespace

TEST_CASE("wireframes: ellipsoid rings lie on the surface, boxes have twelve edges at their corners, meshes each edge once", "[viewer]") {
  sc::AttractionCloud ellipsoid;
  ellipsoid.shape = sc::CloudShape::Ellipsoid;
  ellipsoid.center = Vec3(1, 2, 3);
  ellipsoid.size = Vec3(2, 1, 0.5);
  Lines lines;
  addCloud(lines, ellipsoid, cloudColor(0), 32);
  REQUIRE(lines.size() == 3 * 32 * 2);
  for (const render::LineVertex& v : lines) {
    const Vec3 q = (at(v) - ellipsoid.center) / ellipsoid.size;
    REQUIRE(glm::dot(q, q) == Approx(1.0).epsilon(1e-5));
  }
  sc::AttractionCloud box;
  box.shape = sc::CloudShape::Box;
  box.center = Vec3(0, 0, 1);
  box.size = Vec3(2, 4, 6);
  lines.clear();
  addCloud(lines, box, cloudColor(1));
  REQUIRE(lines.size() == 24);
  REQUIRE(distinctLines(lines) == 12);
  for (const render::LineVertex& v : lines) {
    const Vec3 d = glm::abs(at(v) - box.center);
    REQUIRE(d.x == Approx(1.0));
    REQUIRE(d.y == Approx(2.0));
    REQUIRE(d.z == Approx(3.0));
  }
  sc::AttractionCloud cone;
  cone.shape = sc::CloudShape::Cone;
  cone.size = Vec3(1, 1, 2);
  lines.clear();
  addCloud(lines, cone, cloudColor(2), 16);
  for (const render::LineVertex& v : lines) REQUIRE(sc::insideCloud(cone, at(v) * 0.999));  // on its surface, so just inside when shrunk

  auto tetrahedron = std::make_shared<sc::TriangleMesh>();
  tetrahedron->vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tetrahedron->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  sc::Obstacle mesh;
  mesh.shape = sc::ObstacleShape::Mesh;
  mesh.mesh = tetrahedron;
  lines.clear();
  addObstacle(lines, mesh, kObstacleColor);
  REQUIRE(lines.size() == 12);  // six edges, each drawn once
  REQUIRE(distinctLines(lines) == 6);
}

TEST_CASE("wireframes: one cross per live point, one line per disabled branch", "[viewer]") {
  sc::ColonizerSettings s;
  s.segmentLength = 0.1;
  s.trunkSegments = 10;
  sc::Colonizer c(s);
  const sc::SpaceColonization m = twoClouds();
  c.addCloud(m.clouds[0]);
  c.step(200);
  Lines lines;
  addLivePoints(lines, c, 0.03);
  REQUIRE(lines.size() == 6 * c.livePoints());
  sc::Obstacle wall;
  wall.center = c.nodes().back().position;
  wall.size = Vec3(0.3);
  c.addObstacle(wall);
  const auto disabled = std::count_if(c.nodes().begin(), c.nodes().end(), [](const sc::Node& n) { return !n.enabled; });
  REQUIRE(disabled > 0);
  lines.clear();
  addDisabledBranches(lines, c);
  REQUIRE(lines.size() == 2 * static_cast<std::size_t>(disabled));
}

TEST_CASE("modeller events: parsed with their numbers, refused with --events when malformed", "[viewer]") {
  const std::vector<WindowEvent> e =
      parseEvents("1:grow,2:step=300,3:rewind=12,4:add-cloud=ellipsoid/0/0/5/1/2/1/500/0.6/0.2,5:move-cloud=0/1/2/3,6:remove-obstacle=0,"
                  "7:open=assets/presets/sc-open-broadleaf.json,8:pause");
  REQUIRE(e.size() == 8);
  CHECK(e[1].numbers == std::vector<double>{300});
  CHECK(e[3].text == "ellipsoid");
  CHECK(e[3].numbers == std::vector<double>{0, 0, 5, 1, 2, 1, 500, 0.6, 0.2});
  CHECK(e[4].numbers == std::vector<double>{0, 1, 2, 3});
  CHECK(e[6].text == "assets/presets/sc-open-broadleaf.json");
  CHECK(isSceneEvent(e[0]));
  CHECK_FALSE(isSceneEvent(event("1:resize=20x20")));
  for (const char* bad : {"1:grow=3", "1:step", "1:step=-4", "1:step=2.5", "1:rewind=nan", "1:move-cloud=0/1/2", "1:move-cloud=0/1/2/3/4",
                          "1:add-cloud=sphere/0/0/0/1/1", "1:add-cloud=sphere/0/0/0/1/1/1/5/6/7/8", "1:remove-cloud=1e7", "1:open=",
                          "1:add-obstacle=box/0/0/0/1/1/inf", "1:explode", "0:grow"}) {
    INFO(bad);
    REQUIRE_THROWS_AS(parseEvents(bad), InputError);
  }
}

TEST_CASE("modeller edits change exactly what they name and are checked as the model file is", "[viewer]") {
  const sc::SpaceColonization m = twoClouds();
  const sc::SpaceColonization moved = editedModel(m, event("1:move-cloud=1/4/5/6"));
  CHECK(moved.clouds[1].center == Vec3(4, 5, 6));
  CHECK(moved.clouds[1].size == m.clouds[1].size);
  CHECK(moved.clouds[0].center == m.clouds[0].center);
  const sc::SpaceColonization removed = editedModel(m, event("1:remove-cloud=0"));
  REQUIRE(removed.clouds.size() == 1);
  CHECK(removed.clouds[0].center == m.clouds[1].center);
  const sc::SpaceColonization added = editedModel(m, event("1:add-obstacle=sphere/3/3/3/0.5/0.5/0.5"));
  REQUIRE(added.obstacles.size() == 2);
  CHECK(added.obstacles[1].shape == sc::ObstacleShape::Sphere);

  // Refused as the reader refuses a file: no volume, kill >= influence, a trunk inside an obstacle, a bad index.
  for (const char* bad : {"1:resize-cloud=0/0/0/0", "1:add-cloud=sphere/0/0/3/1/1/1/100/0.2/0.4", "1:add-obstacle=box/0/0/0.5/1/1/1",
                          "1:move-obstacle=0/0/0/1", "1:remove-cloud=2", "1:move-obstacle=1/0/0/0", "1:add-cloud=blob/0/0/3/1/1/1",
                          "1:add-obstacle=mesh/0/0/3/1/1/1"}) {
    INFO(bad);
    try {
      editedModel(m, event(bad));
      FAIL("accepted");
    } catch (const InputError& error) {
      CHECK_THAT(error.what(), Catch::Contains("--events"));
    }
  }
}

TEST_CASE("a script's edits are checked in frame order before the viewer starts, indices following adds and removes", "[viewer]") {
  const TreeModel model = readSpaceColonizationModel(sc::writeSpaceColonization(twoClouds()), "two-clouds.json");
  // Frame order, not the order written: cloud 2 exists by frame 3.
  CHECK_NOTHROW(GrowthScene::checkEvents(model, parseEvents("3:move-cloud=2/0/0/3,2:add-cloud=sphere/0/1/3/1/1/1,1:rewind=4,4:finish")));
  CHECK_THROWS_AS(GrowthScene::checkEvents(model, parseEvents("1:remove-cloud=0,2:move-cloud=1/0/0/3")), InputError);
  CHECK_THROWS_AS(GrowthScene::checkEvents(model, parseEvents("1:open=no-such-model.json")), InputError);
  CHECK_NOTHROW(GrowthScene::checkEvents(model, parseEvents("1:resize=100x100,2:regenerate")));
}
