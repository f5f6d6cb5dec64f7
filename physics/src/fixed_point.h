// Fixed-point conversions the solver uses everywhere: whole units, Q16 velocities, Q17 remainders,
// Q30 positions and rotations. One place, so each rounding rule is written once.
#pragma once
#include <algorithm>

#include "platon/physics/vec2.h"

namespace platon::physics {

inline constexpr int64_t kQ16 = int64_t{1} << 16;  // velocities: 1/65536 unit per frame
inline constexpr int64_t kQ17 = int64_t{1} << 17;  // carried remainders: 1/131072 unit
inline constexpr int kQ30Bits = 30;                // ideal positions and rotations

// A Q30 value rounded to the nearest whole unit (halves up).
inline int64_t unitsFromQ30(int64_t q30) { return static_cast<int64_t>(roundDiv(q30, i128{1} << kQ30Bits)); }
inline Vec2 pointFromQ30(Vec2w q30) {
  return {static_cast<int32_t>(unitsFromQ30(q30.x)), static_cast<int32_t>(unitsFromQ30(q30.y))};
}
inline Vec2w q30FromPoint(Vec2 p) { return {int64_t{p.x} << kQ30Bits, int64_t{p.y} << kQ30Bits}; }

// A velocity held within the largest move per frame (2^30 units, in Q16), component by component.
// Projections along sloped lines and turns into another frame can push one component up to sqrt(2)
// times past it; the world clamps there so every velocity it holds is one setVelocity accepts.
inline Vec2w clampVelocityQ16(Vec2w v) {
  const int64_t limit = int64_t{kMaxMove} << 16;
  return {std::clamp(v.x, -limit, limit), std::clamp(v.y, -limit, limit)};
}

// A frame's remaining motion in Q17 held within the largest move per frame the same way: a bounce
// with a restitution above one can otherwise send the rest of the frame further than any sweep
// accepts.
inline Vec2w clampMotionQ17(Vec2w m) {
  const int64_t limit = int64_t{kMaxMove} << 17;
  return {std::clamp(m.x, -limit, limit), std::clamp(m.y, -limit, limit)};
}

// Largest r with r * r <= v: exact integer square root (Newton's method from above).
inline uint64_t isqrt(u128 v) {
  if (v < 2) return static_cast<uint64_t>(v);
  int bits = 0;
  for (u128 t = v; t; t >>= 1) ++bits;
  u128 x = static_cast<u128>(1) << ((bits + 1) / 2);  // >= sqrt(v)
  for (;;) {
    const u128 y = (x + v / x) / 2;
    if (y >= x) return static_cast<uint64_t>(x);
    x = y;
  }
}

}  // namespace platon::physics
