#include "batch.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "shaders.h"

namespace platon::render {

Batch::Batch() : program_(shaders::flat_vert, shaders::flat_frag, "flat") {
  screenSize_ = program_.uniform("screenSize");
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, r)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
}

Batch::~Batch() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void Batch::triangle(core::Point2 a, core::Point2 b, core::Point2 c, core::Color k) {
  vertices_.push_back({a.x, a.y, k.r, k.g, k.b, k.a});
  vertices_.push_back({b.x, b.y, k.r, k.g, k.b, k.a});
  vertices_.push_back({c.x, c.y, k.r, k.g, k.b, k.a});
}

void Batch::line(core::Point2 a, core::Point2 b, float width, core::Color color) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0)) return;
  const float nx = -dy / length * width / 2, ny = dx / length * width / 2;
  // Extended by half the width at both ends, so that lines meeting at a corner close it.
  const float ex = dx / length * width / 2, ey = dy / length * width / 2;
  const core::Point2 p0{a.x - ex + nx, a.y - ey + ny}, p1{a.x - ex - nx, a.y - ey - ny};
  const core::Point2 p2{b.x + ex - nx, b.y + ey - ny}, p3{b.x + ex + nx, b.y + ey + ny};
  triangle(p0, p1, p2, color);
  triangle(p0, p2, p3, color);
}

void Batch::circle(core::Point2 c, float radius, core::Color color) {
  if (!(radius > 0)) return;
  const int segments = std::clamp(static_cast<int>(radius), 12, 64);
  core::Point2 previous{c.x + radius, c.y};
  for (int i = 1; i <= segments; ++i) {
    const float angle = 6.2831853f * static_cast<float>(i) / static_cast<float>(segments);
    const core::Point2 next{c.x + radius * std::cos(angle), c.y + radius * std::sin(angle)};
    triangle(c, previous, next, color);
    previous = next;
  }
}

void Batch::polygon(std::span<const core::Point2> points, core::Color color) {
  for (size_t i = 2; i < points.size(); ++i) triangle(points[0], points[i - 1], points[i], color);
}

void Batch::rectangle(core::Point2 topLeft, core::Point2 size, core::Color color) {
  const core::Point2 corners[4] = {topLeft,
                                   {topLeft.x + size.x, topLeft.y},
                                   {topLeft.x + size.x, topLeft.y + size.y},
                                   {topLeft.x, topLeft.y + size.y}};
  polygon(corners, color);
}

void Batch::flush(float width, float height) {
  if (vertices_.empty()) return;
  glUseProgram(program_.id());
  glUniform2f(screenSize_, width, height);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)), vertices_.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices_.size()));
  glBindVertexArray(0);
  vertices_.clear();
}

}  // namespace platon::render
