#include "platon/core/draw_list.h"

#include <algorithm>

namespace platon::core {

bool DrawList::circle(Place place, Point2 centre, float radius, Color color, uint32_t body, float squash) {
  if (!enabled_) return true;
  if (shapes_.size() >= kMaxShapes) return false;
  shapes_.push_back({ShapeKind::Circle, place, color, radius, centre, 0, 0, body, 0, 0, squash});
  return true;
}

bool DrawList::polygon(Place place, std::span<const Point2> points, Color color, uint32_t body) {
  if (!enabled_ || points.size() < 3) return true;
  if (shapes_.size() >= kMaxShapes || points_.size() + points.size() > kMaxPoints) return false;
  shapes_.push_back({ShapeKind::Polygon, place, color, 0, points[0], static_cast<uint32_t>(points_.size()),
                     static_cast<uint32_t>(points.size()), body});
  points_.insert(points_.end(), points.begin(), points.end());
  return true;
}

bool DrawList::wall(Place place, Point2 a, Point2 b, uint32_t tag, uint8_t lineKind, stage::TagStyle style) {
  if (!enabled_) return true;
  if (shapes_.size() >= kMaxShapes || points_.size() + 2 > kMaxPoints) return false;
  shapes_.push_back(
      {ShapeKind::Wall, place, Color{}, 0, a, static_cast<uint32_t>(points_.size()), 2, 0, tag, lineKind, 1, style});
  points_.push_back(a);
  points_.push_back(b);
  return true;
}

bool DrawList::line(Place place, Point2 a, Point2 b, float width, Color color) {
  if (!enabled_) return true;
  if (shapes_.size() >= kMaxShapes || points_.size() + 2 > kMaxPoints) return false;
  shapes_.push_back({ShapeKind::Line, place, color, width, a, static_cast<uint32_t>(points_.size()), 2});
  points_.push_back(a);
  points_.push_back(b);
  return true;
}

bool DrawList::text(Place place, Point2 at, std::string_view s, float height, Color color) {
  if (!enabled_) return true;
  if (shapes_.size() >= kMaxShapes || text_.size() + s.size() > kMaxTextBytes) return false;
  shapes_.push_back({ShapeKind::Text, place, color, height, at, static_cast<uint32_t>(text_.size()),
                     static_cast<uint32_t>(s.size())});
  text_.append(s);
  return true;
}

DrawList DrawList::between(const DrawList& from, const DrawList& to, float t) {
  DrawList out = to;
  const size_t n = std::min(from.shapes_.size(), to.shapes_.size());
  auto mix = [t](Point2 a, Point2 b) { return Point2{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; };
  for (size_t i = 0; i < n; ++i) {
    const DrawShape& a = from.shapes_[i];
    DrawShape& b = out.shapes_[i];
    if (a.kind != b.kind || a.place.screen != b.place.screen || a.place.face != b.place.face) continue;
    if (b.kind != ShapeKind::Text && a.count != b.count) continue;
    b.at = mix(a.at, b.at);
    b.size = a.size + (b.size - a.size) * t;
    b.squash = a.squash + (b.squash - a.squash) * t;
    if (b.kind == ShapeKind::Polygon || b.kind == ShapeKind::Line || b.kind == ShapeKind::Wall)
      for (uint32_t k = 0; k < b.count; ++k)
        out.points_[b.first + k] = mix(from.points_[a.first + k], out.points_[b.first + k]);
  }
  return out;
}

void DrawList::clear() {
  shapes_.clear();
  points_.clear();
  text_.clear();
}

}  // namespace platon::core
