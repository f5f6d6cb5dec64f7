// An exact fraction num/den (den > 0) of two int64 values, compared through 128-bit products.
#pragma once
#include <compare>
#include <cstdint>

#include "platon/physics/vec2.h"

namespace platon::physics {

struct Fraction {
  int64_t num = 0;
  int64_t den = 1;  // always > 0

  static constexpr Fraction zero() { return {0, 1}; }
  static constexpr Fraction one() { return {1, 1}; }

  friend constexpr std::strong_ordering operator<=>(Fraction a, Fraction b) {
    return i128{a.num} * b.den <=> i128{b.num} * a.den;
  }
  friend constexpr bool operator==(Fraction a, Fraction b) { return (a <=> b) == 0; }

  // The value scaled by 2^bits and rounded down; for reports and hashing, never for geometry.
  constexpr int64_t scaledFloor(int bits) const { return static_cast<int64_t>(floorDiv(i128{num} << bits, den)); }
};

}  // namespace platon::physics
