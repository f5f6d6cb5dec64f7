// Projections of motions and velocities onto lines, with the slide's rounding rules: what is left
// after a contact never points into the line, and what rounding leaves out can be carried on.
#pragma once
#include "fixed_point.h"

namespace platon::physics {

// Removes the part of v that points into the surface with normal n, rounding so that what is left
// never points into it (dot(result, n) >= 0).
inline Vec2w removeInto(Vec2w v, Vec2w n) {
  const i128 vn = dot128(v, n);
  if (vn >= 0) return v;
  const i128 nn = dot128(n, n);
  auto one = [&](int64_t vk, int64_t nk) -> int64_t {
    if (nk == 0) return vk;
    const i128 q = vn * nk;
    return static_cast<int64_t>(vk - (nk > 0 ? floorDiv(q, nn) : ceilDiv(q, nn)));
  };
  return {one(v.x, n.x), one(v.y, n.y)};
}

// Like removeInto for a whole-unit motion, and also returns, in Q17, what the rounding left out:
// carried into the next frame, it keeps a slide along a sloped line from drifting by a unit a frame.
inline Vec2w removeIntoCarrying(Vec2w v, Vec2w n, Vec2w& carryQ17) {
  const Vec2w kept = removeInto(v, n);
  const i128 vn = dot128(v, n);
  if (vn >= 0) return kept;
  const i128 nn = dot128(n, n);
  auto left = [&](int64_t vk, int64_t nk, int64_t keptk) {
    const i128 exactQ17 = i128{vk} * kQ17 - roundDiv(vn * nk * kQ17, nn);
    return static_cast<int64_t>(exactQ17 - i128{keptk} * kQ17);
  };
  carryQ17 = {left(v.x, n.x, kept.x), left(v.y, n.y, kept.y)};
  return kept;
}

// v minus its component along n, to the nearest unit of v's scale.
inline Vec2w withoutComponent(Vec2w v, Vec2w n) {
  const i128 vn = dot128(v, n), nn = dot128(n, n);
  return {v.x - static_cast<int64_t>(roundDiv(vn * n.x, nn)), v.y - static_cast<int64_t>(roundDiv(vn * n.y, nn))};
}

// Scales a direction down (keeping its sign pattern) so its components fit in 31 bits.
inline Vec2w shortDirection(Vec2w n) {
  while (n.x > (int64_t{1} << 30) || n.x < -(int64_t{1} << 30) || n.y > (int64_t{1} << 30) ||
         n.y < -(int64_t{1} << 30)) {
    n.x /= 2;
    n.y /= 2;
  }
  return n;
}

}  // namespace platon::physics
