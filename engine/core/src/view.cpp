#include "platon/core/display.h"
#include "platon/core/scene.h"

namespace platon::core {

View faceView(const Scene& scene, physics::MapPartId face) {
  View view;
  view.title = scene.manifest().name;
  view.face = face;
  const stage::Stage* net = scene.stage();
  for (size_t i = 0; net && i < net->faceCount(); ++i) {
    if (net->part(i) != face) continue;
    for (const physics::Vec2& c : net->faces[i].corners) view.border.push_back({static_cast<float>(c.x), static_cast<float>(c.y)});
  }
  const physics::MapPart& part = scene.world().mapPart(face);
  const auto segments = part.segments();
  const auto lines = part.lines();
  view.lines.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    const physics::Segment& s = segments[i];
    view.lines.push_back({{static_cast<float>(s.a.x), static_cast<float>(s.a.y)},
                          {static_cast<float>(s.b.x), static_cast<float>(s.b.y)},
                          lines[i].tag,
                          static_cast<uint8_t>(lines[i].kind)});
  }
  return view;
}

}  // namespace platon::core
