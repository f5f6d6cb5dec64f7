// Scenes described in SI units (metres, seconds) turned into Platon's integers at a chosen scale:
// `upm` whole units per metre and `hz` frames per second. Shared by tests, benchmarks and fuzzers
// so that every comparison converts the same way.
#pragma once
#include <cmath>
#include <cstdint>

#include "platon/physics/vec2.h"

namespace platon::testing {

// Metres to whole units, to the nearest unit.
inline int32_t unitsFromMetres(double metres, double upm) { return static_cast<int32_t>(std::llround(metres * upm)); }
// A point in metres to whole units; long double so that points turned by an exact angle keep
// their last bits before rounding.
inline physics::Vec2 pointFromMetres(long double x, long double y, long double upm) {
  return {static_cast<int32_t>(std::llround(x * upm)), static_cast<int32_t>(std::llround(y * upm))};
}
// m/s to 1/65536 units per frame.
inline int64_t q16FromSpeed(double metresPerSecond, double upm, double hz) {
  return std::llround(metresPerSecond * upm / hz * 65536);
}
// m/s^2 to 1/65536 units per frame per frame.
inline int64_t q16FromAcceleration(double metresPerSecond2, double upm, double hz) {
  return std::llround(metresPerSecond2 * upm * 65536 / (hz * hz));
}

}  // namespace platon::testing
