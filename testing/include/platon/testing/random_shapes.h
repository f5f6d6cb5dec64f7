// Random material for the physics tests: integers in a range and convex shapes centred on their
// bounding box (so they go where they are inserted), upright or at a random angle.
#pragma once
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "platon/physics/convex.h"

namespace platon::testing {

// Uniform in [lo, hi].
inline int32_t between(std::mt19937_64& rng, int32_t lo, int32_t hi) {
  return lo + static_cast<int32_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

enum class Turn { Upright, MaybeTurned };

// 3 to 8 random points within `size` of the origin, their hull centred on its box; with
// MaybeTurned, half of them turned by a random angle (so a vertex often points down). Shapes too
// small to turn are drawn again.
inline physics::Convex randomConvex(std::mt19937_64& rng, int32_t size, Turn turn) {
  using physics::Vec2;
  for (;;) {
    std::vector<Vec2> points;
    const int n = 3 + static_cast<int>(rng() % 6);
    for (int i = 0; i < n; ++i) points.push_back({between(rng, -size, size), between(rng, -size, size)});
    std::vector<Vec2> hull = physics::convexHull(points);
    if (hull.size() < 3) continue;
    Vec2 lo = hull[0], hi = hull[0];
    for (const Vec2 v : hull)
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    for (Vec2& v : hull) v = {v.x - (lo.x + hi.x) / 2, v.y - (lo.y + hi.y) / 2};
    physics::Convex c(hull);
    if (turn == Turn::Upright || rng() % 2) return c;
    try {
      return c.rotated(static_cast<physics::Angle>(rng()));
    } catch (const physics::Error&) {  // too small to turn: draw again
    }
  }
}

}  // namespace platon::testing
