#include "render_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "species/species_io.hpp"

namespace arbor::cli {

render::RenderMode parseMode(const std::string& mode, const std::string& field) {
  if (mode == "flat") return render::RenderMode::Flat;
  if (mode == "pn") return render::RenderMode::PN;
  if (mode == "acc") return render::RenderMode::ACC;
  throw SpeciesError(mode, field, "unknown mode; allowed: flat, pn, acc");
}

void parseSize(const std::string& text, std::uint32_t& width, std::uint32_t& height) {
  // Digits only: sscanf's %u would wrap 4294967360 to 64.
  const auto x = text.find('x');
  const auto side = [&](const std::string& digits) -> long {
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
    return std::stol(digits);
  };
  const long w = x == std::string::npos ? -1 : side(text.substr(0, x)), h = x == std::string::npos ? -1 : side(text.substr(x + 1));
  if (w < 16 || h < 16 || w > 8192 || h > 8192) {
    throw SpeciesError(text, "--size", "expected WIDTHxHEIGHT with each in [16, 8192], e.g. 640x800");
  }
  width = static_cast<std::uint32_t>(w);
  height = static_cast<std::uint32_t>(h);
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

glm::vec2 parseSunAngles(const std::string& text) {
  float az = 0.0f, el = 0.0f;
  char comma = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%f%c%f%c", &az, &comma, &el, &rest) != 3 || comma != ',' || !(el >= -90.0f && el <= 90.0f) ||
      !std::isfinite(az)) {
    throw SpeciesError(text, "--light", "expected AZIMUTH,ELEVATION in degrees, elevation from -90 to 90, e.g. 30,45");
  }
  return {az, el};
}

glm::vec3 parseLight(const std::string& text) {
  const glm::vec2 angles = parseSunAngles(text);
  return render::sunDirection(angles.x, angles.y);
}

}  // namespace arbor::cli
