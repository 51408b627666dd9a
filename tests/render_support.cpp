#include "render_support.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "growth/weber_penn/weber_penn_model.hpp"
#include "image/image_compare.hpp"
#include "test_support.hpp"

namespace arbor::test {

namespace {

// CTest runs each test case in its own process: a validation error anywhere in it fails that process,
// even where the test itself did not look.
void failOnValidationErrors() {
  const std::uint32_t errors = vulkan().validationErrors();
  if (errors == 0) return;
  std::fprintf(stderr, "test: %u Vulkan validation errors (see above): failing\n", errors);
  std::fflush(stderr);
  std::_Exit(1);
}

}  // namespace

vk::VulkanContext& vulkan() {
  static vk::VulkanContext context([] {
    vk::ContextOptions o;
    o.validation = true;
    return o;
  }());
  static const bool registered = std::atexit(failOnValidationErrors) == 0;
  (void)registered;
  return context;
}

const render::TreeTextures& textures() {
  static const render::TreeTextures images = render::loadTreeTextures(ARBOR_ASSET_DIR);
  return images;
}

namespace {

Skeleton grownFor(const std::string& preset, int meshLevels, int impostorLevels) {
  const TreeModel model = weberPennModel(loadPreset(preset));
  GrowthOptions growth;
  growth.levels = (meshLevels > 0 ? meshLevels : model.levels()) + impostorLevels;
  return model.grow(growth);
}

}  // namespace

TreeScene::TreeScene(const std::string& preset, int meshLevels, int impostorLevels, std::uint32_t width, std::uint32_t height)
    : skeleton(grownFor(preset, meshLevels, impostorLevels)),
      faked(buildTree(skeleton, BuildOptions{MeshOptions{.levels = skeleton.levels - impostorLevels}, true})),
      session(vulkan(), width, height, VK_SAMPLE_COUNT_1_BIT, textures()) {
  session.setTree(faked.mesh.mesh, faked.patches, skeleton.leaves, faked.impostors);
}

render::Camera TreeScene::framed() const {
  const VkExtent2D e = session.extent();
  return render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f, static_cast<float>(e.width) / static_cast<float>(e.height));
}

GoldenCheck checkGolden(const std::string& name, const Image& actual) {
  namespace fs = std::filesystem;
  constexpr int kPixelThreshold = 16;
  constexpr double kMaxDifferingShare = 0.005;
  constexpr double kMinPsnr = 38.0;
  const fs::path golden = fs::path(ARBOR_SOURCE_DIR) / "tests" / "golden" / (name + ".png");
  const char* bless = std::getenv("ARBOR_BLESS");
  if (bless && std::string(bless) == "1") {
    writePng(golden.string(), actual);
    return {true, "blessed " + golden.string()};
  }
  if (!fs::exists(golden)) return {false, "no golden image " + golden.string() + " (bless with ARBOR_BLESS=1)"};
  const Image expected = readPng(golden.string());
  const ImageDifference d = compareImages(expected, actual, kPixelThreshold);
  const double share = static_cast<double>(d.pixelsOverThreshold) / (static_cast<double>(actual.width) * actual.height);
  std::ostringstream report;
  report << name << ": max channel difference " << d.maxChannelDifference << ", PSNR " << d.psnr << " dB, "
         << d.pixelsOverThreshold << " pixels over " << kPixelThreshold;
  const bool ok = share <= kMaxDifferingShare && d.psnr >= kMinPsnr;
  if (!ok) {
    const fs::path outDir = fs::path(ARBOR_BINARY_DIR) / "test-output" / "golden";
    fs::create_directories(outDir);
    writePng((outDir / (name + ".png")).string(), actual);
    writePng((outDir / (name + "-difference.png")).string(), differenceImage(expected, actual));
    report << "; picture and difference in " << outDir.string();
  }
  return {ok, report.str()};
}

}  // namespace arbor::test
