// Draws the stage in 3D from the view's camera: the fixed mesh (kept on the GPU for as long as the
// view holds the same StageView) and the frame's shapes (uploaded each frame), in two draw calls
// with one lit shader, depth-tested, back faces culled.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <optional>

#include "gl_program.h"
#include "stage_mesh.h"

namespace platon::render {

// Describes LitVertex (position, normal, colour: attributes 0, 1, 2) for the bound vertex array
// and buffer.
void describeLitVertices();

class StageRenderer {
 public:
  StageRenderer();
  ~StageRenderer();
  StageRenderer(const StageRenderer&) = delete;
  StageRenderer& operator=(const StageRenderer&) = delete;

  void draw(const core::View& view, const core::DrawList& draw, int width, int height);
  // Where a face point shows on the screen, in pixels from the top left, after draw(), and how
  // many pixels `height` face units above it span there; false on a face turned away from the
  // eye, behind it, or off the stage.
  bool project(physics::MapPartId part, core::Point2 p, float height, core::Point2& pixel, float& pixels) const;

 private:
  struct Buffer {
    GLuint vao = 0, vbo = 0;
    size_t capacity = 0, count = 0;
  };
  void upload(Buffer& buffer, const std::vector<LitVertex>& vertices, GLenum usage);
  void drawBuffer(const Buffer& buffer);

  GlProgram program_;
  GLint viewProjection_ = -1, lightDirection_ = -1, eye_ = -1;
  Buffer fixed_, shapes_, overlay_;
  std::shared_ptr<const core::StageView> stage_;  // what fixed_ holds
  std::optional<StageMesh> mesh_;
  std::vector<LitVertex> scratch_, overlayScratch_;
  Eigen::Matrix4f viewProjectionMatrix_ = Eigen::Matrix4f::Identity();
  Eigen::Vector3f eyePosition_ = Eigen::Vector3f::Zero();  // stage space, for project()
  int width_ = 1, height_ = 1;
};

}  // namespace platon::render
