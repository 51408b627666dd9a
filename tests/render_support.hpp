#pragma once
// A Vulkan context with the validation layer on, shared by the render tests (lavapipe under CTest).
#include <string>

#include "image/png_io.hpp"
#include "render/render_session.hpp"
#include "vk/context.hpp"

namespace arbor::test {

vk::VulkanContext& vulkan();
const render::TreeTextures& textures();

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
