// Leaves on lavapipe: one quad per leaf, density and distance thinning, back-lighting, self-shadowing, goldens.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "growth/weber_penn/weber_penn.hpp"
#include "image/image_compare.hpp"
#include "mesh/tree_mesh.hpp"
#include "render/cards.hpp"
#include "render_support.hpp"
#include "test_support.hpp"

using namespace arbor;

TEST_CASE("every leaf becomes one quad, and density keeps that share of them", "[render][leaves]") {
  test::TreeScene scene("quaking-aspen", 3, 0, 64, 80);
  const std::uint64_t leaves = scene.skeleton.leaves.size();
  REQUIRE(leaves > 1000);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  const std::uint64_t bare = scene.session.render(scene.framed(), settings).gpu.triangles;
  settings.leaves = true;
  CHECK(scene.session.render(scene.framed(), settings).gpu.triangles == bare + 2 * leaves);
  settings.leafDensity = 0.25f;
  const std::uint64_t quarter = scene.session.render(scene.framed(), settings).gpu.triangles - bare;
  CHECK(std::abs(static_cast<double>(quarter) - 0.5 * static_cast<double>(leaves)) <= 2.0);  // 2 per kept leaf
}

TEST_CASE("more leaves than one draw's cards: every leaf drawn, one more draw per kCardsPerDraw", "[render][leaves]") {
  test::TreeScene scene("quaking-aspen", 3, 1, 64, 80);  // leaves at the fourth level: several hundred thousand
  const std::uint64_t leaves = scene.skeleton.leaves.size();
  REQUIRE(leaves > 2 * render::kCardsPerDraw);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  const render::FrameStats bare = scene.session.render(scene.framed(), settings).gpu;
  settings.leaves = true;
  const render::FrameStats with = scene.session.render(scene.framed(), settings).gpu;
  CHECK(with.triangles == bare.triangles + 2 * leaves);
  CHECK(with.draws == bare.draws + (leaves + render::kCardsPerDraw - 1) / render::kCardsPerDraw);
}

TEST_CASE("distance thins the leaves gradually, the farther the fewer", "[render][leaves]") {
  test::TreeScene scene("quaking-aspen", 3, 0, 64, 80);
  const double leaves = static_cast<double>(scene.skeleton.leaves.size());
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  settings.leaves = true;
  settings.leafLodDistance = 30.0f;
  const render::Camera near = scene.framed();
  settings.leaves = false;
  const std::uint64_t bare = scene.session.render(near, settings).gpu.triangles;
  settings.leaves = true;
  double previous = 2.0 * leaves;
  for (float k = 1.0f; k <= 4.0f; k += 0.1f) {
    render::Camera c = near;
    c.eye = c.target + (near.eye - near.target) * k;
    c.farPlane *= k;
    const double drawn = static_cast<double>(scene.session.render(c, settings).gpu.triangles - bare);
    INFO("distance factor " << k << ": " << drawn / 2.0 << " of " << leaves << " leaves");
    CHECK(drawn <= previous);
    CHECK(previous - drawn < 0.2 * 2.0 * leaves);  // a tenth farther never drops a large share at once
    previous = drawn;
  }
  CHECK(previous < 0.5 * 2.0 * leaves);  // and far away most are gone
}

TEST_CASE("thinned leaves grow so that the crown keeps its leaf cover", "[render][leaves]") {
  test::TreeScene scene("quaking-aspen", 3, 0, 200, 250);
  render::Camera camera = scene.framed();
  camera.eye = camera.target + (camera.eye - camera.target) * 0.5f;  // the crown fills the picture
  const float distance = glm::distance(camera.eye, camera.target);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  settings.ground = false;
  const Image bare = (scene.session.render(camera, settings), scene.session.image());
  settings.leaves = true;
  const render::FrameResult all = scene.session.render(camera, settings);
  const Image allLeaves = scene.session.image();
  settings.leafLodDistance = 0.6f * distance;  // about half the leaves kept, each grown by up to 1.7
  const render::FrameResult thinned = scene.session.render(camera, settings);
  const Image thinnedLeaves = scene.session.image();
  const auto cover = [&bare](const Image& image) {
    const std::vector<bool> differs = differingPixels(image, bare);
    return static_cast<double>(std::count(differs.begin(), differs.end(), true));
  };
  const double kept = static_cast<double>(thinned.gpu.triangles - (all.gpu.triangles - 2 * scene.skeleton.leaves.size())) /
                      (2.0 * static_cast<double>(scene.skeleton.leaves.size()));
  INFO("kept " << kept << " of the leaves; leaf pixels " << cover(thinnedLeaves) << " against " << cover(allLeaves) << " with all");
  REQUIRE(kept < 0.6);
  CHECK(cover(thinnedLeaves) > 0.8 * cover(allLeaves));
  CHECK(cover(thinnedLeaves) < 1.25 * cover(allLeaves));
}

TEST_CASE("leaves with the sun behind them glow yellow-green, self-shadowing darkens the crown", "[render][leaves]") {
  test::TreeScene scene("quaking-aspen", 3, 0, 200, 250);
  const render::Camera camera = scene.framed();
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  settings.ground = false;
  settings.lightDirection = render::sunDirection(25.0f, 40.0f);
  const Image bare = (scene.session.render(camera, settings), scene.session.image());
  settings.leaves = true;
  const Image front = (scene.session.render(camera, settings), scene.session.image());
  settings.lightDirection = render::sunDirection(205.0f, 15.0f);  // behind the crown, low
  const Image back = (scene.session.render(camera, settings), scene.session.image());
  settings.lightDirection = render::sunDirection(25.0f, 40.0f);
  settings.shadowLeaves = 250;
  const Image shadowed = (scene.session.render(camera, settings), scene.session.image());
  settings.shadowLeaves = 1000;
  const Image shadowedMore = (scene.session.render(camera, settings), scene.session.image());

  double frontBlue = 0.0, backBlue = 0.0, frontLuma = 0.0, shadowedLuma = 0.0, shadowedMoreLuma = 0.0, pixels = 0.0;
  const std::vector<bool> frontLeaves = differingPixels(front, bare), backLeaves = differingPixels(back, bare);
  for (std::size_t i = 0; i < bare.rgba.size(); i += 4) {
    if (!frontLeaves[i / 4] || !backLeaves[i / 4]) continue;
    pixels += 1.0;
    const auto blueShare = [i](const Image& im) {
      return static_cast<double>(im.rgba[i + 2]) / std::max(1, im.rgba[i] + im.rgba[i + 1] + im.rgba[i + 2]);
    };
    frontBlue += blueShare(front);
    backBlue += blueShare(back);
    frontLuma += front.rgba[i] + front.rgba[i + 1] + front.rgba[i + 2];
    shadowedLuma += shadowed.rgba[i] + shadowed.rgba[i + 1] + shadowed.rgba[i + 2];
    shadowedMoreLuma += shadowedMore.rgba[i] + shadowedMore.rgba[i + 1] + shadowedMore.rgba[i + 2];
  }
  INFO(pixels << " leaf pixels; luma front " << frontLuma << ", 250 shadow leaves " << shadowedLuma << ", 1000 "
                << shadowedMoreLuma);
  REQUIRE(pixels > 500);
  CHECK(backBlue < 0.85 * frontBlue);      // the light through the leaves is yellow-green: less blue
  CHECK(shadowedLuma < 0.99 * frontLuma);         // inner leaves lose the sun
  CHECK(shadowedMoreLuma < 0.99 * shadowedLuma);  // and more of them against more leaves
}

TEST_CASE("golden images: leaves lit from the front, back-lit, self-shadowed", "[render][leaves][golden]") {
  struct Case {
    const char* name;
    const char* preset;
    int levels;
    float azimuth, elevation;
    std::uint32_t shadowLeaves;
  };
  const Case cases[] = {{"aspen-leaves-front", "quaking-aspen", 3, 25.0f, 40.0f, 0},
                        {"aspen-leaves-backlit", "quaking-aspen", 3, 205.0f, 15.0f, 0},
                        {"tupelo-leaves-shadowed", "black-tupelo", 3, 25.0f, 40.0f, 250},
                        {"palm-leaves", "palm", 0, 25.0f, 40.0f, 250}};
  for (const Case& c : cases) {
    INFO(c.name);
    test::TreeScene scene(c.preset, c.levels, 0, 160, 200);
    render::RenderSettings settings;
    settings.mode = render::RenderMode::ACC;
    settings.tessLevel = 4.0f;
    settings.leaves = true;
    settings.shadowLeaves = c.shadowLeaves;
    settings.lightDirection = render::sunDirection(c.azimuth, c.elevation);
    scene.session.render(scene.framed(), settings);
    const test::GoldenCheck golden = test::checkGolden(c.name, scene.session.image());
    INFO(golden.report);
    CHECK(golden.ok);
  }
}
