#pragma once
/// @file
/// A headless OpenGL 3.3 core context through EGL on Mesa's surfaceless platform: no X server,
/// no window, no GPU needed (llvmpipe renders on the CPU). Draw into framebuffer objects.

#include <memory>
#include <stdexcept>
#include <string>

namespace reconfig::render {

/// Thrown when no OpenGL context can be created (missing EGL/Mesa drivers, no GL 3.3).
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An EGL display + GL 3.3 core context made current on the constructing thread, with no
/// surface. Uses `EGL_PLATFORM_SURFACELESS_MESA` (EGL_MESA_platform_surfaceless); throws
/// `ContextError` naming the step that failed. Several may live at once (e.g. one per thread):
/// they share the display, which ends with the last of them.
class EglContext {
 public:
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  /// Makes the context current on the calling thread again.
  void make_current();

  /// GL_RENDERER and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;
  std::string version() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reconfig::render
