// The stage as lit triangles: each face a flat polygon with a dark rim along its edges, each map
// line a raised wall on its face coloured by its tag, and what the scripts draw on the faces
// (spheres for circles, flat shapes a little above the face). Positions are in stage space: the
// solid's centre at the origin, its radius 1, so depth precision never depends on the level's units.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "platon/core/display.h"

namespace platon::render {

struct LitVertex {
  float x, y, z;
  float nx, ny, nz;
  uint8_t r, g, b, a;
  float u = 0, v = 0;  // a face's own coordinates in tiles (kTiled only)
};

// Alpha 254 marks a colour drawn unlit (lit.vert): it glows. Alpha 253 marks a face's surface,
// drawn in tiles from (u, v) (lit.frag).
inline constexpr uint8_t kGlow = 254;
inline constexpr uint8_t kTiled = 253;

class StageMesh {
 public:
  explicit StageMesh(const core::StageView& stage);

  // The fixed part: faces, rims and walls.
  const std::vector<LitVertex>& fixed() const { return fixed_; }

  // The doors (lines of a kind whose passage is Door): raised walls while shut, a low dashed sill while their tag
  // is in `openTags`. Appended to `out` each frame, since they open and shut.
  void addDoors(std::span<const uint32_t> openTags, std::vector<LitVertex>& out) const;

  // The draw list's shapes on faces, appended to `out`; the debug overlay's (Place::overlay) to
  // `overlay`, which is drawn over everything (its triangles face out of their face, so those on
  // faces turned away are culled). Text is not drawn here.
  void addShapes(const core::DrawList& draw, physics::MapPartId onlyFace, std::vector<LitVertex>& out,
                 std::vector<LitVertex>& overlay) const;

  // A face point in stage space; false when the part is not on the stage.
  bool toStage(physics::MapPartId part, core::Point2 p, float lift, Eigen::Vector3f& out) const;
  bool normalOf(physics::MapPartId part, Eigen::Vector3f& out) const;
  // A camera pose (level units) in stage space: centred on the solid, scaled by its radius.
  camera::CameraPose toStage(const camera::CameraPose& pose) const;
  // The view-projection matrix of a pose (level units) for this mesh; everything drawn lies within
  // the solid's radius plus the tallest thing on a face.
  Eigen::Matrix4f viewProjection(const camera::CameraPose& pose, double verticalFov, double aspect) const;
  float scale() const { return scale_; }  // stage units per level unit

 private:
  struct Frame {
    physics::MapPartId part;
    Eigen::Vector3f origin, xAxis, yAxis, normal;  // in stage space (axes scaled too)
    std::vector<core::Point2> corners;             // the face's outline, in its own units
  };
  // The draw list's shapes [first, last): one entity's instances, drawn as one body.
  void addBall(std::span<const core::DrawShape> instances, std::vector<LitVertex>& out) const;
  void addBodyPolygon(const Frame& f, const core::DrawShape& s, std::span<const core::Point2> points,
                      std::vector<LitVertex>& out) const;
  void addOverlayDot(const Frame& f, const core::DrawShape& s, std::vector<LitVertex>& into) const;
  void addFlatShape(const Frame& f, const core::DrawShape& s, std::span<const core::Point2> points,
                    std::vector<LitVertex>& into) const;
  const Frame* frameOf(physics::MapPartId part) const;
  float outsideHeight(const Frame& f, const Eigen::Vector3f& p) const;
  void addFace(const core::ViewFace& face, size_t index);
  void addWall(const Frame& f, const core::ViewLine& line, std::vector<LitVertex>& out, float heightScale = 1,
               bool moving = false) const;
  struct Door {
    size_t frame;
    core::ViewLine line;
  };
  std::vector<Door> doors_;

  std::vector<Frame> frames_;
  std::vector<LitVertex> fixed_;
  float scale_ = 1;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();  // the solid's centre, level units
  float edge_ = 1;                                    // the longest edge, in stage units
  bool flat_ = false;
};

// Emits triangle a b c wound so that its front faces along `normal`.
void addTriangle(std::vector<LitVertex>& out, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                 const Eigen::Vector3f& c, const Eigen::Vector3f& normal, core::Color color);

}  // namespace platon::render
