#include "render_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "assets.hpp"
#include "common/input_error.hpp"

namespace arbor::cli {

render::RenderMode parseMode(const std::string& mode, const std::string& field) {
  if (const auto found = render::findRenderMode(mode)) return *found;
  throw InputError(mode, field, "unknown mode; allowed: " + render::renderModeList());
}

std::string modeHelp() {
  std::string help;
  for (const render::RenderModeInfo& m : render::renderModes()) help += (help.empty() ? "" : "; ") + std::string(m.name) + ": " + m.summary;
  return help;
}

bool validationWanted(bool flag) {
#ifndef NDEBUG
  return true;
#else
  const char* env = std::getenv("ARBOR_VALIDATION");
  return flag || (env && std::string(env) == "1");
#endif
}

vk::ContextOptions vulkanOptions(bool validationFlag, const std::string& device) {
  vk::ContextOptions options;
  options.validation = validationWanted(validationFlag);
  options.device = device;
  return options;
}

bool reportValidationErrors(const vk::VulkanContext& context) {
  if (context.validationErrors() == 0) return false;
  std::fprintf(stderr, "arbor: error: %u Vulkan validation errors (see above)\n", context.validationErrors());
  return true;
}

void addAnisotropyOption(CLI::App* cmd, float& anisotropy, const std::string& byDevice) {
  cmd->add_option("--anisotropy", anisotropy, "Largest anisotropy of the bark's texture filtering, 1 (trilinear only) to 16 (default " + byDevice + ")")
      ->check(Number(1.0, 16.0));
}

render::TreeTextures treeTextures(float anisotropy) {
  render::TreeTextures textures = render::loadTreeTextures(assetDirectory());
  if (anisotropy > 0.0f) textures.barkAnisotropy = anisotropy;
  return textures;
}

render::TreeTextures treeTextures(float anisotropy, const vk::VulkanContext& context) {
  return treeTextures(anisotropy > 0.0f ? anisotropy : (context.isLavapipe() ? 1.0f : 0.0f));
}

glm::vec3 parseLight(const std::string& text) {
  const glm::vec2 angles = parseSunAngles(text);
  return render::sunDirection(angles.x, angles.y);
}

}  // namespace arbor::cli
