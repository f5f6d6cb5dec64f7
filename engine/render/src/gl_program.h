// A linked GLSL program from vertex and fragment source; compile and link errors throw with the
// driver's log.
#pragma once
#include <epoxy/gl.h>

namespace platon::render {

class GlProgram {
 public:
  GlProgram(const char* vertexSource, const char* fragmentSource, const char* name);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace platon::render
