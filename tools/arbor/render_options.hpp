#pragma once
// Command-line values shared by `arbor render` and `arbor bench tess`: mode names, image sizes, validation.
#include <cstdint>
#include <string>

#include "cli_values.hpp"
#include "render/render_session.hpp"
#include "render/renderer.hpp"
#include "vk/context.hpp"

namespace arbor::cli {

// "flat", "pn" or "acc"; anything else is bad input naming `field`.
render::RenderMode parseMode(const std::string& mode, const std::string& field = "--mode");
// Every render mode with its one-line summary, for --help.
std::string modeHelp();
// The same as a unit vector towards the sun.
glm::vec3 parseLight(const std::string& text);
// --anisotropy: the bark's largest anisotropic filtering, 1 (trilinear only) to 16; `byDevice` names the default.
void addAnisotropyOption(CLI::App* cmd, float& anisotropy, const std::string& byDevice);
// The textures with the bark filtered as asked (0: TreeTextures' own default).
render::TreeTextures treeTextures(float anisotropy);
// The same, where none is asked for (0) filtered for the device: trilinearly on lavapipe, which filters
// anisotropically in software (a third of the viewer's frame at 8, and ACC at factor 16 four times slower).
render::TreeTextures treeTextures(float anisotropy, const vk::VulkanContext& context);
// On when asked for, when ARBOR_VALIDATION=1 (the tests set it), and always in debug builds.
bool validationWanted(bool flag);
// What every Vulkan command asks of the context: validation as validationWanted decides, the preferred device.
vk::ContextOptions vulkanOptions(bool validationFlag, const std::string& device);
// True (after saying how many on stderr) when the context's validation layer reported errors.
bool reportValidationErrors(const vk::VulkanContext& context);

}  // namespace arbor::cli
