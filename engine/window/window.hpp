#pragma once
// A GLFW window with a Vulkan surface and the input a walkthrough needs: keys held, mouse motion, resize,
// minimise and a fullscreen toggle.
#include <string>
#include <vector>


#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace arbor::window {

// True when GLFW can open a window here (a display is reachable).
bool displayAvailable();
// The instance extensions a window surface needs (after displayAvailable()).
std::vector<const char*> requiredInstanceExtensions();

class Window {
 public:
  Window(const std::string& title, int width, int height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  VkSurfaceKHR createSurface(VkInstance instance) const;

  bool shouldClose() const;
  void pollEvents();
  // Framebuffer size in pixels; 0 x 0 while minimised. Asked of the window system only after a change (on X11 the
  // question is a round trip, which waits until the server has taken in the frame just presented).
  VkExtent2D framebufferSize() const;
  // The same, asked now (after the swapchain found itself out of date).
  VkExtent2D queryFramebufferSize() const;
  VkExtent2D windowSize() const;  // in screen coordinates (the framebuffer's on X11; fewer on high-DPI screens)
  void waitWhileMinimised();
  void toggleFullscreen();
  // Scripted window events (tests, demos).
  void resize(int width, int height);
  void minimise();
  void restore();

  bool keyHeld(int key) const;
  bool keyPressed(int key);      // went down during the last pollEvents (a tap between two frames counts)
  bool mouseLookHeld() const;    // right button
  // Mouse motion in pixels since the last call.
  void takeMouseDelta(double& dx, double& dy);
  double takeScroll();
  // The pointer as its events last told, never asked of the window system (on X11 each question is a round trip).
  double cursorX() const { return cursorX_; }
  double cursorY() const { return cursorY_; }
  bool cursorInside() const { return cursorInside_; }
  bool focused() const { return focused_; }
  bool mouseButtonHeld(int button) const;
  bool mouseButtonPressed(int button) const;  // went down during the last pollEvents (a click shorter than a frame)
  bool clickedWithinFrame() const;            // a button went down and up again during the last pollEvents

 private:
  static Window& self(GLFWwindow* window);  // the Window whose GLFW window an event came from
  GLFWwindow* window_ = nullptr;
  int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
  double lastX_ = 0.0, lastY_ = 0.0;
  bool mouseKnown_ = false;
  std::vector<int> pressed_;  // keys that went down during the last pollEvents
  std::vector<int> buttonsPressed_;  // mouse buttons, likewise
  double cursorX_ = 0.0, cursorY_ = 0.0;
  bool cursorInside_ = false, focused_ = false;
  mutable VkExtent2D size_{}, windowSize_{};
  mutable bool sizeKnown_ = false;  // false after a resize, minimise or fullscreen, asked for or reported
};

}  // namespace arbor::window
