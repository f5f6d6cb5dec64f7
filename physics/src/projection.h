// Projections of motions and velocities onto lines, with the slide's rounding rules: what is left
// after a contact never points into the line, and what rounding leaves out can be carried on.
#pragma once
#include <span>

#include "fixed_point.h"
#include "platon/physics/sweep.h"

namespace platon::physics {

// Removes the part of v that points into the surface with normal n: the whole vector nearest to the
// exact v - (v.n / n.n) n that does not point into it (dot(result, n) >= 0). Rounding each
// component away from the surface would also keep it out, but up to a unit further off than the
// nearest such vector: a body sliding in a corner would be lifted by it on every contact.
inline Vec2w removeInto(Vec2w v, Vec2w n) {
  const i128 vn = dot128(v, n);
  if (vn >= 0) return v;
  // A floor, ceiling or wall: the exact result is whole (what the search below finds, cheaply).
  if (n.x == 0) return {v.x, 0};
  if (n.y == 0) return {0, v.y};
  const i128 nn = dot128(n, n);  // the exact result is (v nn - vn n) / nn, component by component
  const i128 ex = i128{v.x} * nn - vn * n.x, ey = i128{v.y} * nn - vn * n.y;
  const i128 fx = floorDiv(ex, nn), fy = floorDiv(ey, nn);
  // Fractional parts in Q32: enough to rank the four corners of the unit square around it.
  const i128 px = floorDiv((ex - fx * nn) << 32, nn), py = floorDiv((ey - fy * nn) << 32, nn);
  const i128 one = i128{1} << 32;
  Vec2w best = {static_cast<int64_t>(fx + (n.x > 0)), static_cast<int64_t>(fy + (n.y > 0))};  // away: always out
  i128 bestDistance = -1;
  for (int k = 0; k < 4; ++k) {
    const int ax = k & 1, ay = k >> 1;
    const Vec2w d{static_cast<int64_t>(fx + ax), static_cast<int64_t>(fy + ay)};
    if (dot128(d, n) < 0) continue;
    const i128 dx = ax * one - px, dy = ay * one - py;
    const i128 distance = dx * dx + dy * dy;
    if (bestDistance < 0 || distance < bestDistance) best = d, bestDistance = distance;
  }
  return best;
}

// Like removeInto for a whole-unit motion, and also returns, in Q17, what the rounding left out:
// carried into the next frame, it keeps a slide along a sloped line from drifting by a unit a frame.
inline Vec2w removeIntoCarrying(Vec2w v, Vec2w n, Vec2w& carryQ17) {
  const Vec2w kept = removeInto(v, n);
  const i128 vn = dot128(v, n);
  if (vn >= 0) return kept;
  if (n.x == 0 || n.y == 0) {  // exact: nothing left out
    carryQ17 = {};
    return kept;
  }
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
  if (n.x == 0 && n.y != 0) return {v.x, 0};  // exact, as below
  if (n.y == 0 && n.x != 0) return {0, v.y};
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

// A step of about `units` whole units along `direction` (none for none): each component of the
// direction scaled to that length, rounded to the nearest unit.
inline Vec2w stepAlong(Vec2w direction, int64_t units) {
  const Vec2w n = shortDirection(direction);
  const int64_t length = static_cast<int64_t>(isqrt(static_cast<u128>(i128{n.x} * n.x + i128{n.y} * n.y)));
  if (length == 0) return {};
  return {static_cast<int64_t>(roundDiv(i128{n.x} * units, length)),
          static_cast<int64_t>(roundDiv(i128{n.y} * units, length))};
}

// The normal of the directed segment on the side the polygon lies (by the sum of its vertices'
// sides; the left one when they balance), not normalized.
inline Vec2w normalTowards(std::span<const Vec2> verts, Segment s) {
  const Vec2w d = s.b - s.a;
  i128 side = 0;
  for (const Vec2 v : verts) side += cross(d, v - s.a);
  return side >= 0 ? Vec2w{-d.y, d.x} : Vec2w{d.y, -d.x};
}

// How far (whole units, rounded up) the vertices reach behind the line through `s`, seen from its
// side `normal` points to (none when all are on that side).
inline int64_t depthBehind(std::span<const Vec2> verts, Segment s, Vec2w normal) {
  const Vec2w n = shortDirection(normal);
  const int64_t length = static_cast<int64_t>(isqrt(static_cast<u128>(i128{n.x} * n.x + i128{n.y} * n.y)));
  i128 deepest = 0;
  for (const Vec2 v : verts) deepest = std::max(deepest, -dot128(v - s.a, n));
  return length == 0 ? 0 : static_cast<int64_t>((deepest + length - 1) / length);
}

}  // namespace platon::physics
