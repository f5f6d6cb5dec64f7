// The debug overlay: the world's lines, platforms, entities and contacts as the physics has them.
#include "platon/core/debug_view.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace platon::core {
namespace {

constexpr Color kSolid{160, 255, 120, 255}, kOneWay{86, 180, 233, 255}, kWarp{130, 130, 150, 255};
constexpr Color kPlatform{230, 60, 230, 255}, kAnchor{255, 220, 0, 255}, kCopy{255, 140, 0, 255};
constexpr Color kVelocity{60, 220, 90, 255}, kContact{255, 60, 60, 255};

Point2 point(physics::Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// A line from a to b, dashed when `dashed` (dashes of `dash` units).
void line(DrawList& out, Place place, Point2 a, Point2 b, float width, Color color, bool dashed, float dash) {
  const float dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!dashed || length <= 2 * dash) {
    out.line(place, a, b, width, color);
    return;
  }
  for (float t = 0; t < length; t += 2 * dash) {
    const float u = std::min(t + dash, length);
    out.line(place, {a.x + dx * t / length, a.y + dy * t / length}, {a.x + dx * u / length, a.y + dy * u / length},
             width, color);
  }
}

// An arrow from `from` along (dx, dy).
void arrow(DrawList& out, Place place, Point2 from, float dx, float dy, float width, Color color) {
  const Point2 to{from.x + dx, from.y + dy};
  out.line(place, from, to, width, color);
  const float length = std::hypot(dx, dy);
  if (length <= 0) return;
  const float ux = dx / length, uy = dy / length, head = std::min(length / 3, 4 * width);
  out.line(place, to, {to.x - head * (ux + uy * 0.6f), to.y - head * (uy - ux * 0.6f)}, width, color);
  out.line(place, to, {to.x - head * (ux - uy * 0.6f), to.y - head * (uy + ux * 0.6f)}, width, color);
}

Color tagColor(const stage::TagStyle& s) { return {s.r, s.g, s.b, 255}; }

void drawPart(const Scene& scene, physics::MapPartId id, float unit, DrawList& out) {
  const physics::MapPart* part = scene.world().findMapPart(id);
  if (!part) return;
  const stage::TagTable& tags = *scene.tags();
  const Place place = Place::overlayOnFace(id);
  const auto segments = part->segments();
  const auto lines = part->lines();
  std::vector<std::pair<std::string, Point2>> labels;  // the tag words shown on this face
  for (size_t i = 0; i < segments.size(); ++i) {
    const Point2 a = point(segments[i].a), b = point(segments[i].b);
    const physics::Line& l = lines[i];
    if (l.kind == physics::LineKind::Warp) {
      line(out, place, a, b, unit, kWarp, true, 12 * unit);
      continue;
    }
    const bool oneWay = l.kind == physics::LineKind::OneWay;
    const Color color = l.tag != 0 ? tagColor(tags.style(l.tag)) : oneWay ? kOneWay : kSolid;
    line(out, place, a, b, 3 * unit, color, tags.passage(l.tag) != stage::Passage::Wall, 10 * unit);
    const float dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    if (oneWay && length > 0)  // ticks on its solid side: its left, seen from a to b
      for (float t = 0.25f; t < 1; t += 0.25f)
        out.line(place, {a.x + dx * t, a.y + dy * t},
                 {a.x + dx * t - dy / length * 8 * unit, a.y + dy * t + dx / length * 8 * unit}, unit, color);
    if (l.tag != 0 && length > 0) {  // its word beside its middle, on its left; once for lines close together
      const std::string word = tags.written(l.tag).substr(1);
      const Point2 at{(a.x + b.x) / 2 - dy / length * 12 * unit, (a.y + b.y) / 2 + dx / length * 12 * unit + 16 * unit};
      bool shown = false;
      for (const auto& [w, p] : labels) shown = shown || (w == word && std::hypot(p.x - at.x, p.y - at.y) < 80 * unit);
      if (!shown) out.text(place, at, word, 16 * unit, color), labels.emplace_back(word, at);
    }
  }
}

}  // namespace

void drawDebug(const Scene& scene, DrawList& out) {
  if (!out.enabled()) return;
  const physics::World& world = scene.world();
  // A unit of the overlay: a face's size over 600, so it reads the same on any solid.
  float unit = 4;
  if (const stage::Stage* stage = scene.stage()) {
    double size = 0;
    for (const physics::Vec2 c : stage->faces.at(0).corners)
      size = std::max({size, std::abs(static_cast<double>(c.x)), std::abs(static_cast<double>(c.y))});
    unit = static_cast<float>(size / 600);
    for (size_t i = 0; i < stage->faceCount(); ++i) drawPart(scene, stage->part(i), unit, out);
  }
  for (const physics::PlatformId id : world.platforms()) {
    const physics::PlatformView p = world.platform(id);
    const Place place = Place::overlayOnFace(p.part);
    for (const physics::PlatformLine& l : p.lines) {
      line(out, place, point(l.segment.a), point(l.segment.b), 3 * unit, kPlatform, false, 0);
      const Point2 mid{(point(l.segment.a).x + point(l.segment.b).x) / 2,
                       (point(l.segment.a).y + point(l.segment.b).y) / 2};
      arrow(out, place, mid, static_cast<float>(p.motion.x) * 8, static_cast<float>(p.motion.y) * 8, unit, kPlatform);
    }
    for (const physics::PlatformCopyView& c : p.copies)  // over an edge: its lines on the face beyond
      for (const physics::PlatformLine& l : c.lines)
        line(out, Place::overlayOnFace(c.part), point(l.segment.a), point(l.segment.b), 3 * unit, kPlatform, false, 0);
  }
  for (const physics::EntityId id : world.entities()) {
    const physics::EntityView e = world.entity(id);
    for (size_t k = 0; k < e.instanceCount(); ++k) {
      const physics::InstanceView in = e.instance(k);
      const Place place = Place::overlayOnFace(in.part);
      const Point2 at = point(in.position);
      const Color color = k == 0 ? kAnchor : kCopy;
      for (size_t v = 0; v < in.shape.size(); ++v) {
        const physics::Vec2 p = in.shape[v], q = in.shape[(v + 1) % in.shape.size()];
        out.line(place, {at.x + static_cast<float>(p.x), at.y + static_cast<float>(p.y)},
                 {at.x + static_cast<float>(q.x), at.y + static_cast<float>(q.y)}, unit, color);
      }
      if (k > 0) out.text(place, {at.x, at.y + 20 * unit}, "copy " + std::to_string(k), 10 * unit, color);
    }
    if (!e.inserted()) continue;
    // Its velocity (in its anchor's frame), drawn as 8 frames of motion.
    const physics::Vec2w v = e.velocity();
    arrow(out, Place::overlayOnFace(e.part()), point(e.position()), static_cast<float>(v.x) / 65536 * 8,
          static_cast<float>(v.y) / 65536 * 8, 2 * unit, kVelocity);
    for (const physics::Contact& c : e.contacts()) {
      const double n = std::hypot(static_cast<double>(c.normal.x), static_cast<double>(c.normal.y));
      if (n <= 0 || c.points.count == 0) continue;
      const Place place = Place::overlayOnFace(c.part);
      for (int i = 0; i < c.points.count; ++i) {
        const Point2 p = point(c.points.points[i]);
        out.circle(place, p, 4 * unit, kContact);
        arrow(out, place, p, static_cast<float>(static_cast<double>(c.normal.x) / n) * 50 * unit,
              static_cast<float>(static_cast<double>(c.normal.y) / n) * 50 * unit, 1.5f * unit, kContact);
      }
    }
  }
}

}  // namespace platon::core
