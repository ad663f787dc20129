#include "gl_program.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace reconfig::render::detail {
namespace {

/// Throws with the driver's log, after deleting `object`, unless its `status` is set.
template <typename GetStatus, typename GetLog, typename Delete>
void require_status(GLuint object, GLenum status, GetStatus get_status, GetLog get_log, Delete destroy,
                    const char* failure) {
  GLint ok = 0;
  get_status(object, status, &ok);
  if (ok) return;
  char log[2048];
  get_log(object, sizeof log, nullptr, log);
  destroy(object);
  throw std::runtime_error(std::string("render: ") + failure + ": " + log);
}

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  require_status(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader,
                 "shader compilation failed");
  return shader;
}

}  // namespace

GLuint link_program(const char* vertex, const char* fragment) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  require_status(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram, "shader link failed");
  return program;
}

void make_indexed_positions_vao(GLuint& vao, GLuint& vertex_buffer, GLuint& element_buffer) {
  glGenVertexArrays(1, &vao);
  glGenBuffers(1, &vertex_buffer);
  glGenBuffers(1, &element_buffer);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, element_buffer);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
}

void check_gl(const char* during) {
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw std::runtime_error(std::string("render: OpenGL error ") + code + " while " + during);
  }
}

}  // namespace reconfig::render::detail
