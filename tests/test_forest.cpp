// The forest behind the walkthrough: crowns placed without overlap, whole trees culled outside the view,
// farther trees with more of their levels as fake branches, the same tree instanced rather than grown again.
#include <catch2/catch.hpp>

#include "image/image_compare.hpp"
#include "growth/weber_penn/weber_penn_model.hpp"
#include "render/forest.hpp"
#include "render/renderer.hpp"
#include "render_support.hpp"
#include "test_support.hpp"

using namespace arbor;

TEST_CASE("trees are placed without overlapping crowns, the same for the same seed", "[forest]") {
  const std::vector<float> radii{3.0f, 5.0f, 2.0f};
  float area = 0.0f, again = 0.0f;
  const auto placed = render::placeTrees(radii, 200, 7, area);
  REQUIRE(placed.size() == 200);
  CHECK(placed.front().position == glm::vec2(0.0f));
  for (std::size_t i = 0; i < placed.size(); ++i) {
    CHECK(placed[i].tree == i % radii.size());
    CHECK(glm::length(placed[i].position) <= area + 1e-3f);
    for (std::size_t j = 0; j < i; ++j) {
      CHECK(glm::distance(placed[i].position, placed[j].position) >= radii[placed[i].tree] + radii[placed[j].tree]);
    }
  }
  const auto same = render::placeTrees(radii, 200, 7, again);
  CHECK(same.size() == placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) CHECK(same[i].position == placed[i].position);
  CHECK(render::placeTrees(radii, 200, 8, again)[1].position != placed[1].position);
}

namespace {

ForestTreesOptions forestOf(const std::vector<std::string>& presets, std::uint32_t trees, std::uint32_t seeds, int maxLevels = 8) {
  ForestTreesOptions o;
  o.labels = presets;
  for (const std::string& name : presets) {
    SpeciesParams p = test::loadPreset(name);
    p.levels = std::min(p.levels, maxLevels);
    o.sources.emplace_back(weberPennModel(p));
  }
  o.trees = trees;
  o.seeds = seeds;
  o.details = static_cast<int>(render::kDetailLevels);
  o.maxDistinct = render::TreeRenderer::kMaxTrees / render::kDetailLevels;
  return o;
}

render::Forest plant(const ForestTreesOptions& o, std::vector<std::string>* progress = nullptr) {
  const auto trees = growForestTrees(o, [&](const std::string& line) {
    if (progress) progress->push_back(line);
  });
  return render::Forest(test::vulkan(), trees, o.trees, o.seed);
}

}  // namespace

TEST_CASE("a forest instances its distinct trees, culls whole trees and fakes more levels the farther a tree is", "[forest][render]") {
  std::vector<std::string> progress;
  const render::Forest forest = plant(forestOf({"palm"}, 30, 2), &progress);
  REQUIRE(forest.trees().size() == 2);  // two seeds of one species, grown once each
  CHECK(progress.size() == 2);
  CHECK(forest.placements().size() == 30);
  CHECK(forest.gpuTrees().size() == 2 * render::kDetailLevels);
  const auto& details = forest.trees()[0].detail;
  CHECK(details[1].impostorCount > details[0].impostorCount);  // near: only the few fronds the mesh fakes
  CHECK(details[1].patchCount < details[0].patchCount);
  CHECK(details[2].patchCount <= details[1].patchCount);  // the palm has two levels: the trunk stays

  const render::Camera overview = forest.overview(1.5f);
  const render::ForestFrame all = forest.frame(overview, 1.5f, {1e6f, 1e6f});
  CHECK(all.visible == 30);  // the overview sees every tree
  CHECK(all.culled == 0);
  CHECK(all.perDetail[0] == 30);
  const render::ForestFrame reduced = forest.frame(overview, 1.5f, {0.0f, 1e6f});
  CHECK(reduced.perDetail[1] == 30);
  for (const render::TreeInstance& i : reduced.instances) CHECK(i.tree % render::kDetailLevels == 1);
  const render::ForestFrame farAway = forest.frame(overview, 1.5f, {0.5f, 1.0f});
  CHECK(farAway.perDetail[2] == farAway.visible);  // everything beyond a metre fakes two levels
  for (const render::TreeInstance& i : farAway.instances) CHECK(i.tree % render::kDetailLevels == 2);
  for (const render::TreeInstance& i : farAway.instances) CHECK_FALSE(i.far);  // far only beyond its own distance
  const render::ForestFrame far = forest.frame(overview, 1.5f, {0.5f, 1.0f, 2.0f});
  CHECK(far.far == far.visible);
  for (const render::TreeInstance& i : far.instances) CHECK(i.far);
  // Standing at the centre looking along +x: the trees behind are culled, and only they.
  render::Camera inside;
  inside.eye = glm::vec3(0.0f, 0.0f, 1.7f);
  inside.target = glm::vec3(1.0f, 0.0f, 1.7f);
  const render::ForestFrame half = forest.frame(inside, 1.5f, {});
  CHECK(half.culled > 0);
  CHECK(half.visible + half.culled == 30);
  std::uint32_t behind = 0;
  for (const render::ForestPlacement& p : forest.placements()) {
    const float reach = forest.trees()[p.tree].crownRadius + (forest.trees()[p.tree].bounds.hi.z - forest.trees()[p.tree].bounds.lo.z);
    behind += p.position.x < -reach ? 1 : 0;
  }
  CHECK(half.culled >= behind);
}

TEST_CASE("golden image: a small mixed forest from the viewer's overview, each tree at its detail", "[forest][render][golden]") {
  render::RenderSession session(test::vulkan(), 200, 120, VK_SAMPLE_COUNT_1_BIT, test::textures());
  const render::Forest forest = plant(forestOf({"palm", "quaking-aspen"}, 8, 1, 2));  // two levels: light enough for the suite
  session.renderer().setTrees(forest.gpuTrees());
  const render::Camera camera = forest.overview(200.0f / 120.0f);
  // The nearest trees whole, the middle ones with a level faked, the farthest with two.
  const render::ForestFrame frame = forest.frame(camera, 200.0f / 120.0f, {45.0f, 55.0f});
  CHECK(frame.visible == 8);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::ACC;
  settings.tessLevel = 3.0f;
  settings.leaves = true;
  settings.impostors = true;
  settings.groundRadius = 200.0f;
  session.render(camera, settings, frame.instances);
  const test::GoldenCheck golden = test::checkGolden("forest-overview", session.image());
  INFO(golden.report);
  CHECK(golden.ok);
}

TEST_CASE("a far tree drawn without the tessellator looks as ACC at factor 1, with fewer fake branches", "[forest][render]") {
  render::RenderSession session(test::vulkan(), 160, 160, VK_SAMPLE_COUNT_1_BIT, test::textures());
  // Three levels: light enough for the suite; detail 2 meshes the trunk and fakes two levels.
  const render::Forest forest = plant(forestOf({"black-tupelo"}, 1, 1, 3));
  session.renderer().setTrees(forest.gpuTrees());
  const render::Camera camera = forest.overview(1.0f);
  render::ForestFrame frame = forest.frame(camera, 1.0f, {0.0f, 0.0f, 1e6f});  // two levels faked, not far
  REQUIRE(frame.instances.size() == 1);
  CHECK_FALSE(frame.instances[0].far);
  render::RenderSettings settings;
  settings.mode = render::RenderMode::ACC;
  settings.tessLevel = 1.0f;
  settings.ground = false;
  session.render(camera, settings, frame.instances);
  const Image tessellated = session.image();
  frame.instances[0].far = true;
  const render::FrameResult far = session.render(camera, settings, frame.instances);
  const Image flat = session.image();
  // The same triangles through the same corners: only rasterisation order and normal interpolation may differ.
  const ImageDifference d = compareImages(tessellated, flat, 24);
  INFO(d.pixelsOverThreshold << " pixels differ by more than 24");
  CHECK(d.pixelsOverThreshold <= 40);
  const render::GpuTree& tree = *forest.gpuTrees()[2];
  CHECK(far.gpu.triangles == tree.triangles);  // flat: two triangles per quad, nothing tessellated
  CHECK(tree.sketchCount * 3 < tree.impostorCount);
}

TEST_CASE("a forest whose distinct trees would pass its quad limit is refused before anything is grown", "[forest]") {
  ForestTreesOptions options = forestOf({"black-tupelo"}, 10, 4);
  options.maxQuads = 200'000;  // four tupelos of about 140,000 quads each, at three details
  std::vector<std::string> progress;
  CHECK_THROWS_WITH(growForestTrees(options, [&](const std::string& line) { progress.push_back(line); }),
                    Catch::Contains("4 distinct trees") && Catch::Contains("fewer species or --seeds"));
  CHECK(progress.empty());  // refused from the estimates: nothing was grown
}
