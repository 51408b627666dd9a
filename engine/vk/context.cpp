#include "context.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace arbor::vk {

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw VulkanError(std::string(what) + " failed (VkResult " + std::to_string(result) + ")");
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasInstanceExtension(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// Higher is better: discrete GPUs first, lavapipe last; a name match beats everything.
int deviceScore(const VkPhysicalDeviceProperties& p, const std::string& wanted) {
  if (!wanted.empty()) return std::string(p.deviceName).find(wanted) != std::string::npos ? 100 : -1;
  switch (p.deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                       VkDebugUtilsMessageTypeFlagsEXT,
                                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<VulkanContext*>(user);
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    ++self->validationErrors_;
    std::fprintf(stderr, "arbor: Vulkan validation error: %s\n", data->pMessage);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    std::fprintf(stderr, "arbor: Vulkan validation warning: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

VulkanContext::VulkanContext(const ContextOptions& options) {
  validation_ = options.validation;
  if (validation_ && !hasLayer(kValidationLayer)) {
    throw VulkanError("the Khronos validation layer was asked for but is not installed (Debian: vulkan-validationlayers)");
  }
  std::vector<const char*> extensions = options.instanceExtensions;
  if (validation_ && hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "arbor";
  app.pEngineName = "arbor";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const char* layers[] = {kValidationLayer};
  if (validation_) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
  }
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger.pfnUserCallback = &VulkanContext::onMessage;
  messenger.pUserData = this;
  if (validation_) info.pNext = &messenger;  // also catches messages about instance creation itself
  check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance (is a Vulkan driver installed?)");
  if (validation_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create) check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }

  // A device that draws and tessellates, preferring the user's choice, then discrete GPUs.
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  int best = -1;
  std::string seen;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    VkPhysicalDeviceFeatures f;
    vkGetPhysicalDeviceFeatures(d, &f);
    seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, props.data());
    int family = -1;
    for (std::uint32_t i = 0; i < families; ++i) {
      if (props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
        family = static_cast<int>(i);
        break;
      }
    }
    const int score = deviceScore(p, options.device);
    if (family < 0 || !f.tessellationShader || score < 0 || score <= best) continue;
    best = score;
    physical_ = d;
    queueFamily_ = static_cast<std::uint32_t>(family);
  }
  if (physical_ == VK_NULL_HANDLE) {
    throw VulkanError(options.device.empty() ? "no Vulkan device with tessellation shaders found (devices: " + seen + ")"
                                             : "no Vulkan device named like '" + options.device + "' (devices: " + seen + ")");
  }
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  lavapipe_ = std::string(properties_.deviceName).find("llvmpipe") != std::string::npos;

  VkPhysicalDeviceFeatures available;
  vkGetPhysicalDeviceFeatures(physical_, &available);
  enabled_.tessellationShader = VK_TRUE;
  enabled_.fillModeNonSolid = available.fillModeNonSolid;
  enabled_.pipelineStatisticsQuery = available.pipelineStatisticsQuery;
  enabled_.samplerAnisotropy = available.samplerAnisotropy;
  enabled_.vertexPipelineStoresAndAtomics = available.vertexPipelineStoresAndAtomics;
  enabled_.largePoints = available.largePoints;
  enabled_.multiDrawIndirect = available.multiDrawIndirect;  // one call for all of an instance's patch draws

  // The culling pass decides how many draws a frame has: with this extension the GPU's count is used as is.
  std::vector<const char*> deviceExtensions = options.deviceExtensions;
  std::uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> deviceExtensionList(extensionCount);
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, deviceExtensionList.data());
  bool indirectCount = false;
  for (const VkExtensionProperties& e : deviceExtensionList) {
    indirectCount = indirectCount || std::string(e.extensionName) == VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME;
  }
  if (indirectCount) deviceExtensions.push_back(VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.pEnabledFeatures = &enabled_;
  deviceInfo.enabledExtensionCount = static_cast<std::uint32_t>(deviceExtensions.size());
  deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
  check(vkCreateDevice(physical_, &deviceInfo, nullptr, &device_), "vkCreateDevice");
  if (indirectCount) {
    drawIndirectCount_ = reinterpret_cast<PFN_vkCmdDrawIndirectCountKHR>(vkGetDeviceProcAddr(device_, "vkCmdDrawIndirectCountKHR"));
  }
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  check(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
}

VulkanContext::~VulkanContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::string VulkanContext::deviceDescription() const {
  const std::uint32_t v = properties_.driverVersion;
  std::string driver = std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
                       std::to_string(VK_API_VERSION_PATCH(v));
  if (properties_.vendorID == 0x10DE) {  // NVIDIA packs its version differently
    driver = std::to_string((v >> 22) & 0x3ff) + "." + std::to_string((v >> 14) & 0xff);
  }
  return std::string(properties_.deviceName) + " (driver " + driver + ")";
}

std::uint32_t VulkanContext::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags properties) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & properties) == properties) return i;
  }
  throw VulkanError("no Vulkan memory type with the required properties");
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(device_, &fenceInfo, nullptr, &fence), "vkCreateFence");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  const VkResult result = vkQueueSubmit(queue_, 1, &submit, fence);
  if (result == VK_SUCCESS) vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
  vkDestroyFence(device_, fence, nullptr);
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
  check(result, "vkQueueSubmit");
}

}  // namespace arbor::vk
