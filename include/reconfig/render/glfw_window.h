#pragma once
/// @file
/// A desktop window with an OpenGL 3.3 core context (GLFW): the studio's on-screen backend.
/// Only this backend's source file includes GLFW; callers get the raw handle for the UI layer.

#include <string>

#include "reconfig/render/egl_context.h"

struct GLFWwindow;

namespace reconfig::render {

/// A resizable window whose GL 3.3 core context is current on the constructing thread, with
/// vsync on. Throws `ContextError` when there is no display or no GL 3.3.
class GlfwWindow {
 public:
  GlfwWindow(const std::string& title, int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  /// Whether the user asked to close the window (title bar button, Alt-F4).
  bool close_requested() const;
  /// Withdraws a close request (the user chose to keep working).
  void cancel_close();
  /// Waits for and handles the window system's events (with a timeout in seconds, so
  /// animations and background results still get frames).
  void poll_events(double timeout_seconds) const;
  /// Size of the drawable area in pixels.
  void framebuffer_size(int& width, int& height) const;
  /// Shows the frame drawn into the default framebuffer.
  void swap_buffers();
  void set_title(const std::string& title);

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace reconfig::render
