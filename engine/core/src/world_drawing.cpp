#include "platon/core/world_drawing.h"

#include <cmath>
#include <vector>

namespace platon::core {
namespace {

// The radius of the shape's smallest enclosing circle about its origin (for a ball: the regular
// polygon's circumradius, what `circle = r` made).
float radiusOf(std::span<const physics::Vec2> shape) {
  double most = 0;
  for (const physics::Vec2 v : shape)
    most = std::max(most, std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)));
  return static_cast<float>(most);
}

void drawEntity(const physics::EntityView& e, const Look& look, DrawList& out, std::vector<Point2>& scratch) {
  if (look.form == Look::Form::None) return;
  const uint32_t body = e.id().index + 1;
  const float radius = radiusOf(e.shape().vertices());  // turning does not change it
  for (const physics::InstanceView i : e.instances()) {
    const Place place = Place::onFace(i.part);
    const Point2 at{static_cast<float>(i.position.x), static_cast<float>(i.position.y)};
    if (look.form == Look::Form::Ball) {
      out.circle(place, at, radius, look.color, body, look.squash);
      continue;
    }
    scratch.clear();
    for (const physics::Vec2 v : i.shape)
      scratch.push_back({at.x + static_cast<float>(v.x), at.y + static_cast<float>(v.y)});
    out.polygon(place, scratch, look.color, body);
  }
}

}  // namespace

void drawWorld(const physics::World& world, const Looks& looks, const stage::TagTable& tags, DrawList& out) {
  if (!out.enabled()) return;
  std::vector<Point2> scratch;
  for (const physics::PlatformId id : world.platforms()) {
    const physics::PlatformView p = world.platform(id);
    // Its own lines, and over a face's edge its copy's on the face beyond (the renderer cuts each
    // at its face's edges).
    auto draw = [&](physics::MapPartId part, std::span<const physics::PlatformLine> lines) {
      for (const physics::PlatformLine& line : lines) {
        const physics::Segment& s = line.segment;
        out.wall(Place::onFace(part), {static_cast<float>(s.a.x), static_cast<float>(s.a.y)},
                 {static_cast<float>(s.b.x), static_cast<float>(s.b.y)}, line.tag,
                 line.kind == physics::LineKind::OneWay ? 2 : 0, tags.style(line.tag));
      }
    };
    draw(p.part, p.lines);
    for (const physics::PlatformCopyView& c : p.copies) draw(c.part, c.lines);
  }
  for (const physics::EntityId id : world.entities()) {
    const physics::EntityView e = world.entity(id);
    if (e.inserted()) drawEntity(e, looks.of(id), out, scratch);
  }
}

}  // namespace platon::core
