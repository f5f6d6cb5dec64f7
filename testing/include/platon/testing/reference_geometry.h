// Brute-force exact reference for platon/physics/sweep.h, built independently of sweep.cpp.
//
// sweep.cpp intersects per-axis intervals (separating axes). Here we instead build the
// configuration-space obstacle explicitly: the interior of P + t*m meets the closed segment S
// exactly when t*m lies in the interior of O = S (-) P = hull{A - w_j, B - w_j}. We take that
// hull with our own exact monotone chain and clip the ray t*m against its edges (Cyrus-Beck).
// Contacts are found a third way: clip the segment A + s(B - A) against the closed half-planes
// of the moved polygon at an exact rational time.
//
// Overflow: every product goes through a checked multiply that throws, so a wrong bound below
// shows up as a test error, never as a silently wrong answer.
// Bounds, for any input sweep() accepts (points within kCoordLimit = 2^30 - 1, so differences
// below 2^31; motion components below 2^31):
//  - O's vertices are differences of points: |component| < 2^31. Its edge normals are reduced to
//    primitive vectors, which divide a polygon edge or B - A, so |component| < 2^31 as well.
//    Then |h| = |n.p| < 2^63 and |rate| = |n.m| < 2^63, and comparing two such fractions costs
//    < 2^126: the ray clipping fits in __int128 at every coordinate the physics allows.
//  - Segment clipping at time p/q (|p|, q < 2^63): ca = q * cross(e, d) < 2^126 and
//    cb = p * cross(e, m) - q * cross(e, A - w) < 2^127, compared in products < 2^253: Int256.
#pragma once
#include <algorithm>
#include <array>
#include <compare>
#include <cstdint>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "platon/physics/vec2.h"

namespace platon::testing::reference {

using physics::i128;
using physics::Vec2;
using physics::Vec2w;
using physics::wide;
__extension__ typedef unsigned __int128 u128;

inline std::string toString(i128 v) {
  if (v == 0) return "0";
  const bool neg = v < 0;
  u128 u = neg ? u128(0) - u128(v) : u128(v);
  std::string s;
  for (; u != 0; u /= 10) s.insert(s.begin(), char('0' + int(u % 10)));
  return neg ? "-" + s : s;
}

// Signed 256-bit two's-complement integer: just enough (+, -, *, compare) for exact clipping.
class Int256 {
 public:
  Int256() = default;
  Int256(i128 v) {  // implicit on purpose: mixes freely with int64 and i128 values
    const u128 u = static_cast<u128>(v);
    w_ = {static_cast<uint64_t>(u), static_cast<uint64_t>(u >> 64), v < 0 ? ~uint64_t{0} : 0, v < 0 ? ~uint64_t{0} : 0};
  }

  bool negative() const { return static_cast<int64_t>(w_[3]) < 0; }
  int sign() const { return negative() ? -1 : (*this == Int256{} ? 0 : 1); }

  friend Int256 operator+(const Int256& a, const Int256& b) {
    Int256 r;
    u128 carry = 0;
    for (int i = 0; i < 4; ++i) {
      const u128 s = u128(a.w_[i]) + b.w_[i] + carry;
      r.w_[i] = static_cast<uint64_t>(s);
      carry = s >> 64;
    }
    return r;
  }
  friend Int256 operator-(Int256 a) {
    for (uint64_t& x : a.w_) x = ~x;
    return a + Int256(1);
  }
  friend Int256 operator-(const Int256& a, const Int256& b) { return a + -b; }
  // Schoolbook product modulo 2^256, which is the true signed product whenever it fits; the
  // bit-length test makes "fits" a checked precondition (|result| < 2^254).
  friend Int256 operator*(const Int256& a, const Int256& b) {
    if (a.magnitudeBits() + b.magnitudeBits() > 254) throw std::overflow_error("reference: Int256 overflow");
    Int256 r;
    for (int i = 0; i < 4; ++i) {
      u128 carry = 0;
      for (int j = 0; i + j < 4; ++j) {
        const u128 t = u128(a.w_[i]) * b.w_[j] + r.w_[i + j] + carry;
        r.w_[i + j] = static_cast<uint64_t>(t);
        carry = t >> 64;
      }
    }
    return r;
  }
  friend std::strong_ordering operator<=>(const Int256& a, const Int256& b) {
    if (a.w_[3] != b.w_[3]) return static_cast<int64_t>(a.w_[3]) <=> static_cast<int64_t>(b.w_[3]);
    for (int i = 2; i >= 0; --i)
      if (a.w_[i] != b.w_[i]) return a.w_[i] <=> b.w_[i];
    return std::strong_ordering::equal;
  }
  friend bool operator==(const Int256&, const Int256&) = default;

 private:
  int magnitudeBits() const {
    const Int256 m = negative() ? -*this : *this;
    for (int i = 3; i >= 0; --i)
      if (m.w_[i] != 0) return 64 * i + 64 - __builtin_clzll(m.w_[i]);
    return 0;
  }
  std::array<uint64_t, 4> w_{};
};

// Checked products for Rat<T>.
inline i128 mul(i128 a, i128 b) {
  i128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw std::overflow_error("reference: i128 overflow");
  return r;
}
inline Int256 mul(const Int256& a, const Int256& b) { return a * b; }

// Largest z with z * den <= num (den > 0), for results known to lie in |z| < 2^40: found by
// bisection, so Int256 needs no division.
inline int64_t floorDiv(const Int256& num, const Int256& den) {
  int64_t lo = -(int64_t{1} << 40), hi = int64_t{1} << 40;  // lo * den <= num < hi * den
  if (!(Int256(lo) * den <= num && num < Int256(hi) * den))
    throw std::overflow_error("reference: rounded point out of range");
  while (hi - lo > 1) {
    const int64_t mid = lo + (hi - lo) / 2;
    (Int256(mid) * den <= num ? lo : hi) = mid;
  }
  return lo;
}

// An exact rational num / den with den > 0.
template <class T>
struct Rat {
  T num{0};
  T den{1};
  friend std::strong_ordering operator<=>(const Rat& a, const Rat& b) {
    return mul(a.num, b.den) <=> mul(b.num, a.den);
  }
  friend bool operator==(const Rat& a, const Rat& b) { return (a <=> b) == 0; }
};

// Exact for any int64 components (unlike physics::cross, which relies on the coordinate range).
inline i128 crossExact(Vec2w a, Vec2w b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
inline i128 dotExact(Vec2w a, Vec2w b) { return i128{a.x} * b.x + i128{a.y} * b.y; }

// Counter-clockwise convex hull without collinear points (Andrew's monotone chain).
inline std::vector<Vec2w> hull(std::vector<Vec2w> pts) {
  std::sort(pts.begin(), pts.end(), [](Vec2w a, Vec2w b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Vec2w> h;
  for (int pass = 0; pass < 2; ++pass) {  // lower chain left to right, then upper right to left
    const size_t start = h.size();
    for (const Vec2w p : pts) {
      while (h.size() >= start + 2 && crossExact(h.back() - h[h.size() - 2], p - h[h.size() - 2]) <= 0) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();  // the last point starts the other chain
    std::reverse(pts.begin(), pts.end());
  }
  return h;
}

// The line t * motion against the obstacle O, for all real t.
struct RefSweep {
  std::vector<Vec2w> obstacle;  // O, counter-clockwise
  bool overlapsAtZero = false;  // origin in the open O: interiors meet now
  bool touchesAtZero = false;   // origin in the closed O: closed sets meet now
  bool overlaps = false;        // the open interval of t below is non-empty
  bool bounded = false;         // motion != 0, so enter and exit are finite
  Rat<i128> enter, exit;
  std::vector<Vec2w> enterNormals;  // outward normals of O's edges through the entry point
};

// Against any convex set given by its points (a segment's two ends, a polygon's vertices): the
// obstacle is hull{q - w} over its points q and the polygon's vertices w.
inline RefSweep referenceSweep(std::span<const Vec2> poly, Vec2w motion, std::span<const Vec2> points) {
  RefSweep r;
  std::vector<Vec2w> pts;
  for (const Vec2 w : poly)
    for (const Vec2 q : points) pts.push_back(q - w);
  r.obstacle = hull(std::move(pts));
  if (r.obstacle.size() < 3) throw std::logic_error("reference: obstacle has no interior");
  r.overlapsAtZero = r.touchesAtZero = true;
  bool parallelOutside = false, haveEnter = false, haveExit = false;
  struct Entering {
    Rat<i128> t;
    Vec2w n;
  };
  std::vector<Entering> entering;
  const size_t k = r.obstacle.size();
  for (size_t i = 0; i < k; ++i) {
    const Vec2w p = r.obstacle[i];
    const Vec2w e = r.obstacle[(i + 1) % k] - p;
    const int64_t g = std::gcd(e.x, e.y);
    const Vec2w n{e.y / g, -e.x / g};  // outward for a counter-clockwise polygon
    // Interior of O: n.(x - p) < 0. On the ray x = t * motion: t * rate < h.
    const i128 h = dotExact(n, p), rate = dotExact(n, motion);
    r.overlapsAtZero = r.overlapsAtZero && h > 0;
    r.touchesAtZero = r.touchesAtZero && h >= 0;
    if (rate < 0) {  // moving inwards across this edge: inside once t > h / rate
      const Rat<i128> t{-h, -rate};
      entering.push_back({t, n});
      if (!haveEnter || t > r.enter) r.enter = t;
      haveEnter = true;
    } else if (rate > 0) {  // moving outwards: inside only while t < h / rate
      const Rat<i128> t{h, rate};
      if (!haveExit || t < r.exit) r.exit = t;
      haveExit = true;
    } else if (h <= 0) {
      parallelOutside = true;
    }
  }
  r.bounded = haveEnter;
  if (haveEnter != haveExit) throw std::logic_error("reference: O must be bounded");
  r.overlaps = !parallelOutside && (!r.bounded || r.enter < r.exit);
  for (const Entering& en : entering)
    if (en.t == r.enter) r.enterNormals.push_back(en.n);
  return r;
}

inline RefSweep referenceSweep(std::span<const Vec2> poly, Vec2w motion, Vec2 a, Vec2 b) {
  const Vec2 ends[2] = {a, b};
  return referenceSweep(poly, motion, ends);
}

// The set of s in [0, 1] for which A + s(B - A) lies in the polygon moved by t * motion: the
// closed polygon, or its interior when `strict`.
struct Clip {
  bool hit = false;
  Rat<Int256> lo, hi;
};

inline Clip clipSegment(std::span<const Vec2> poly, Vec2w motion, Vec2 a, Vec2 b, Rat<i128> t, bool strict) {
  const Int256 p = t.num, q = t.den;
  const Vec2w d = b - a;
  Rat<Int256> lo{0, 1}, hi{1, 1};
  bool loOpen = false, hiOpen = false, ok = true;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2w e = poly[(i + 1) % n] - poly[i];
    // Left of edge i of the moved polygon: cross(e, A + s d - w_i - t m) >= 0 (> 0 when strict),
    // i.e. s * ca >= cb after multiplying by q > 0.
    const Int256 ca = q * crossExact(e, d);
    const Int256 cb = p * crossExact(e, motion) - q * crossExact(e, a - poly[i]);
    if (ca.sign() > 0) {
      const Rat<Int256> bound{cb, ca};
      if (bound > lo || (bound == lo && strict)) lo = bound, loOpen = strict;
    } else if (ca.sign() < 0) {
      const Rat<Int256> bound{-cb, -ca};
      if (bound < hi || (bound == hi && strict)) hi = bound, hiOpen = strict;
    } else if (strict ? cb.sign() >= 0 : cb.sign() > 0) {
      ok = false;
    }
  }
  return {ok && (lo < hi || (lo == hi && !loOpen && !hiOpen)), lo, hi};
}

// A + s(B - A) rounded to the nearest unit, halves up: floor((2x + 1) / 2) per coordinate.
inline Vec2w roundedPoint(Vec2 a, Vec2 b, const Rat<Int256>& s) {
  const auto coord = [&](int64_t ac, int64_t dc) {
    const Int256 twoX = Int256(2) * (Int256(ac) * s.den + s.num * dc);  // 2x * den
    return floorDiv(twoX + s.den, Int256(2) * s.den);
  };
  return {coord(a.x, int64_t{b.x} - a.x), coord(a.y, int64_t{b.y} - a.y)};
}

// Where the closed polygon moved by t * motion meets the segment: nothing, one point, or the
// two ends of a shared stretch, each rounded (segment endpoints are integers, so stay exact).
struct RefContact {
  int count = 0;
  Vec2w points[2];
};

inline RefContact referenceContact(std::span<const Vec2> poly, Vec2w motion, Vec2 a, Vec2 b, Rat<i128> t) {
  const Clip c = clipSegment(poly, motion, a, b, t, false);
  RefContact r;
  if (!c.hit) return r;
  r.points[r.count++] = roundedPoint(a, b, c.lo);
  if (c.lo < c.hi) r.points[r.count++] = roundedPoint(a, b, c.hi);
  return r;
}

}  // namespace platon::testing::reference
