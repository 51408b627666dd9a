#include "window.hpp"

#include <algorithm>
#include <stdexcept>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "vk/context.hpp"

namespace arbor::window {

namespace {

double gScroll = 0.0;  // GLFW reports scrolling through a callback

bool initGlfw() {
  static const bool ok = [] {
    glfwSetErrorCallback([](int, const char*) {});  // a missing display is reported by displayAvailable()
    return glfwInit() == GLFW_TRUE;
  }();
  return ok;
}

}  // namespace

bool displayAvailable() { return initGlfw() && glfwVulkanSupported() == GLFW_TRUE; }

std::vector<const char*> requiredInstanceExtensions() {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  return std::vector<const char*>(names, names + count);
}

Window::Window(const std::string& title, int width, int height) {
  if (!displayAvailable()) throw std::runtime_error("no display: cannot open a window (set DISPLAY, or render offscreen)");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw std::runtime_error("glfwCreateWindow failed");
  glfwSetScrollCallback(window_, [](GLFWwindow*, double, double y) { gScroll += y; });
  // Key presses arrive as events, so a tap shorter than a frame is not lost between two looks at the keys.
  // (Installed before the overlay's, which calls it on.)
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS) static_cast<Window*>(glfwGetWindowUserPointer(w))->pressed_.push_back(key);
  });
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  vk::check(glfwCreateWindowSurface(instance, window_, nullptr, &surface), "glfwCreateWindowSurface");
  return surface;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void Window::pollEvents() {
  pressed_.clear();
  glfwPollEvents();
}

VkExtent2D Window::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {static_cast<std::uint32_t>(std::max(w, 0)), static_cast<std::uint32_t>(std::max(h, 0))};
}

void Window::waitWhileMinimised() {
  for (VkExtent2D e = framebufferSize(); (e.width == 0 || e.height == 0) && !shouldClose(); e = framebufferSize()) glfwWaitEvents();
}

void Window::toggleFullscreen() {
  if (glfwGetWindowMonitor(window_)) {
    glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_, windowedHeight_, 0);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return;
  glfwGetWindowPos(window_, &windowedX_, &windowedY_);
  glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

void Window::resize(int width, int height) { glfwSetWindowSize(window_, width, height); }
void Window::minimise() { glfwIconifyWindow(window_); }
void Window::restore() { glfwRestoreWindow(window_); }

bool Window::keyHeld(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }

bool Window::keyPressed(int key) { return std::find(pressed_.begin(), pressed_.end(), key) != pressed_.end(); }

bool Window::mouseLookHeld() const { return glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS; }

void Window::takeMouseDelta(double& dx, double& dy) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  dx = mouseKnown_ ? x - lastX_ : 0.0;
  dy = mouseKnown_ ? y - lastY_ : 0.0;
  lastX_ = x;
  lastY_ = y;
  mouseKnown_ = true;
}

double Window::takeScroll() {
  const double s = gScroll;
  gScroll = 0.0;
  return s;
}

}  // namespace arbor::window
