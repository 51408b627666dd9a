#pragma once
// A Vulkan context with the validation layer on, shared by the render tests (lavapipe under CTest).
#include "render/render_session.hpp"
#include "vk/context.hpp"

namespace arbor::test {

vk::VulkanContext& vulkan();
const render::BarkImages& barkImages();

}  // namespace arbor::test
