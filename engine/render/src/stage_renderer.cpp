#include "stage_renderer.h"

#include <cmath>
#include <cstddef>

#include "shaders.h"

namespace platon::render {

void describeLitVertices() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LitVertex), reinterpret_cast<void*>(offsetof(LitVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(LitVertex), reinterpret_cast<void*>(offsetof(LitVertex, nx)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(LitVertex),
                        reinterpret_cast<void*>(offsetof(LitVertex, r)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(LitVertex), reinterpret_cast<void*>(offsetof(LitVertex, u)));
}

StageRenderer::StageRenderer() : program_(shaders::lit_vert, shaders::lit_frag, "lit") {
  viewProjection_ = program_.uniform("viewProjection");
  lightDirection_ = program_.uniform("lightDirection");
  eye_ = program_.uniform("eye");
  for (Buffer* b : {&fixed_, &shapes_, &overlay_}) {
    glGenVertexArrays(1, &b->vao);
    glGenBuffers(1, &b->vbo);
    glBindVertexArray(b->vao);
    glBindBuffer(GL_ARRAY_BUFFER, b->vbo);
    describeLitVertices();
  }
  glBindVertexArray(0);
}

StageRenderer::~StageRenderer() {
  for (Buffer* b : {&fixed_, &shapes_, &overlay_}) {
    glDeleteBuffers(1, &b->vbo);
    glDeleteVertexArrays(1, &b->vao);
  }
}

void StageRenderer::upload(Buffer& buffer, const std::vector<LitVertex>& vertices, GLenum usage) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  const size_t bytes = vertices.size() * sizeof(LitVertex);
  if (vertices.size() > buffer.capacity || usage == GL_STATIC_DRAW) {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), vertices.data(), usage);
    buffer.capacity = vertices.size();
  } else if (bytes > 0) {
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), vertices.data());
  }
  buffer.count = vertices.size();
}

void StageRenderer::drawBuffer(const Buffer& buffer) {
  if (buffer.count == 0) return;
  glBindVertexArray(buffer.vao);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(buffer.count));
}

void StageRenderer::draw(const core::View& view, const core::DrawList& draw, int width, int height) {
  width_ = width, height_ = height;
  if (!view.stage) {  // nothing to draw, and nothing to project onto
    stage_.reset();
    mesh_.reset();
    return;
  }
  if (view.stage != stage_) {
    stage_ = view.stage;
    mesh_.emplace(*stage_);
    upload(fixed_, mesh_->fixed(), GL_STATIC_DRAW);
  }
  scratch_.clear();
  overlayScratch_.clear();
  mesh_->addDoors(view.openTags, scratch_);
  mesh_->addShapes(draw, view.face, scratch_, overlayScratch_);
  upload(shapes_, scratch_, GL_STREAM_DRAW);
  upload(overlay_, overlayScratch_, GL_STREAM_DRAW);

  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  viewProjectionMatrix_ = mesh_->viewProjection(view.camera, view.verticalFov, aspect);
  const camera::CameraPose pose = mesh_->toStage(view.camera);
  const Eigen::Vector3f eye = pose.eye().cast<float>();
  eyePosition_ = eye;
  const Eigen::Vector3f light =
      (pose.orientation * Eigen::Vector3d(-0.35, 0.6, 1.0)).normalized().cast<float>();  // over the left shoulder

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glUseProgram(program_.id());
  glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, viewProjectionMatrix_.data());
  glUniform3f(lightDirection_, light.x(), light.y(), light.z());
  glUniform3f(eye_, eye.x(), eye.y(), eye.z());
  drawBuffer(fixed_);
  drawBuffer(shapes_);
  glDisable(GL_DEPTH_TEST);  // the debug overlay: over walls and bodies, culled on faces turned away
  drawBuffer(overlay_);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
}

bool StageRenderer::project(physics::MapPartId part, core::Point2 p, float height, core::Point2& pixel,
                            float& pixels) const {
  Eigen::Vector3f at, above, normal;
  if (!mesh_ || !mesh_->toStage(part, p, 0.01f, at) || !mesh_->toStage(part, {p.x, p.y + height}, 0.01f, above) ||
      !mesh_->normalOf(part, normal))
    return false;
  if (normal.dot(eyePosition_ - at) <= 0) return false;  // on a face turned away: hidden behind the solid
  auto toPixels = [&](const Eigen::Vector3f& q, core::Point2& out) {
    const Eigen::Vector4f clip = viewProjectionMatrix_ * Eigen::Vector4f(q.x(), q.y(), q.z(), 1);
    if (clip.w() <= 1e-6f) return false;
    out = {(clip.x() / clip.w() * 0.5f + 0.5f) * static_cast<float>(width_),
           (0.5f - clip.y() / clip.w() * 0.5f) * static_cast<float>(height_)};
    return true;
  };
  core::Point2 top;
  if (!toPixels(at, pixel) || !toPixels(above, top)) return false;
  pixels = std::hypot(top.x - pixel.x, top.y - pixel.y);
  return true;
}

}  // namespace platon::render
