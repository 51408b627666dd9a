#include "render_support.hpp"

namespace arbor::test {

vk::VulkanContext& vulkan() {
  static vk::VulkanContext context([] {
    vk::ContextOptions o;
    o.validation = true;  // any validation error fails the test that caused it
    return o;
  }());
  return context;
}

const render::BarkImages& barkImages() {
  static const render::BarkImages images = render::loadBarkImages(ARBOR_ASSET_DIR);
  return images;
}

}  // namespace arbor::test
