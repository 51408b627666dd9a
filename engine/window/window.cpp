#include "window.hpp"

#include <dlfcn.h>
#include <sys/socket.h>

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

// A software device (lavapipe) presents to X11 by writing every frame's pixels into the display connection, 3.7 MB
// at 1280 x 720, and waits while the server reads them unless the socket's send buffer holds the whole frame; room
// for one lets the next frame's work start at once. Looked up at run time: GLFW may be built without X11.
void roomForAFrameOnTheDisplayConnection() {
  using GetDisplay = void* (*)();
  using ConnectionNumber = int (*)(void*);
  const auto display = reinterpret_cast<GetDisplay>(dlsym(RTLD_DEFAULT, "glfwGetX11Display"));
  const auto connection = reinterpret_cast<ConnectionNumber>(dlsym(RTLD_DEFAULT, "XConnectionNumber"));
  void* x11 = display && connection ? display() : nullptr;
  if (!x11) return;
  const int socket = connection(x11);
  const int bytes = 16 << 20;  // a 1920 x 1080 frame twice; the kernel caps it at net.core.wmem_max unless privileged
  if (setsockopt(socket, SOL_SOCKET, SO_SNDBUFFORCE, &bytes, sizeof bytes) != 0) setsockopt(socket, SOL_SOCKET, SO_SNDBUF, &bytes, sizeof bytes);
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
  roomForAFrameOnTheDisplayConnection();
  glfwSetScrollCallback(window_, [](GLFWwindow*, double, double y) { gScroll += y; });
  // Key presses arrive as events, so a tap shorter than a frame is not lost between two looks at the keys.
  // (Installed before the overlay's, which calls it on.)
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS) static_cast<Window*>(glfwGetWindowUserPointer(w))->pressed_.push_back(key);
  });
  // The size is asked of the window system again only after it reported a change.
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { static_cast<Window*>(glfwGetWindowUserPointer(w))->sizeKnown_ = false; });
  glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { static_cast<Window*>(glfwGetWindowUserPointer(w))->sizeKnown_ = false; });
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

VkExtent2D Window::framebufferSize() const { return sizeKnown_ ? size_ : queryFramebufferSize(); }

VkExtent2D Window::queryFramebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  size_ = {static_cast<std::uint32_t>(std::max(w, 0)), static_cast<std::uint32_t>(std::max(h, 0))};
  sizeKnown_ = true;
  return size_;
}

void Window::waitWhileMinimised() {
  for (VkExtent2D e = framebufferSize(); (e.width == 0 || e.height == 0) && !shouldClose(); e = framebufferSize()) glfwWaitEvents();
}

void Window::toggleFullscreen() {
  sizeKnown_ = false;
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

void Window::resize(int width, int height) {
  glfwSetWindowSize(window_, width, height);
  sizeKnown_ = false;
}
void Window::minimise() {
  glfwIconifyWindow(window_);
  sizeKnown_ = false;
}
void Window::restore() {
  glfwRestoreWindow(window_);
  sizeKnown_ = false;
}

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
