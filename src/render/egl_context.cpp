#include "reconfig/render/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <string>

namespace reconfig::render {
namespace {

std::string egl_error_name(EGLint error) {
  switch (error) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: {
      char code[32];
      std::snprintf(code, sizeof code, "EGL error 0x%04x", static_cast<unsigned>(error));
      return code;
    }
  }
}

[[noreturn]] void fail(const std::string& step) {
  throw ContextError("cannot create a headless OpenGL 3.3 context (EGL surfaceless, Mesa): " + step + " failed (" +
                     egl_error_name(eglGetError()) +
                     "); install libegl-mesa0 and libgl1-mesa-dri (./run deps)");
}

bool has_extension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = extensions; (p = std::strstr(p, name)); p += length)
    if ((p == extensions || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

// Contexts alive per display. Every context of the process gets the same surfaceless display,
// and eglTerminate ends it for all of them: the last context to go terminates it. Never
// destroyed: contexts held by static objects go after every static of this file.
struct Displays {
  std::mutex mutex;
  std::map<EGLDisplay, int> contexts;
};

Displays& displays() {
  static Displays* const instance = new Displays;
  return *instance;
}

void release_display(EGLDisplay display) {
  Displays& all = displays();
  std::lock_guard lock(all.mutex);
  if (--all.contexts[display] > 0) return;
  all.contexts.erase(display);
  eglTerminate(display);
}

}  // namespace

// Also when the constructor fails half-way: what was made is undone.
struct EglContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  bool initialized = false;  ///< counted in `displays()`

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (!initialized) return;
    if (context != EGL_NO_CONTEXT) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display, context);
    }
    release_display(display);
  }
};

EglContext::EglContext() : impl_(std::make_unique<Impl>()) {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless"))
    throw ContextError(
        "cannot create a headless OpenGL 3.3 context: the EGL client does not offer EGL_MESA_platform_surfaceless "
        "(is Mesa's EGL installed? ./run deps installs libegl-mesa0 and libgl1-mesa-dri)");
  impl_->display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (impl_->display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)");
  EGLint major = 0, minor = 0;
  {
    Displays& all = displays();
    std::lock_guard lock(all.mutex);  // not while another thread terminates it
    if (!eglInitialize(impl_->display, &major, &minor)) fail("eglInitialize");
    ++all.contexts[impl_->display];
    impl_->initialized = true;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(impl_->display, config_attributes, &config, 1, &count)) fail("eglChooseConfig");
  if (count == 0) {
    if (!has_extension(eglQueryString(impl_->display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
      fail("eglChooseConfig (no OpenGL config)");
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  impl_->context = eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, context_attributes);
  if (impl_->context == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL 3.3 core)");
  make_current();
}

EglContext::~EglContext() = default;

void EglContext::make_current() {
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
    fail("eglMakeCurrent (surfaceless)");
}

std::string EglContext::renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }

std::string EglContext::version() const { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

}  // namespace reconfig::render
