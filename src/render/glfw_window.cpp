#include "reconfig/render/glfw_window.h"

#define GLFW_INCLUDE_NONE  // the renderer declares GL through epoxy
#include <GLFW/glfw3.h>

#include <string>

namespace reconfig::render {
namespace {

std::string last_glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown error";
}

}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, int width, int height) {
  if (!glfwInit()) throw ContextError("cannot open a window (" + last_glfw_error() + "); use --headless");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string error = last_glfw_error();
    glfwTerminate();
    throw ContextError("cannot create an OpenGL 3.3 window (" + error + ")");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::close_requested() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::cancel_close() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }
void GlfwWindow::poll_events(double timeout_seconds) const { glfwWaitEventsTimeout(timeout_seconds); }
void GlfwWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
void GlfwWindow::swap_buffers() { glfwSwapBuffers(window_); }
void GlfwWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

}  // namespace reconfig::render
