#include "walls_near.h"

#include <algorithm>
#include <cmath>

#include "face_geometry.h"

namespace platon::stage {

FlatMap FlatMap::inverse() const {
  // p = R q + t  =>  q = R^T (p - t)
  FlatMap back{cos, -sin, 0, 0};
  back.x = -(cos * x + sin * y);
  back.y = -(-sin * x + cos * y);
  return back;
}

FlatMap unfoldAcross(const Stage& stage, size_t face, size_t edge) {
  const StageFace& here = stage.faces[face];
  const physics::Vec2 a = here.corners[edge], b = here.corners[(edge + 1) % here.corners.size()];
  const auto [g, j] = here.neighbours[edge];
  const StageFace& there = stage.faces[static_cast<size_t>(g)];
  // The neighbour's edge j runs p -> q, the same edge as our a -> b the other way: q lands on a.
  const physics::Vec2 p = there.corners[static_cast<size_t>(j)],
                      q = there.corners[(static_cast<size_t>(j) + 1) % there.corners.size()];
  const double turn =
      std::atan2(double(b.y) - a.y, double(b.x) - a.x) - std::atan2(double(p.y) - q.y, double(p.x) - q.x);
  FlatMap map{std::cos(turn), std::sin(turn), 0, 0};
  double qx = q.x, qy = q.y;
  map.apply(qx, qy);
  map.x = a.x - qx, map.y = a.y - qy;
  return map;
}

bool counts(const LevelLine& line, const TagTable& tags, Counting counting) {
  const Passage passage = tags.passage(line.tag);
  if (passage == Passage::Through) return false;
  return counting == Counting::Clearance || (!line.oneWay && passage != Passage::Door);
}

std::vector<FlatWall> wallsNear(const Level& level, const Stage& stage, size_t face, double margin, Counting counting) {
  std::vector<FlatWall> out;
  for (const LevelLine& l : level.faces[face].lines)
    if (counts(l, *level.tags, counting))
      out.push_back({double(l.a.x), double(l.a.y), double(l.b.x), double(l.b.y), int(face), &l});
  const StageFace& here = stage.faces[face];
  for (size_t k = 0; k < here.corners.size(); ++k) {
    const auto [g, j] = here.neighbours[k];
    const StageFace& there = stage.faces[static_cast<size_t>(g)];
    const physics::Vec2 p = there.corners[static_cast<size_t>(j)],
                        q = there.corners[(static_cast<size_t>(j) + 1) % there.corners.size()];
    const FlatMap map = unfoldAcross(stage, face, k);
    // The edge's bounding box grown by the margin: a line whose own box misses it is not near.
    const double x0 = std::min(p.x, q.x) - margin, x1 = std::max(p.x, q.x) + margin;
    const double y0 = std::min(p.y, q.y) - margin, y1 = std::max(p.y, q.y) + margin;
    for (const LevelLine& l : level.faces[static_cast<size_t>(g)].lines) {
      if (std::max(l.a.x, l.b.x) < x0 || std::min(l.a.x, l.b.x) > x1 || std::max(l.a.y, l.b.y) < y0 ||
          std::min(l.a.y, l.b.y) > y1)
        continue;
      if (!counts(l, *level.tags, counting)) continue;
      // Near the edge: either end within the margin of it, or the line crossing its strip.
      const double ea = distanceToSegment(l.a.x, l.a.y, p, q), eb = distanceToSegment(l.b.x, l.b.y, p, q);
      const double mid = distanceToSegment((double(l.a.x) + l.b.x) / 2, (double(l.a.y) + l.b.y) / 2, p, q);
      const double half = std::hypot(double(l.b.x) - l.a.x, double(l.b.y) - l.a.y) / 2;
      if (std::min({ea, eb, mid - half}) >= margin) continue;
      FlatWall w{double(l.a.x), double(l.a.y), double(l.b.x), double(l.b.y), g, &l};
      map.apply(w.ax, w.ay);
      map.apply(w.bx, w.by);
      out.push_back(w);
    }
  }
  return out;
}

}  // namespace platon::stage
