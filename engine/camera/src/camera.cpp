#include "platon/camera/camera.h"

#include <algorithm>
#include <cmath>

namespace platon::camera {
namespace {

// The orientation whose forward is `forward` and whose right is `rightHint` made perpendicular to it.
Eigen::Quaterniond lookAlong(const Eigen::Vector3d& forward, const Eigen::Vector3d& rightHint) {
  const Eigen::Vector3d back = -forward.normalized();
  Eigen::Vector3d right = rightHint - rightHint.dot(back) * back;
  if (right.squaredNorm() < 1e-24) right = back.unitOrthogonal();  // walking along the view line: any
  right.normalize();
  Eigen::Matrix3d axes;
  axes.col(0) = right;
  axes.col(1) = back.cross(right);
  axes.col(2) = back;
  return Eigen::Quaterniond(axes).normalized();
}

}  // namespace

CameraPose CameraPose::between(const CameraPose& a, const CameraPose& b, double t) {
  CameraPose p;
  p.orientation = a.orientation.slerp(t, b.orientation);
  p.centre = a.centre + t * (b.centre - a.centre);
  p.distance = a.distance + t * (b.distance - a.distance);
  return p;
}

CameraPose Camera::wanted(const CameraTarget& target) {
  CameraPose p;
  Eigen::Vector3d out = target.player - target.centre;
  const double radial = out.norm();
  if (radial < 1e-12) out = Eigen::Vector3d::UnitZ();
  p.orientation = lookAlong(-out, target.normal.cross(target.down));
  p.centre = target.centre;
  p.distance = radial + target.viewHeight;
  return p;
}

void Camera::set(const CameraTarget& target, int width, int height) {
  resize(width, height);
  pose_ = wanted(target);
}

void Camera::resize(int width, int height) {
  if (width > 0 && height > 0) aspect_ = static_cast<double>(width) / height;
}

void Camera::lerp(const CameraTarget& target, double seconds) {
  if (!(seconds > 0)) return;  // no time (or NaN): nowhere to go
  const CameraPose goal = wanted(target);
  // Exponential approach, the same after any split of the time; then capped at the top speed.
  double t = 1 - std::exp(-seconds / std::max(settings_.settleSeconds, 1e-9));
  Eigen::Quaterniond from = pose_.orientation;
  if (from.dot(goal.orientation) < 0) from.coeffs() = -from.coeffs();  // the short way round
  const double gap = from.angularDistance(goal.orientation);
  const double reach = std::max(settings_.topSpeed, 0.0) * seconds;
  if (gap * t > reach) t = reach / gap;  // gap > 0 here
  pose_.orientation = from.slerp(t, goal.orientation).normalized();
  pose_.centre = goal.centre;
  const double z = 1 - std::exp(-seconds / std::max(settings_.zoomSeconds, 1e-9));
  pose_.distance += z * (goal.distance - pose_.distance);
}

Eigen::Matrix4f viewMatrix(const CameraPose& pose) {
  const Eigen::Matrix3d toCamera = pose.orientation.conjugate().toRotationMatrix();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = toCamera;
  m.topRightCorner<3, 1>() = -(toCamera * pose.eye());
  return m.cast<float>();
}

Eigen::Matrix4f projectionMatrix(const CameraPose& pose, double verticalFov, double aspect, double radius) {
  // Everything drawn lies within `radius` of the centre (walls and the player a little above the
  // faces: the caller's radius includes them).
  const double farPlane = pose.distance + radius;
  const double nearPlane = std::max(pose.distance - radius, farPlane * 1e-3);
  const double f = 1 / std::tan(verticalFov / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
  m(2, 3) = 2 * farPlane * nearPlane / (nearPlane - farPlane);
  m(3, 2) = -1;
  return m.cast<float>();
}

}  // namespace platon::camera
