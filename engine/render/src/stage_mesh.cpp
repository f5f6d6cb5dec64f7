#include "stage_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace platon::render {
namespace {

using core::Color;
using Eigen::Vector3f;

Vector3f vec(const core::Point3& p) { return {p.x, p.y, p.z}; }

// The look: a faceted stone world at dusk. Faces in two close warm slates (neighbours read apart
// without a rainbow) in faint tiles that show the solid turning; walls of pale stone; the
// tags in Okabe and Ito's palette for colour-blind readers, told apart by lightness as well as hue,
// and a hazard by its shape too (a row of spikes).
Color faceColor(size_t index) { return index % 2 ? Color{92, 96, 118, 255} : Color{82, 86, 108, 255}; }
constexpr Color kRim{30, 30, 44, 255};
constexpr float kTile = 512;  // level units

// A line's colour: its tag's look from the scene's tag table (stage/tags.h); a one-way line's own.
Color wallColor(const core::ViewLine& line) {
  if (line.kind == 2) return {86, 180, 233, 255};  // one-way: sky blue
  const stage::TagStyle& s = line.style;
  return {s.r, s.g, s.b, s.glow ? kGlow : uint8_t{255}};
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

// How far p lies outside the convex polygon `corners` (counter-clockwise): 0 inside or on it.
float outside(std::span<const core::Point2> corners, core::Point2 p) {
  bool inside = true;
  float nearest = 1e30f;
  const size_t n = corners.size();
  for (size_t k = 0; k < n; ++k) {
    const core::Point2 a = corners[k], b = corners[(k + 1) % n];
    const float ex = b.x - a.x, ey = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
    if (ex * py - ey * px < 0) inside = false;
    const float len2 = ex * ex + ey * ey;
    const float t = len2 > 0 ? std::clamp((px * ex + py * ey) / len2, 0.0f, 1.0f) : 0;
    nearest = std::min(nearest, std::hypot(px - t * ex, py - t * ey));
  }
  return inside ? 0 : nearest;
}

// `shape` cut to the convex polygon `window` (both counter-clockwise): Sutherland-Hodgman.
std::vector<core::Point2> clipped(std::vector<core::Point2> shape, std::span<const core::Point2> window) {
  const size_t n = window.size();
  for (size_t k = 0; k < n && !shape.empty(); ++k) {
    const core::Point2 a = window[k], b = window[(k + 1) % n];
    auto side = [&](core::Point2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
    std::vector<core::Point2> kept;
    for (size_t i = 0; i < shape.size(); ++i) {
      const core::Point2 p = shape[i], q = shape[(i + 1) % shape.size()];
      const float sp = side(p), sq = side(q);
      if (sp >= 0) kept.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const float t = sp / (sp - sq);
        kept.push_back({p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t});
      }
    }
    shape = std::move(kept);
  }
  return shape;
}

// The part of the segment a-b inside the convex polygon `window` (counter-clockwise), as the
// fractions of the way [t0, t1] along it; t0 > t1 when none of it is.
std::pair<float, float> insideOf(core::Point2 a, core::Point2 b, std::span<const core::Point2> window) {
  float t0 = 0, t1 = 1;
  const size_t n = window.size();
  for (size_t k = 0; k < n && t0 <= t1; ++k) {
    const core::Point2 p = window[k], q = window[(k + 1) % n];
    auto side = [&](core::Point2 v) { return (q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x); };
    const float sa = side(a), sb = side(b);
    if (sa < 0 && sb < 0) return {1, 0};
    if (sa < 0) t0 = std::max(t0, sa / (sa - sb));
    if (sb < 0) t1 = std::min(t1, sa / (sa - sb));
  }
  return {t0, t1};
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
                       vec(f.normal).normalized(), f.corners});
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
  // The face, with a rim: a dark ring between the outer polygon and the inner one (pulled toward the
  // centre), which is in the face's colour, a hair above it.
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
  // The rim as a ring around the inner polygon, not a whole polygon under it: each pixel of a face
  // is drawn once (on a software rasterizer the fill is most of the frame).
  for (size_t k = 0; k < n; ++k)
    quad(fixed_, outer[k], outer[(k + 1) % n], inner[(k + 1) % n], inner[k], f.normal, kRim);
  // The face's tiles, 512 level units square (the player's ball is 192 across): a floor with a
  // scale, which slides by as the camera turns. Drawn by the fragment shader from each vertex's
  // place in tiles (lit.frag): grid lines as triangles over the face cost a software rasterizer a
  // fifth of the frame, for their length across its tiles, not their pixels (render_frames).
  Color color = faceColor(index);
  if (!flat_) color.a = kTiled;
  const size_t first = fixed_.size();
  for (size_t k = 1; k + 1 < n; ++k) addTriangle(fixed_, inner[0], inner[k], inner[k + 1], f.normal, color);
  for (size_t i = first; i < fixed_.size(); ++i) {  // the vertex's place on the face, in tiles
    const Vector3f from = Vector3f(fixed_[i].x, fixed_[i].y, fixed_[i].z) - f.origin;
    fixed_[i].u = from.dot(f.xAxis) / f.xAxis.squaredNorm() / kTile;
    fixed_[i].v = from.dot(f.yAxis) / f.yAxis.squaredNorm() / kTile;
  }
  for (const core::ViewLine& line : face.lines) {
    if (line.kind == 1) continue;  // warp lines are the face's own edges: the rim shows them
    if (line.door)
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

void StageMesh::addWall(const Frame& f, const core::ViewLine& line, std::vector<LitVertex>& out, float heightScale,
                        bool moving) const {
  Color color = wallColor(line);
  if (heightScale < 1)
    color = {static_cast<uint8_t>(color.r / 2), static_cast<uint8_t>(color.g / 2), static_cast<uint8_t>(color.b / 2),
             255};
  // Walls scale with the solid, but never past a few level units: on a large face (a prism's 6144
  // long side) a wall as tall as the player's ball hid it.
  // A moving platform is a plank, thicker than a wall and in its own colour (a plain or one-way
  // line's; a tagged one keeps its tag's), so a lift reads as a lift.
  const bool oneWay = line.kind == 2;
  float height = std::min((oneWay ? 0.008f : 0.02f) * edge_, (oneWay ? 24.0f : 48.0f) * scale_) * heightScale;
  float halfWidth = std::min((oneWay ? 0.004f : 0.006f) * edge_, (oneWay ? 12.0f : 20.0f) * scale_);
  if (moving) {
    height = halfWidth = 32.0f * scale_;
    if (line.tag == 0) color = oneWay ? Color{120, 215, 205, 255} : Color{70, 190, 185, 255};
  }
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
  // A hazard says so by its shape as well as its colour: a row of spikes along its top.
  if (line.style.spikes && line.kind != 2 && heightScale >= 1) {
    const float length = (b - a).norm(), spike = 2.5f * halfWidth;
    const int count = std::max(1, static_cast<int>(length / (2 * spike)));
    const float pitch = length / static_cast<float>(count);
    for (int i = 0; i < count; ++i) {
      const Vector3f base = a + along * (pitch * (static_cast<float>(i) + 0.5f)) + up;
      const Vector3f tip = base + f.normal * (1.6f * spike), l = base - along * (0.5f * pitch),
                     r = base + along * (0.5f * pitch);
      addTriangle(out, l - side, r - side, tip, (-side.normalized() + f.normal).normalized(), color);
      addTriangle(out, r + side, l + side, tip, (side.normalized() + f.normal).normalized(), color);
    }
  }
}

// How far `p` stands above the face's plane.
float StageMesh::outsideHeight(const Frame& f, const Vector3f& p) const { return (p - f.origin).dot(f.normal); }

void StageMesh::addBall(std::span<const core::DrawShape> instances, std::vector<LitVertex>& out) const {
  // The ball sits on the face that holds its centre; near an edge it leans over it: the direction
  // it is lifted in blends the normals of the faces within its radius (each by how far inside that
  // radius it reaches), so it rolls over an edge with no jump and shows once.
  const core::DrawShape* home = nullptr;
  const Frame* homeFrame = nullptr;
  float homeOutside = 1e30f;
  Vector3f lift = Vector3f::Zero();
  for (const core::DrawShape& s : instances) {
    const Frame* f = frameOf(s.place.face);
    if (!f) continue;
    const float d = outside(f->corners, s.at);
    lift += std::max(0.0f, s.size - d) * f->normal;
    if (d < homeOutside) home = &s, homeFrame = f, homeOutside = d;
  }
  if (!home) return;
  const Vector3f n = lift.norm() > 1e-9f ? Vector3f(lift.normalized()) : homeFrame->normal;
  const float r = home->size * scale_;
  // Squashed or stretched along the way it stands, its volume kept and its foot on the face.
  const float along = std::clamp(home->squash, 0.25f, 4.0f), across = 1 / std::sqrt(along);
  const Vector3f centre =
      homeFrame->origin + home->at.x * homeFrame->xAxis + home->at.y * homeFrame->yAxis + r * along * n;
  const core::Color c = home->color;
  // Its shadow: a soft dark disc on the face beneath it (light from above the face), drawn first so
  // the ball covers it; smaller as the ball leaves the face. Shadows stay on the home face.
  const float height = outsideHeight(*homeFrame, centre) - r * along;
  const float shade = std::clamp(1 - height / (6 * r), 0.0f, 1.0f);
  if (shade > 0) {
    const Vector3f ground = homeFrame->origin + home->at.x * homeFrame->xAxis + home->at.y * homeFrame->yAxis +
                            0.0016f * edge_ * homeFrame->normal;
    const Vector3f u = homeFrame->xAxis.normalized() * (r * across * (0.6f + 0.4f * shade)),
                   w = homeFrame->yAxis.normalized() * (r * across * (0.6f + 0.4f * shade));
    const core::Color dark{12, 10, 24, static_cast<uint8_t>(120 * shade)};
    constexpr int kSides = 20;
    for (int k = 0; k < kSides; ++k) {
      const float t0 = 6.2831853f * static_cast<float>(k) / kSides,
                  t1 = 6.2831853f * static_cast<float>(k + 1) / kSides;
      addTriangle(out, ground, ground + std::cos(t0) * u + std::sin(t0) * w,
                  ground + std::cos(t1) * u + std::sin(t1) * w, homeFrame->normal, dark);
    }
  }
  for (const Vector3f& v : unitSphere()) {
    const float up = v.dot(n);
    const Vector3f p = centre + r * (across * (v - up * n) + along * up * n);
    // The ellipsoid's normal: the sphere's, scaled the other way.
    const Vector3f m = ((v - up * n) / across + up * n / along).normalized();
    out.push_back({p.x(), p.y(), p.z(), m.x(), m.y(), m.z(), c.r, c.g, c.b, c.a});
  }
}

void StageMesh::addBodyPolygon(const Frame& f, const core::DrawShape& s, std::span<const core::Point2> points,
                               std::vector<LitVertex>& out) const {
  // The instance cut at its face's edges (the next face draws the rest), raised as a block.
  std::vector<core::Point2> shape(points.begin() + s.first, points.begin() + s.first + s.count);
  core::Point2 mid{0, 0};
  for (const core::Point2 p : shape)
    mid.x += p.x / static_cast<float>(s.count), mid.y += p.y / static_cast<float>(s.count);
  float inradius = 1e30f;
  for (size_t k = 0; k < shape.size(); ++k) {
    const core::Point2 a = shape[k], b = shape[(k + 1) % shape.size()];
    const float len = std::hypot(b.x - a.x, b.y - a.y);
    if (len > 0)
      inradius = std::min(inradius, std::fabs((mid.x - a.x) * (b.y - a.y) - (mid.y - a.y) * (b.x - a.x)) / len);
  }
  shape = clipped(std::move(shape), f.corners);
  if (shape.size() < 3) return;
  const Vector3f up = std::min(0.6f * inradius, 48.0f) * scale_ * f.normal;
  auto at = [&](core::Point2 p) { return Vector3f(f.origin + p.x * f.xAxis + p.y * f.yAxis); };
  for (size_t k = 1; k + 1 < shape.size(); ++k)
    addTriangle(out, at(shape[0]) + up, at(shape[k]) + up, at(shape[k + 1]) + up, f.normal, s.color);
  const core::Color side{static_cast<uint8_t>(s.color.r * 3 / 4), static_cast<uint8_t>(s.color.g * 3 / 4),
                         static_cast<uint8_t>(s.color.b * 3 / 4), s.color.a};
  for (size_t k = 0; k < shape.size(); ++k) {
    const Vector3f a = at(shape[k]), b = at(shape[(k + 1) % shape.size()]);
    const Vector3f outward = (b - a).cross(f.normal);
    if (outward.norm() < 1e-12f) continue;
    quad(out, a, b, b + up, a + up, outward.normalized(), side);
  }
}

void StageMesh::addShapes(const core::DrawList& draw, physics::MapPartId onlyFace, std::vector<LitVertex>& out,
                          std::vector<LitVertex>& overlay) const {
  const auto points = draw.points();
  const auto shapes = draw.shapes();
  for (size_t index = 0; index < shapes.size(); ++index) {
    core::DrawShape s = shapes[index];
    if (s.place.screen || s.kind == core::ShapeKind::Text) continue;
    std::vector<LitVertex>& into = s.place.overlay ? overlay : out;
    if (s.color.a == kGlow || s.color.a == kTiled) s.color.a = 255;  // the stage's own markers, not the scripts'
    if (s.kind == core::ShapeKind::Circle && s.place.overlay) {      // a flat dot over the walls
      if (const Frame* f = frameOf(s.place.face)) addOverlayDot(*f, s, into);
      continue;
    }
    if (s.kind == core::ShapeKind::Circle && s.body != 0 && !flat_) {
      size_t end = index + 1;  // the entity's instances come one after another
      while (end < shapes.size() && shapes[end].kind == core::ShapeKind::Circle && shapes[end].body == s.body) ++end;
      addBall(shapes.subspan(index, end - index), into);
      index = end - 1;
      continue;
    }
    if (flat_ && s.place.face != onlyFace) continue;
    const Frame* f = frameOf(s.place.face);
    if (!f) continue;
    if (s.kind == core::ShapeKind::Wall) {
      // Cut at the face's edges: a platform over an edge is drawn on each face by its own lines
      // there (its copy's on the face beyond), never off the solid.
      const core::Point2 a = points[s.first], b = points[s.first + 1];
      const auto [t0, t1] = insideOf(a, b, f->corners);
      if (t0 >= t1) continue;
      auto at = [&](float t) { return core::Point2{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; };
      addWall(*f, {at(t0), at(t1), s.tag, s.lineKind, s.style}, into, 1, true);
      continue;
    }
    if (s.kind == core::ShapeKind::Polygon && s.body != 0) {
      addBodyPolygon(*f, s, points, into);
      continue;
    }
    addFlatShape(*f, s, points, into);
  }
}

// A dot of the debug overlay: a flat disc a little above its face, glowing.
void StageMesh::addOverlayDot(const Frame& f, const core::DrawShape& s, std::vector<LitVertex>& into) const {
  constexpr int kSides = 12;
  for (int k = 0; k < kSides; ++k) {
    const float a0 = static_cast<float>(2 * M_PI * k / kSides), a1 = static_cast<float>(2 * M_PI * (k + 1) / kSides);
    auto on = [&](float a) {
      return Vector3f(f.origin + (s.at.x + s.size * std::cos(a)) * f.xAxis + (s.at.y + s.size * std::sin(a)) * f.yAxis +
                      0.004f * edge_ * f.normal);
    };
    const Vector3f c = f.origin + s.at.x * f.xAxis + s.at.y * f.yAxis + 0.004f * edge_ * f.normal;
    addTriangle(into, c, on(a0), on(a1), f.normal, {s.color.r, s.color.g, s.color.b, kGlow});
  }
}

// A shape the scripts drew on a face that is neither a wall nor a body: a circle as a ball resting
// on it, a polygon or a line flat a little above it.
void StageMesh::addFlatShape(const Frame& f, const core::DrawShape& s, std::span<const core::Point2> points,
                             std::vector<LitVertex>& into) const {
  auto at = [&](core::Point2 p, float lift) {
    return Vector3f(f.origin + p.x * f.xAxis + p.y * f.yAxis + lift * edge_ * f.normal);
  };
  switch (s.kind) {
    case core::ShapeKind::Circle: {
      // A ball resting on the face.
      const float r = s.size * scale_;
      const Vector3f centre = at(s.at, 0) + r * f.normal;
      const auto& sphere = unitSphere();
      for (const Vector3f& v : sphere) {
        const Vector3f p = centre + r * v;
        into.push_back({p.x(), p.y(), p.z(), v.x(), v.y(), v.z(), s.color.r, s.color.g, s.color.b, s.color.a});
      }
      break;
    }
    case core::ShapeKind::Polygon:
      for (uint32_t i = 1; i + 1 < s.count; ++i)
        addTriangle(into, at(points[s.first], 0.003f), at(points[s.first + i], 0.003f),
                    at(points[s.first + i + 1], 0.003f), f.normal, s.color);
      break;
    case core::ShapeKind::Line: {
      const float lift = 0.004f;
      core::Color color = s.color;  // the overlay's glow: it reads the same in any light
      if (s.place.overlay) color.a = kGlow;
      for (uint32_t i = 1; i < s.count; ++i) {
        const core::Point2 p = points[s.first + i - 1], q = points[s.first + i];
        const float dx = q.x - p.x, dy = q.y - p.y, len = std::hypot(dx, dy);
        if (len <= 0) continue;
        const float hx = -dy / len * s.size / 2, hy = dx / len * s.size / 2;
        quad(into, at({p.x - hx, p.y - hy}, lift), at({q.x - hx, q.y - hy}, lift), at({q.x + hx, q.y + hy}, lift),
             at({p.x + hx, p.y + hy}, lift), f.normal, color);
      }
      break;
    }
    case core::ShapeKind::Text:
    case core::ShapeKind::Wall:
      break;
  }
}

}  // namespace platon::render
