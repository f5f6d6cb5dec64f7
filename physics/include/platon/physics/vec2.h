// Integer points and vectors: the only coordinates physics knows.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace platon::physics {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

// Every world point (line endpoints, entity vertices) satisfies |x|,|y| <= kCoordLimit.
// Differences of two such points then have |component| <= 2^31 - 2, so a cross or dot product of
// two differences is below 2 * (2^31 - 2)^2 < 2^63 and never overflows int64.
inline constexpr int32_t kCoordLimit = (1 << 30) - 1;
// Shape vertices relative to the entity origin: small enough that any rotation stays below 2^30.
inline constexpr int32_t kShapeLimit = 1 << 29;
// Largest motion per frame and component, in whole units.
inline constexpr int32_t kMaxMove = 1 << 30;

// Every misuse of the physics API throws this, with a message that names the bad value.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Vec2 {
  int32_t x = 0;
  int32_t y = 0;
  friend constexpr bool operator==(Vec2, Vec2) = default;
};

// A wide vector: differences of points, normals, fixed-point velocities.
struct Vec2w {
  int64_t x = 0;
  int64_t y = 0;
  friend constexpr bool operator==(Vec2w, Vec2w) = default;
};

constexpr Vec2w wide(Vec2 v) { return {v.x, v.y}; }
constexpr Vec2w operator-(Vec2 a, Vec2 b) { return {int64_t{a.x} - b.x, int64_t{a.y} - b.y}; }
constexpr Vec2w operator+(Vec2w a, Vec2w b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2w operator-(Vec2w a, Vec2w b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2w operator-(Vec2w a) { return {-a.x, -a.y}; }

// Callers guarantee the range documented above; these never widen further.
constexpr int64_t cross(Vec2w a, Vec2w b) { return a.x * b.y - a.y * b.x; }
constexpr int64_t dot(Vec2w a, Vec2w b) { return a.x * b.x + a.y * b.y; }
constexpr i128 cross128(Vec2w a, Vec2w b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
constexpr i128 dot128(Vec2w a, Vec2w b) { return i128{a.x} * b.x + i128{a.y} * b.y; }

constexpr bool inRange(Vec2 p) {
  return p.x >= -kCoordLimit && p.x <= kCoordLimit && p.y >= -kCoordLimit && p.y <= kCoordLimit;
}

std::string toString(Vec2 p);

// Floor and ceiling of a / b for b != 0, exact for any signs. 128-bit division is a library call;
// most operands fit in 64 bits, so that case takes the hardware divide.
constexpr i128 floorDiv(i128 a, i128 b) {
  if (a == static_cast<int64_t>(a) && b == static_cast<int64_t>(b) && !(a == INT64_MIN && b == -1)) {
    const int64_t x = static_cast<int64_t>(a), y = static_cast<int64_t>(b);
    int64_t q = x / y;
    if ((x % y != 0) && ((x < 0) != (y < 0))) --q;
    return q;
  }
  i128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}
constexpr i128 ceilDiv(i128 a, i128 b) { return -floorDiv(-a, b); }
// Nearest integer to a / b (b > 0), halves rounded up.
constexpr i128 roundDiv(i128 a, i128 b) { return floorDiv(2 * a + b, 2 * b); }

}  // namespace platon::physics
