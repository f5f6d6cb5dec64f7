#include "stage_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace platon::render {
namespace {

using core::Color;
using Eigen::Vector3f;

Vector3f vec(const core::Point3& p) { return {p.x, p.y, p.z}; }

// Faces in two close tones, so that neighbours read apart without a rainbow.
Color faceColor(size_t index) { return index % 2 ? Color{86, 98, 124, 255} : Color{76, 88, 114, 255}; }
constexpr Color kRim{34, 38, 50, 255};

// The game's tags (scripts/rules/game.lua): 0 solid, 1 hazard, 2 goal, 3 checkpoint, 1000 + n
// door, 2000 + n switch. Hazards and the goal glow.
Color wallColor(const core::ViewLine& line) {
  if (line.kind == 2) return {190, 130, 240, 255};
  if (line.tag == 1) return {240, 70, 55, kGlow};
  if (line.tag == 2) return {90, 235, 120, kGlow};
  if (line.tag == 3) return {90, 160, 245, 255};
  if (line.tag >= 1000 && line.tag < 2000) return {245, 160, 60, 255};
  if (line.tag >= 2000 && line.tag < 3000) return {250, 225, 70, 255};
  return {226, 228, 234, 255};
}

void quad(std::vector<LitVertex>& out, const Vector3f& a, const Vector3f& b, const Vector3f& c, const Vector3f& d,
          const Vector3f& n, Color color) {
  addTriangle(out, a, b, c, n, color);
  addTriangle(out, a, c, d, n, color);
}

// A unit sphere as triangles (positions are their own normals).
const std::vector<Vector3f>& unitSphere() {
  static const std::vector<Vector3f> sphere = [] {
    constexpr int kRings = 10, kSegments = 16;
    auto at = [](int ring, int seg) {
      const float theta = static_cast<float>(M_PI * ring / kRings),
                  phi = static_cast<float>(2 * M_PI * seg / kSegments);
      return Vector3f(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    };
    std::vector<Vector3f> v;
    for (int r = 0; r < kRings; ++r)
      for (int s = 0; s < kSegments; ++s) {
        const Vector3f a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
        if (r > 0) v.insert(v.end(), {a, b, d});
        if (r < kRings - 1) v.insert(v.end(), {b, c, d});
      }
    return v;
  }();
  return sphere;
}

}  // namespace

void addTriangle(std::vector<LitVertex>& out, const Vector3f& a, const Vector3f& b, const Vector3f& c,
                 const Vector3f& normal, Color color) {
  const bool flip = (b - a).cross(c - a).dot(normal) < 0;
  for (const Vector3f* p : {&a, flip ? &c : &b, flip ? &b : &c})
    out.push_back({p->x(), p->y(), p->z(), normal.x(), normal.y(), normal.z(), color.r, color.g, color.b, color.a});
}

StageMesh::StageMesh(const core::StageView& stage) : flat_(stage.flat) {
  scale_ = 1.0f / std::max(stage.radius, 1e-6f);
  centre_ = {stage.centre.x, stage.centre.y, stage.centre.z};
  edge_ = stage.edge * scale_;
  const Vector3f centre = vec(stage.centre);
  for (const core::ViewFace& f : stage.faces)
    frames_.push_back({f.part, (vec(f.origin) - centre) * scale_, vec(f.xAxis) * scale_, vec(f.yAxis) * scale_,
                       vec(f.normal).normalized()});
  for (size_t i = 0; i < stage.faces.size(); ++i) addFace(stage.faces[i], i);
}

const StageMesh::Frame* StageMesh::frameOf(physics::MapPartId part) const {
  for (const Frame& f : frames_)
    if (f.part == part) return &f;
  return nullptr;
}

bool StageMesh::toStage(physics::MapPartId part, core::Point2 p, float lift, Vector3f& out) const {
  const Frame* f = frameOf(part);
  if (!f) return false;
  out = f->origin + p.x * f->xAxis + p.y * f->yAxis + lift * edge_ * f->normal;
  return true;
}

camera::CameraPose StageMesh::toStage(const camera::CameraPose& pose) const {
  camera::CameraPose p = pose;
  p.centre = (pose.centre - centre_) * scale_;
  p.distance *= scale_;
  return p;
}

Eigen::Matrix4f StageMesh::viewProjection(const camera::CameraPose& pose, double verticalFov, double aspect) const {
  const camera::CameraPose p = toStage(pose);
  return camera::projectionMatrix(p, verticalFov, aspect, 1.3) * camera::viewMatrix(p);
}

bool StageMesh::normalOf(physics::MapPartId part, Vector3f& out) const {
  const Frame* f = frameOf(part);
  if (!f) return false;
  out = f->normal;
  return true;
}

void StageMesh::addFace(const core::ViewFace& face, size_t index) {
  const Frame& f = frames_[index];
  auto at = [&](core::Point2 p, float lift) {
    return Vector3f(f.origin + p.x * f.xAxis + p.y * f.yAxis + lift * edge_ * f.normal);
  };
  const size_t n = face.corners.size();
  if (n < 3) return;
  // The face, with a rim: the outer polygon dark, the inner one (pulled toward the centre) in the
  // face's colour, a hair above it.
  core::Point2 mid{0, 0};
  for (const core::Point2 c : face.corners) mid.x += c.x / static_cast<float>(n), mid.y += c.y / static_cast<float>(n);
  float inradius = 1e30f;
  for (size_t k = 0; k < n; ++k) {
    const core::Point2 a = face.corners[k], b = face.corners[(k + 1) % n];
    const float ex = b.x - a.x, ey = b.y - a.y, len = std::hypot(ex, ey);
    if (len > 0) inradius = std::min(inradius, std::fabs((mid.x - a.x) * ey - (mid.y - a.y) * ex) / len);
  }
  const float rim = flat_ ? 0 : std::min(0.012f * edge_ / scale_, 0.2f * inradius);
  const float shrink = inradius > 0 ? 1 - rim / inradius : 1;
  std::vector<Vector3f> outer, inner;
  for (const core::Point2 c : face.corners) {
    outer.push_back(at(c, 0));
    inner.push_back(at({mid.x + (c.x - mid.x) * shrink, mid.y + (c.y - mid.y) * shrink}, 0.0008f));
  }
  for (size_t k = 1; k + 1 < n; ++k) {
    addTriangle(fixed_, outer[0], outer[k], outer[k + 1], f.normal, kRim);
    addTriangle(fixed_, inner[0], inner[k], inner[k + 1], f.normal, faceColor(index));
  }
  for (const core::ViewLine& line : face.lines) {
    if (line.kind == 1) continue;  // warp lines are the face's own edges: the rim shows them
    if (line.tag >= 1000 && line.tag < 2000)
      doors_.push_back({index, line});
    else
      addWall(f, line, fixed_);
  }
}

void StageMesh::addDoors(std::span<const uint32_t> openTags, std::vector<LitVertex>& out) const {
  for (const Door& d : doors_) {
    const bool open = std::find(openTags.begin(), openTags.end(), d.line.tag) != openTags.end();
    addWall(frames_[d.frame], d.line, out, open ? 0.12f : 1.0f);
  }
}

void StageMesh::addWall(const Frame& f, const core::ViewLine& line, std::vector<LitVertex>& out,
                        float heightScale) const {
  Color color = wallColor(line);
  if (heightScale < 1)
    color = {static_cast<uint8_t>(color.r / 2), static_cast<uint8_t>(color.g / 2), static_cast<uint8_t>(color.b / 2),
             255};
  const bool oneWay = line.kind == 2;
  const float height = (oneWay ? 0.008f : 0.02f) * edge_ * heightScale, halfWidth = (oneWay ? 0.004f : 0.006f) * edge_;
  const Vector3f a = f.origin + line.a.x * f.xAxis + line.a.y * f.yAxis;
  const Vector3f b = f.origin + line.b.x * f.xAxis + line.b.y * f.yAxis;
  Vector3f along = b - a;
  if (along.norm() < 1e-9f) return;
  along.normalize();
  const Vector3f side = f.normal.cross(along).normalized() * halfWidth, up = f.normal * height;
  const Vector3f ext = along * halfWidth;  // square ends reach past the endpoints, closing joints
  const Vector3f a0 = a - ext - side, a1 = a - ext + side, b0 = b + ext - side, b1 = b + ext + side;
  quad(out, a0 + up, b0 + up, b1 + up, a1 + up, f.normal, color);
  quad(out, a0, b0, b0 + up, a0 + up, -side.normalized(), color);
  quad(out, a1, b1, b1 + up, a1 + up, side.normalized(), color);
  quad(out, a0, a1, a1 + up, a0 + up, -along, color);
  quad(out, b0, b1, b1 + up, b0 + up, along, color);
}

void StageMesh::addShapes(const core::DrawList& draw, physics::MapPartId onlyFace, std::vector<LitVertex>& out) const {
  const auto points = draw.points();
  for (core::DrawShape s : draw.shapes()) {
    if (s.place.screen || s.kind == core::ShapeKind::Text) continue;
    if (s.color.a == kGlow) s.color.a = 255;  // the glow marker is the stage's own, not the scripts'
    if (flat_ && s.place.face != onlyFace) continue;
    const Frame* f = frameOf(s.place.face);
    if (!f) continue;
    auto at = [&](core::Point2 p, float lift) {
      return Vector3f(f->origin + p.x * f->xAxis + p.y * f->yAxis + lift * edge_ * f->normal);
    };
    switch (s.kind) {
      case core::ShapeKind::Circle: {
        // A ball resting on the face.
        const float r = s.size * scale_;
        const Vector3f centre = at(s.at, 0) + r * f->normal;
        const auto& sphere = unitSphere();
        for (const Vector3f& v : sphere) {
          const Vector3f p = centre + r * v;
          out.push_back({p.x(), p.y(), p.z(), v.x(), v.y(), v.z(), s.color.r, s.color.g, s.color.b, s.color.a});
        }
        break;
      }
      case core::ShapeKind::Polygon:
        for (uint32_t i = 1; i + 1 < s.count; ++i)
          addTriangle(out, at(points[s.first], 0.003f), at(points[s.first + i], 0.003f),
                      at(points[s.first + i + 1], 0.003f), f->normal, s.color);
        break;
      case core::ShapeKind::Line:
        for (uint32_t i = 1; i < s.count; ++i) {
          const core::Point2 p = points[s.first + i - 1], q = points[s.first + i];
          const float dx = q.x - p.x, dy = q.y - p.y, len = std::hypot(dx, dy);
          if (len <= 0) continue;
          const float hx = -dy / len * s.size / 2, hy = dx / len * s.size / 2;
          quad(out, at({p.x - hx, p.y - hy}, 0.004f), at({q.x - hx, q.y - hy}, 0.004f),
               at({q.x + hx, q.y + hy}, 0.004f), at({p.x + hx, p.y + hy}, 0.004f), f->normal, s.color);
        }
        break;
      case core::ShapeKind::Text:
        break;
    }
  }
}

}  // namespace platon::render
