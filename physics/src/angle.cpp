#include "platon/physics/angle.h"

#include <array>

namespace platon::physics {
namespace {

// atan(2^-i) in binary-angle units, i = 0..30.
constexpr std::array<int64_t, 31> kAtan = {
    536870912, 316933406, 167458907, 85004756, 42667331, 21354465, 10679838, 5340245,
    2670163,   1335087,   667544,    333772,   166886,   83443,    41722,    20861,
    10430,     5215,      2608,      1304,     652,      326,      163,      81,
    41,        20,        10,        5,        3,        1,        1};
// Product of the CORDIC gains, in Q30: starting the rotation from it gives unit length.
constexpr int64_t kGainQ30 = 652032874;

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
  int64_t x = kGainQ30;
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
  // Exact values at quarter turns keep cube faces exact.
  if (angle % kQuarterTurn == 0) {
    const int64_t one = int64_t{1} << 30;
    switch (angle / kQuarterTurn) {
      case 0: return {one, 0};
      case 1: return {0, one};
      case 2: return {-one, 0};
      default: return {0, -one};
    }
  }
  return flip ? Rotation{-x, -y} : Rotation{x, y};
}

Angle angleOf(Vec2w v) {
  if (v.x == 0 && v.y == 0) return 0;
  // Scale down so the CORDIC iterations (growth < 1.65) stay far inside int64.
  int64_t x = v.x;
  int64_t y = v.y;
  while (x > (int64_t{1} << 40) || x < -(int64_t{1} << 40) || y > (int64_t{1} << 40) ||
         y < -(int64_t{1} << 40)) {
    x /= 2;
    y /= 2;
  }
  // Scale up small vectors for precision.
  while (x < (int64_t{1} << 30) && x > -(int64_t{1} << 30) && y < (int64_t{1} << 30) &&
         y > -(int64_t{1} << 30)) {
    x *= 2;
    y *= 2;
  }
  int64_t angle = 0;
  if (x < 0) {  // rotate by a half turn into the right half-plane
    x = -x;
    y = -y;
    angle = int64_t{kHalfTurn};
  }
  for (int i = 0; i < 31; ++i) {
    const int64_t dx = y >> i;
    const int64_t dy = x >> i;
    if (y > 0) {
      x += dx;
      y -= dy;
      angle += kAtan[i];
    } else {
      x -= dx;
      y += dy;
      angle -= kAtan[i];
    }
  }
  return static_cast<Angle>(angle & 0xffffffff);
}

Vec2w rotateWide(Rotation r, Vec2w v) {
  if (r.s == 0 && r.c == int64_t{1} << 30) return v;  // the anchor's frame: nothing to turn
  const i128 x = i128{r.c} * v.x - i128{r.s} * v.y;
  const i128 y = i128{r.s} * v.x + i128{r.c} * v.y;
  return {static_cast<int64_t>(roundDiv(x, i128{1} << 30)),
          static_cast<int64_t>(roundDiv(y, i128{1} << 30))};
}

Vec2w rotateWideInverse(Rotation r, Vec2w v) { return rotateWide({r.c, -r.s}, v); }

}  // namespace platon::physics
