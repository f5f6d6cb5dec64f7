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

}  // namespace platon::stage
