#include "platon/editor/pick.h"

#include <cmath>

namespace platon::editor {
namespace {

Eigen::Vector3d vec(core::Point3 p) { return {p.x, p.y, p.z}; }

}  // namespace

Ray rayThrough(const Lens& lens, double px, double py) {
  const double h = std::max(1, lens.height), w = std::max(1, lens.width);
  const double ndcX = 2 * px / w - 1, ndcY = 1 - 2 * py / h;
  const double t = std::tan(lens.verticalFov / 2);
  const Eigen::Vector3d right = lens.pose.orientation * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d d = lens.pose.forward() + t * ndcY * lens.pose.up() + t * (w / h) * ndcX * right;
  return {lens.pose.eye(), d.normalized()};
}

Eigen::Vector3d toSpace(const core::StageView& stage, FacePoint p) {
  const core::ViewFace& f = stage.faces.at(static_cast<size_t>(p.face));
  return vec(f.origin) + p.x * vec(f.xAxis) + p.y * vec(f.yAxis);
}

bool insideFace(const core::StageView& stage, int face, double x, double y) {
  const std::vector<core::Point2>& c = stage.faces.at(static_cast<size_t>(face)).corners;
  for (size_t i = 0; i < c.size(); ++i) {
    const core::Point2 a = c[i], b = c[(i + 1) % c.size()];
    const double cross = (double(b.x) - a.x) * (y - a.y) - (double(b.y) - a.y) * (x - a.x);
    const double length = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
    if (cross < -1e-6 * length) return false;  // outside this edge (a hair of slack: float corners)
  }
  return true;
}

std::optional<FacePoint> onFacePlane(const core::StageView& stage, int face, const Ray& ray) {
  const core::ViewFace& f = stage.faces.at(static_cast<size_t>(face));
  const Eigen::Vector3d n = vec(f.normal), o = vec(f.origin);
  const double along = n.dot(ray.direction);
  if (std::abs(along) < 1e-12) return std::nullopt;
  const double t = n.dot(o - ray.origin) / along;
  if (t <= 0) return std::nullopt;
  const Eigen::Vector3d q = ray.origin + t * ray.direction - o;
  return FacePoint{face, q.dot(vec(f.xAxis)), q.dot(vec(f.yAxis))};
}

std::optional<FacePoint> pickFace(const core::StageView& stage, const Ray& ray) {
  std::optional<FacePoint> best;
  double bestT = INFINITY;
  for (size_t i = 0; i < stage.faces.size(); ++i) {
    const core::ViewFace& f = stage.faces[i];
    if (vec(f.normal).dot(ray.direction) >= 0) continue;  // seen from inside, or edge on
    const auto p = onFacePlane(stage, static_cast<int>(i), ray);
    if (!p || !insideFace(stage, p->face, p->x, p->y)) continue;
    const double t = (toSpace(stage, *p) - ray.origin).norm();
    if (t < bestT) bestT = t, best = p;
  }
  return best;
}

std::optional<Eigen::Vector2d> toScreen(const Lens& lens, const core::StageView& stage, FacePoint point) {
  const Eigen::Vector3d d = toSpace(stage, point) - lens.pose.eye();
  const Eigen::Vector3d local = lens.pose.orientation.conjugate() * d;  // x right, y up, -z forward
  if (local.z() >= 0) return std::nullopt;
  const double t = std::tan(lens.verticalFov / 2), aspect = double(lens.width) / std::max(1, lens.height);
  const double ndcX = local.x() / (-local.z() * t * aspect), ndcY = local.y() / (-local.z() * t);
  return Eigen::Vector2d((ndcX + 1) / 2 * lens.width, (1 - ndcY) / 2 * lens.height);
}

}  // namespace platon::editor
