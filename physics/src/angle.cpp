#include "platon/physics/angle.h"

#include <array>

namespace platon::physics {
namespace {

// atan(2^-i), i = 0..30, in units of 2^-64 turn: 32 bits finer than an Angle, so the table's own
// rounding never adds up to a visible error.
constexpr std::array<int64_t, 31> kAtan = {
    2305843009213693952, 1361218612134873190, 719230530580881038, 365092647525521947, 183254791493294829,
    91716730292036216,   45869556482713130,   22936177926750895,  11468263948075831,  5734153847876408,
    2867079658191483,    1433540170878135,    716770128161890,    358385069421298,    179192535378193,
    89596267772540,      44798133896700,      22399066949654,     11199533474990,     5599766737515,
    2799883368760,       1399941684380,       699970842190,       349985421095,       174992710548,
    87496355274,         43748177637,         21874088818,        10937044409,        5468522205,
    2734261102};
// Product of the 31 CORDIC gains, in Q60: starting the rotation from it gives unit length. The
// iterations run in Q60 so their truncations stay far below the Q30 result.
constexpr int64_t kGainQ60 = 700114967507363239;
// 2 pi / 2^32 in Q60: one binary-angle unit in radians.
constexpr int64_t kRadiansPerUnitQ60 = 1686629713;

}  // namespace

Rotation rotationOf(Angle angle) {
  // Reduce to [-90, 90] degrees, where CORDIC converges; remember a half-turn flip.
  int64_t a = static_cast<int32_t>(angle);  // signed: (-180, 180]
  bool flip = false;
  if (a > int64_t{kQuarterTurn}) {
    a -= int64_t{kHalfTurn};
    flip = true;
  } else if (a < -int64_t{kQuarterTurn}) {
    a += int64_t{kHalfTurn};
    flip = true;
  }
  a *= int64_t{1} << 32;  // to 2^-64 turn
  int64_t x = kGainQ60;
  int64_t y = 0;
  for (int i = 0; i < 31; ++i) {
    const int64_t dx = y >> i;
    const int64_t dy = x >> i;
    if (a >= 0) {
      x -= dx;
      y += dy;
      a -= kAtan[i];
    } else {
      x += dx;
      y -= dy;
      a += kAtan[i];
    }
  }
  // The few units of angle left over: one small-angle step (sin r ~ r) finishes the turn.
  const i128 r = (i128{a} * kRadiansPerUnitQ60) >> 32;
  const int64_t xr = x - static_cast<int64_t>((r * y) >> 60);
  const int64_t yr = y + static_cast<int64_t>((r * x) >> 60);
  x = static_cast<int64_t>(roundDiv(xr, i128{1} << 30));
  y = static_cast<int64_t>(roundDiv(yr, i128{1} << 30));
  // Exact values at quarter turns keep cube faces exact.
  if (angle % kQuarterTurn == 0) {
    const int64_t one = int64_t{1} << 30;
    switch (angle / kQuarterTurn) {
      case 0:
        return {one, 0};
      case 1:
        return {0, one};
      case 2:
        return {-one, 0};
      default:
        return {0, -one};
    }
  }
  return flip ? Rotation{-x, -y} : Rotation{x, y};
}

Angle angleOf(Vec2w v) {
  if (v.y == 0) return v.x >= 0 ? 0 : kHalfTurn;  // axis directions are exact
  if (v.x == 0) return v.y > 0 ? kQuarterTurn : 3 * kQuarterTurn;
  // Scale to about 2^58 so the iterations' truncations are negligible and the growth (< 1.65)
  // stays inside int64.
  int64_t x = v.x;
  int64_t y = v.y;
  while (x > (int64_t{1} << 58) || x < -(int64_t{1} << 58) || y > (int64_t{1} << 58) || y < -(int64_t{1} << 58)) {
    x /= 2;
    y /= 2;
  }
  while (x < (int64_t{1} << 57) && x > -(int64_t{1} << 57) && y < (int64_t{1} << 57) && y > -(int64_t{1} << 57)) {
    x *= 2;
    y *= 2;
  }
  uint64_t angle = 0;  // in 2^-64 turn, wrapping
  if (x < 0) {         // rotate by a half turn into the right half-plane
    x = -x;
    y = -y;
    angle = uint64_t{1} << 63;
  }
  for (int i = 0; i < 31; ++i) {
    const int64_t dx = y >> i;
    const int64_t dy = x >> i;
    if (y > 0) {
      x += dx;
      y -= dy;
      angle += static_cast<uint64_t>(kAtan[i]);
    } else {
      x -= dx;
      y += dy;
      angle -= static_cast<uint64_t>(kAtan[i]);
    }
  }
  // What is left is a tiny angle, y / x radians: add it, then round to a whole Angle.
  angle += static_cast<uint64_t>(static_cast<int64_t>(roundDiv(i128{y} << 92, i128{x} * kRadiansPerUnitQ60)));
  return static_cast<Angle>((angle + (uint64_t{1} << 31)) >> 32);
}

Vec2w rotateWide(Rotation r, Vec2w v) {
  if (r.s == 0 && r.c == int64_t{1} << 30) return v;  // the anchor's frame: nothing to turn
  const i128 x = i128{r.c} * v.x - i128{r.s} * v.y;
  const i128 y = i128{r.s} * v.x + i128{r.c} * v.y;
  return {static_cast<int64_t>(roundDiv(x, i128{1} << 30)), static_cast<int64_t>(roundDiv(y, i128{1} << 30))};
}

Vec2w rotateWideInverse(Rotation r, Vec2w v) { return rotateWide({r.c, -r.s}, v); }

}  // namespace platon::physics
