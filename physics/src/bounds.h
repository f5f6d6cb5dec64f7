// Boxes around moving shapes, and the coordinate range's edge as four sweep constraints.
#pragma once
#include <algorithm>
#include <span>

#include "grid.h"
#include "platon/physics/sweep.h"

namespace platon::physics {

// The box swept by a polygon moving by m; lines wholly outside it cannot be met.
inline Box sweptBox(std::span<const Vec2> verts, Vec2w m) {
  Box b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  for (const Vec2 v : verts) {
    b.x0 = std::min<int64_t>(b.x0, v.x), b.x1 = std::max<int64_t>(b.x1, v.x);
    b.y0 = std::min<int64_t>(b.y0, v.y), b.y1 = std::max<int64_t>(b.y1, v.y);
  }
  if (m.x < 0)
    b.x0 += m.x;
  else
    b.x1 += m.x;
  if (m.y < 0)
    b.y0 += m.y;
  else
    b.y1 += m.y;
  return b;
}

inline bool outside(const Segment& s, const Box& b) {
  return std::max(s.a.x, s.b.x) < b.x0 || std::min(s.a.x, s.b.x) > b.x1 || std::max(s.a.y, s.b.y) < b.y0 ||
         std::min(s.a.y, s.b.y) > b.y1;
}

// Constraints that keep every vertex inside the coordinate range, in the sweep's form: moving by D
// stays inside while slack - dot(c, D) >= 0. Only those a move within `swept` (the box it sweeps)
// can meet: none while that box stays inside the range (a constraint stops a move only past it).
inline std::span<const Constraint> boundConstraints(std::span<const Vec2> verts, const Box& swept,
                                                    Constraint (&out)[4]) {
  if (swept.x0 >= -kCoordLimit && swept.y0 >= -kCoordLimit && swept.x1 <= kCoordLimit && swept.y1 <= kCoordLimit)
    return {};
  int64_t x0 = INT64_MAX, x1 = INT64_MIN, y0 = INT64_MAX, y1 = INT64_MIN;
  for (const Vec2 v : verts) {
    x0 = std::min<int64_t>(x0, v.x), x1 = std::max<int64_t>(x1, v.x);
    y0 = std::min<int64_t>(y0, v.y), y1 = std::max<int64_t>(y1, v.y);
  }
  out[0] = {kCoordLimit - x1, {1, 0}};
  out[1] = {x0 + kCoordLimit, {-1, 0}};
  out[2] = {kCoordLimit - y1, {0, 1}};
  out[3] = {y0 + kCoordLimit, {0, -1}};
  return out;
}

// Every vertex on or left of the directed segment's line: wholly on a one-way line's front.
inline bool wholyInFront(std::span<const Vec2> verts, Segment seg) {
  const Vec2w d = seg.b - seg.a;
  for (const Vec2 v : verts)
    if (cross(d, v - seg.a) < 0) return false;
  return true;
}

}  // namespace platon::physics
