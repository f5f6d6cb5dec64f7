#include "gl_program.h"

#include <stdexcept>
#include <string>

namespace platon::render {
namespace {

GLuint compile(GLenum type, const char* source, const char* name) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  char log[2048] = "";
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  glDeleteShader(shader);
  throw std::runtime_error(std::string("shader ") + name + (type == GL_VERTEX_SHADER ? ".vert" : ".frag") + ": " + log);
}

}  // namespace

GlProgram::GlProgram(const char* vertexSource, const char* fragmentSource, const char* name) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertexSource, name);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragmentSource, name);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok) return;
  char log[2048] = "";
  glGetProgramInfoLog(id_, sizeof log, nullptr, log);
  glDeleteProgram(id_);
  throw std::runtime_error(std::string("shader program ") + name + ": " + log);
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

}  // namespace platon::render
