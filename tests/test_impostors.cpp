// Fake branches on lavapipe: one rectangle per skeleton edge, standing in for the mesh of the levels they
// replace, and goldens of mesh + leaves + fake branches on three presets.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "image/image_compare.hpp"
#include "render_support.hpp"

using namespace arbor;

namespace {

// How far apart two masks' coverage is, block by block (8x8 pixels): the summed difference of the tree pixels
// each block holds, over the reference's tree pixels. Twigs thinner than a pixel land on different pixels in
// two pictures of the same branch, so pixel overlap says little; coverage per block does not care.
double blockCoverageError(const std::vector<bool>& mask, const std::vector<bool>& reference, std::uint32_t width) {
  constexpr std::uint32_t kBlock = 8;
  const std::uint32_t height = static_cast<std::uint32_t>(mask.size()) / width;
  double difference = 0.0, total = 0.0;
  for (std::uint32_t by = 0; by < height; by += kBlock) {
    for (std::uint32_t bx = 0; bx < width; bx += kBlock) {
      double a = 0.0, b = 0.0;
      for (std::uint32_t y = by; y < std::min(by + kBlock, height); ++y) {
        for (std::uint32_t x = bx; x < std::min(bx + kBlock, width); ++x) {
          a += mask[y * width + x] ? 1.0 : 0.0;
          b += reference[y * width + x] ? 1.0 : 0.0;
        }
      }
      difference += std::abs(a - b);
      total += b;
    }
  }
  return difference / std::max(total, 1.0);
}

double count(const std::vector<bool>& mask) { return static_cast<double>(std::count(mask.begin(), mask.end(), true)); }

}  // namespace

TEST_CASE("every fake-branch segment becomes one rectangle", "[render][impostors]") {
  test::TreeScene scene("quaking-aspen", 2, 1, 64, 80);
  REQUIRE(scene.faked.impostors.size() > 1000);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::Flat;
  const std::uint64_t bare = scene.session.render(scene.framed(), settings).gpu.triangles;
  settings.impostors = true;
  CHECK(scene.session.render(scene.framed(), settings).gpu.triangles == bare + 2 * scene.faked.impostors.size());
  // Seen from straight above many segments point at the eye; each still yields its rectangle.
  render::Camera above = scene.framed();
  above.eye = above.target + glm::vec3(0.0f, 0.001f, glm::length(above.eye - above.target));
  const std::uint64_t bareAbove = (settings.impostors = false, scene.session.render(above, settings).gpu.triangles);
  settings.impostors = true;
  CHECK(scene.session.render(above, settings).gpu.triangles == bareAbove + 2 * scene.faked.impostors.size());
}

TEST_CASE("fake branches cover what the mesh of their levels would", "[render][impostors]") {
  constexpr std::uint32_t kWidth = 240, kHeight = 300;
  test::TreeScene full("quaking-aspen", 3, 0, kWidth, kHeight);
  test::TreeScene faked("quaking-aspen", 2, 1, kWidth, kHeight);
  render::RenderSession empty(test::vulkan(), kWidth, kHeight, VK_SAMPLE_COUNT_1_BIT, test::textures());
  const render::Camera camera = full.framed();
  render::RenderSettings settings;
  settings.mode = render::RenderMode::ACC;
  settings.tessLevel = 4.0f;
  settings.ground = false;
  const Image sky = (empty.render(camera, settings), empty.image());
  const auto fullMask = differingPixels((full.session.render(camera, settings), full.session.image()), sky);
  const auto bareMask = differingPixels((faked.session.render(camera, settings), faked.session.image()), sky);
  settings.impostors = true;
  const auto fakedMask = differingPixels((faked.session.render(camera, settings), faked.session.image()), sky);
  const double fakedError = blockCoverageError(fakedMask, fullMask, kWidth), bareError = blockCoverageError(bareMask, fullMask, kWidth);
  INFO("tree pixels: full mesh " << count(fullMask) << ", mesh + fake branches " << count(fakedMask) << ", mesh alone "
                                 << count(bareMask) << "; block coverage error " << fakedError << " (faked), " << bareError << " (bare)");
  CHECK(count(fakedMask) > 0.8 * count(fullMask));
  CHECK(count(fakedMask) < 1.25 * count(fullMask));
  CHECK(fakedError < 0.5 * bareError);
}

TEST_CASE("golden images: mesh, leaves and fake branches on three presets", "[render][impostors][golden]") {
  struct Case {
    const char* name;
    const char* preset;
    int meshLevels, impostorLevels;
    std::uint32_t shadowLeaves;
  };
  const Case cases[] = {{"aspen-impostors", "quaking-aspen", 2, 1, 0},
                        {"tupelo-impostors", "black-tupelo", 2, 1, 250},
                        {"oak-impostors", "ca-black-oak", 2, 1, 0}};
  for (const Case& c : cases) {
    INFO(c.name);
    test::TreeScene scene(c.preset, c.meshLevels, c.impostorLevels, 160, 200);
    render::RenderSettings settings;
    settings.mode = render::RenderMode::ACC;
    settings.tessLevel = 4.0f;
    settings.leaves = true;
    settings.impostors = true;
    settings.shadowLeaves = c.shadowLeaves;
    settings.lightDirection = render::sunDirection(25.0f, 40.0f);
    scene.session.render(scene.framed(), settings);
    const test::GoldenCheck golden = test::checkGolden(c.name, scene.session.image());
    INFO(golden.report);
    CHECK(golden.ok);
  }
}
