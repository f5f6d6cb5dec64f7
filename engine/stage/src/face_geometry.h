// Plane geometry on a face's whole-unit frame, shared by the level checks and the reachability
// search (doubles: these are the level designer's checks, not the physics).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "platon/physics/vec2.h"

namespace platon::stage {

// Twice the signed area of (a, b, p): > 0 when p is left of a -> b.
inline double side(physics::Vec2 a, physics::Vec2 b, double x, double y) {
  return (double(b.x) - a.x) * (y - a.y) - (double(b.y) - a.y) * (x - a.x);
}

// Inside or on the border of a convex counter-clockwise polygon.
inline bool insidePolygon(const std::vector<physics::Vec2>& corners, double x, double y) {
  for (size_t i = 0; i < corners.size(); ++i)
    if (side(corners[i], corners[(i + 1) % corners.size()], x, y) < 0) return false;
  return true;
}

inline double distanceToSegment(double x, double y, physics::Vec2 a, physics::Vec2 b) {
  const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
  const double t = std::clamp(((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

// Squared distances (no square root) for the search's inner loops, and plain ones.
inline double pointSegmentDistance2(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / length2, 0.0, 1.0) : 0.0;
  const double ex = ax + t * dx - px, ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}
inline double pointSegmentDistance(double px, double py, double ax, double ay, double bx, double by) {
  return std::sqrt(pointSegmentDistance2(px, py, ax, ay, bx, by));
}

// An axis-aligned box [x0, x1] x [y0, y1].
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  double distance2To(double x, double y) const {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return dx * dx + dy * dy;
  }
  double distanceTo(double x, double y) const { return std::sqrt(distance2To(x, y)); }
  double distanceTo(const Box& o) const {
    return std::hypot(std::max({o.x0 - x1, 0.0, x0 - o.x1}), std::max({o.y0 - y1, 0.0, y0 - o.y1}));
  }
};

// Whether segments a-b and c-d meet (touching counts).
inline bool segmentsMeet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
  auto cross = [](double ox, double oy, double px, double py, double qx, double qy) {
    return (px - ox) * (qy - oy) - (py - oy) * (qx - ox);
  };
  const double d1 = cross(cx, cy, dx, dy, ax, ay), d2 = cross(cx, cy, dx, dy, bx, by);
  const double d3 = cross(ax, ay, bx, by, cx, cy), d4 = cross(ax, ay, bx, by, dx, dy);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto onSegment = [](double ox, double oy, double px, double py, double qx, double qy) {  // q on o-p, collinear
    return std::min(ox, px) <= qx && qx <= std::max(ox, px) && std::min(oy, py) <= qy && qy <= std::max(oy, py);
  };
  return (d1 == 0 && onSegment(cx, cy, dx, dy, ax, ay)) || (d2 == 0 && onSegment(cx, cy, dx, dy, bx, by)) ||
         (d3 == 0 && onSegment(ax, ay, bx, by, cx, cy)) || (d4 == 0 && onSegment(ax, ay, bx, by, dx, dy));
}

// The squared distance from segment a-b to a box (0 when they meet): when apart, the nearest
// points are an end of the segment and the box, or a corner of the box and the segment.
inline double segmentBoxDistance2(double ax, double ay, double bx, double by, const Box& box) {
  if (box.contains(ax, ay) || box.contains(bx, by)) return 0;
  const double xs[4] = {box.x0, box.x1, box.x1, box.x0}, ys[4] = {box.y0, box.y0, box.y1, box.y1};
  double nearest = std::min(box.distance2To(ax, ay), box.distance2To(bx, by));
  for (int i = 0; i < 4; ++i) {
    if (segmentsMeet(ax, ay, bx, by, xs[i], ys[i], xs[(i + 1) % 4], ys[(i + 1) % 4])) return 0;
    nearest = std::min(nearest, pointSegmentDistance2(xs[i], ys[i], ax, ay, bx, by));
  }
  return nearest;
}
inline double segmentBoxDistance(double ax, double ay, double bx, double by, const Box& box) {
  return std::sqrt(segmentBoxDistance2(ax, ay, bx, by, box));
}

}  // namespace platon::stage
