#include "render_support.hpp"

#include <cstdio>
#include <cstdlib>

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

const render::BarkImages& barkImages() {
  static const render::BarkImages images = render::loadBarkImages(ARBOR_ASSET_DIR);
  return images;
}

}  // namespace arbor::test
