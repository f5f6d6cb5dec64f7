// The mouse on the solid: the ray from the eye through a pixel, the face it meets first and the
// point there in the face's own coordinates; and back, a face's point to the screen.
#pragma once
#include <Eigen/Core>
#include <optional>

#include "platon/camera/camera.h"
#include "platon/core/display.h"

namespace platon::editor {

// What the screen shows: the camera's pose and lens and the window's size in pixels.
struct Lens {
  camera::CameraPose pose;
  double verticalFov = 0.785398;
  int width = 1280, height = 720;
};

struct Ray {
  Eigen::Vector3d origin, direction;  // direction: unit length
};

// A point on a face: the face's index in StageView::faces and the point in its frame (units).
struct FacePoint {
  int face = -1;
  double x = 0, y = 0;
};

// The ray through pixel (px, py) (from the top left; a pixel's centre is at +0.5).
Ray rayThrough(const Lens& lens, double px, double py);
// The face the ray meets first from the front (its outside), and where; none when it misses.
std::optional<FacePoint> pickFace(const core::StageView& stage, const Ray& ray);
// Where the ray meets face `face`'s plane, in its frame, inside the face or not (dragging past an
// edge); none when the ray runs along or away from the plane.
std::optional<FacePoint> onFacePlane(const core::StageView& stage, int face, const Ray& ray);
// The pixel a point of a face shows at; none behind the eye.
std::optional<Eigen::Vector2d> toScreen(const Lens& lens, const core::StageView& stage, FacePoint point);
// The 3D point of a face point.
Eigen::Vector3d toSpace(const core::StageView& stage, FacePoint point);
// Whether (x, y) lies inside face `face` (or on its border).
bool insideFace(const core::StageView& stage, int face, double x, double y);

}  // namespace platon::editor
