#pragma once
// Compiling GLSL programs, making vertex arrays, and turning GL errors into exceptions (the
// render module's GL plumbing).

#include <epoxy/gl.h>

namespace reconfig::render::detail {

/// A linked program of one vertex and one fragment shader. Throws `std::runtime_error` with
/// the driver's log when a shader does not compile or the program does not link.
GLuint link_program(const char* vertex_source, const char* fragment_source);

/// Creates a vertex array with an array buffer of tightly packed positions (attribute 0: three
/// floats) and an element buffer, and leaves all three bound.
void make_indexed_positions_vao(GLuint& vao, GLuint& vertex_buffer, GLuint& element_buffer);

/// Throws `std::runtime_error` naming `during` when the GL error flag is set.
void check_gl(const char* during);

}  // namespace reconfig::render::detail
