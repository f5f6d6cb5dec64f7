// Coloured triangles in pixels, gathered for one draw call: lines become quads, circles fans of
// triangles, convex polygons fans. Drawn with shaders/flat.*.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "gl_program.h"
#include "platon/core/draw_list.h"

namespace platon::render {

class Batch {
 public:
  Batch();
  ~Batch();
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  void line(core::Point2 a, core::Point2 b, float width, core::Color color);
  void circle(core::Point2 centre, float radius, core::Color color);
  void polygon(std::span<const core::Point2> points, core::Color color);  // convex
  void rectangle(core::Point2 topLeft, core::Point2 size, core::Color color);

  // Draws everything gathered onto a screen of that many pixels, then forgets it.
  void flush(float width, float height);

 private:
  struct Vertex {
    float x, y;
    uint8_t r, g, b, a;
  };
  void triangle(core::Point2 a, core::Point2 b, core::Point2 c, core::Color color);

  std::vector<Vertex> vertices_;
  GlProgram program_;
  GLint screenSize_ = -1;
  GLuint vao_ = 0, vbo_ = 0;
};

}  // namespace platon::render
