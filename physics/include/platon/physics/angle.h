// Angles as exact binary fractions of a turn, and deterministic integer trigonometry.
#pragma once
#include <cstdint>

#include "platon/physics/vec2.h"

namespace platon::physics {

// 2^32 units make a full turn; sums wrap exactly, so composed rotations never drift.
using Angle = uint32_t;
inline constexpr Angle kQuarterTurn = Angle{1} << 30;
inline constexpr Angle kHalfTurn = Angle{1} << 31;

// Nearest binary angle to a whole number of degrees divided by `divisor` (exact for 90, 180, ...).
constexpr Angle angleFromDegrees(int64_t degrees, int64_t divisor = 1) {
  const i128 turn = i128{1} << 32;
  i128 d = degrees % (360 * divisor);
  if (d < 0) d += i128{360} * divisor;
  return static_cast<Angle>(roundDiv(d * turn, i128{360} * divisor) & 0xffffffff);
}

// cos and sin in Q30 fixed point (2^30 == 1.0), computed by integer CORDIC: bit-identical everywhere.
struct Rotation {
  int64_t c = int64_t{1} << 30;
  int64_t s = 0;
};
Rotation rotationOf(Angle angle);

// Direction of (x, y) as a binary angle, by integer CORDIC. (0, 0) gives 0.
Angle angleOf(Vec2w v);

// v rotated, in Q30 (the result is 2^30 times the real rotated vector).
constexpr Vec2w rotateQ30(Rotation r, Vec2w v) { return {r.c * v.x - r.s * v.y, r.s * v.x + r.c * v.y}; }
// v rotated, wide input (up to 2^62 per component); result in the same scale as v, rounded to nearest.
Vec2w rotateWide(Rotation r, Vec2w v);
// Inverse rotation of v, same scale, rounded to nearest.
Vec2w rotateWideInverse(Rotation r, Vec2w v);

}  // namespace platon::physics
