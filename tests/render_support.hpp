#pragma once
// A Vulkan context with the validation layer on, shared by the render tests (lavapipe under CTest).
#include <string>

#include "growth/skeleton.hpp"
#include "image/png_io.hpp"
#include "tree/build_tree.hpp"
#include "render/render_session.hpp"
#include "vk/context.hpp"

namespace arbor::test {

vk::VulkanContext& vulkan();
const render::TreeTextures& textures();

// A preset grown, meshed and uploaded with its leaves and fake branches into its own offscreen session.
struct TreeScene {
  Skeleton skeleton;
  TreeGeometry faked;  // the mesh of the meshed levels and its patches, the others as fake-branch segments
  render::RenderSession session;

  // meshLevels 0: the species' Levels; impostorLevels more are grown and drawn as fake branches.
  TreeScene(const std::string& preset, int meshLevels, int impostorLevels, std::uint32_t width, std::uint32_t height);
  // The whole planted tree from the default framing (azimuth 25, elevation 6 degrees).
  render::Camera framed() const;
};

// Screenshot regression against tests/golden/<name>.png. Tolerance: lavapipe is bit-exact on one machine;
// another CPU's LLVM code may round a few pixels apart, so at most 0.5 % of the pixels may differ by more than
// 16/255 in a channel, and the PSNR over the picture must reach 38 dB. With ARBOR_BLESS=1 the picture becomes
// the golden instead; a failure writes it and an amplified difference into <build>/test-output/golden/.
struct GoldenCheck {
  bool ok = false;
  std::string report;  // what differed, for INFO
};
GoldenCheck checkGolden(const std::string& name, const Image& actual);

}  // namespace arbor::test
