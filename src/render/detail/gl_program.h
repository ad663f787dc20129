#pragma once
// Compiling GLSL programs and turning GL errors into exceptions (the render module's shaders).

#include <epoxy/gl.h>

namespace reconfig::render::detail {

/// A linked program of one vertex and one fragment shader. Throws `std::runtime_error` with
/// the driver's log when a shader does not compile or the program does not link.
GLuint link_program(const char* vertex_source, const char* fragment_source);

/// Throws `std::runtime_error` naming `during` when the GL error flag is set.
void check_gl(const char* during);

}  // namespace reconfig::render::detail
