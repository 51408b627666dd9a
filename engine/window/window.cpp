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

Window& Window::self(GLFWwindow* window) { return *static_cast<Window*>(glfwGetWindowUserPointer(window)); }

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
    if (action == GLFW_PRESS) self(w).pressed_.push_back(key);
  });
  // The size is asked of the window system again only after it reported a change.
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { self(w).sizeKnown_ = false; });
  glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { self(w).sizeKnown_ = false; });
  // The pointer is followed by its events; the overlay's callbacks, installed after these, call them on.
  glfwGetCursorPos(window_, &cursorX_, &cursorY_);
  cursorInside_ = glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE;
  focused_ = glfwGetWindowAttrib(window_, GLFW_FOCUSED) == GLFW_TRUE;
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    self(w).cursorX_ = x;
    self(w).cursorY_ = y;
  });
  glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int entered) { self(w).cursorInside_ = entered == GLFW_TRUE; });
  glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int focused) { self(w).focused_ = focused == GLFW_TRUE; });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (action == GLFW_PRESS) self(w).buttonsPressed_.push_back(button);
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
  buttonsPressed_.clear();
  glfwPollEvents();
}

VkExtent2D Window::framebufferSize() const { return sizeKnown_ ? size_ : queryFramebufferSize(); }

VkExtent2D Window::queryFramebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  size_ = {static_cast<std::uint32_t>(std::max(w, 0)), static_cast<std::uint32_t>(std::max(h, 0))};
  glfwGetWindowSize(window_, &w, &h);
  windowSize_ = {static_cast<std::uint32_t>(std::max(w, 0)), static_cast<std::uint32_t>(std::max(h, 0))};
  sizeKnown_ = true;
  return size_;
}

VkExtent2D Window::windowSize() const {
  if (!sizeKnown_) queryFramebufferSize();
  return windowSize_;
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
  dx = mouseKnown_ ? cursorX_ - lastX_ : 0.0;
  dy = mouseKnown_ ? cursorY_ - lastY_ : 0.0;
  lastX_ = cursorX_;
  lastY_ = cursorY_;
  mouseKnown_ = true;
}

bool Window::mouseButtonHeld(int button) const { return glfwGetMouseButton(window_, button) == GLFW_PRESS; }

bool Window::mouseButtonPressed(int button) const {
  return std::find(buttonsPressed_.begin(), buttonsPressed_.end(), button) != buttonsPressed_.end();
}

bool Window::clickedWithinFrame() const {
  return std::any_of(buttonsPressed_.begin(), buttonsPressed_.end(), [&](int button) { return !mouseButtonHeld(button); });
}

double Window::takeScroll() {
  const double s = gScroll;
  gScroll = 0.0;
  return s;
}

}  // namespace arbor::window
