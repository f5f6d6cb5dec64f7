// Seeded property test: sweep(), contactPoints(), overlapsInterior() and touchesOrOverlaps()
// against the independent brute-force reference in reference_geometry.h.
//
// Every case is drawn from std::mt19937_64 with a fixed, printed seed (override with the
// environment variable PLATON_SWEEP_SEED); a failing case is printed in full.
#include <algorithm>
#include <bit>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/physics/convex.h"
#include "platon/physics/sweep.h"
#include "platon/testing/reference_geometry.h"

using namespace platon::physics;
namespace ref = platon::testing::reference;
using ref::Rat;

namespace {

struct Case {
  std::vector<Vec2> poly;
  Vec2w motion;
  Segment seg;
};

std::string describe(const Case& c) {
  std::ostringstream o;
  o << "\n  polygon {";
  for (const Vec2 v : c.poly) o << "{" << v.x << ", " << v.y << "}, ";
  o << "}\n  motion {" << c.motion.x << ", " << c.motion.y << "}\n  segment {{" << c.seg.a.x << ", " << c.seg.a.y
    << "}, {" << c.seg.b.x << ", " << c.seg.b.y << "}}";
  return o.str();
}

std::string str(Fraction f) { return std::to_string(f.num) + "/" + std::to_string(f.den); }
std::string str(const Rat<i128>& r) { return ref::toString(r.num) + "/" + ref::toString(r.den); }
std::string str(Vec2w v) { return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ")"; }
bool same(Fraction f, const Rat<i128>& r) { return Rat<i128>{f.num, f.den} == r; }

Vec2w operator*(Vec2w v, int64_t k) { return {v.x * k, v.y * k}; }
// d = lattice(d) * step(d), where step(d) is the shortest lattice step along d.
int64_t lattice(Vec2w d) { return std::gcd(d.x, d.y); }
Vec2w step(Vec2w d) { return lattice(d) == 0 ? d : Vec2w{d.x / lattice(d), d.y / lattice(d)}; }

// Random cases that favour the coincidences an exact sweep must get right: exact touching at
// t = 0, edges along the segment, shared endpoints, zero/unit/parallel/near-parallel motions, and
// motions aimed at the segment so that hits inside the frame are common.
class CaseGen {
 public:
  CaseGen(uint64_t seed, int64_t coordLimit, int64_t moveLimit)
      : rng_(seed), coordLimit_(coordLimit), moveLimit_(moveLimit) {}

  Case next() {
    for (;;) {
      std::vector<Vec2w> poly;
      Vec2w a, b, m;
      build(poly, a, b, m);
      const auto in = [&](Vec2w p) { return std::max(std::abs(p.x), std::abs(p.y)) <= coordLimit_; };
      if (!std::all_of(poly.begin(), poly.end(), in) || !in(a) || !in(b) || a == b) continue;
      if (std::max(std::abs(m.x), std::abs(m.y)) > moveLimit_) continue;
      Case c{{}, m, {narrow(a), narrow(b)}};
      for (const Vec2w v : poly) c.poly.push_back(narrow(v));
      return c;
    }
  }

 private:
  static Vec2 narrow(Vec2w p) { return {static_cast<int32_t>(p.x), static_cast<int32_t>(p.y)}; }
  int64_t uni(int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng_); }
  bool oneIn(int64_t n) { return uni(1, n) == 1; }
  Vec2w randVec(int64_t r) { return {uni(-r, r), uni(-r, r)}; }
  // Log-uniform magnitude in [1, limit]: tiny shapes (rich in lattice coincidences) are as common
  // as huge ones. At the full range, half the draws come from the top 3 bits to stress overflow.
  int64_t size(int64_t limit) {
    const int64_t width = std::bit_width(static_cast<uint64_t>(limit));
    const int bits =
        static_cast<int>(uni(coordLimit_ > (1 << 20) && oneIn(2) ? std::max<int64_t>(0, width - 3) : 0, width - 1));
    return std::min(limit, uni(int64_t{1} << bits, (int64_t{2} << bits) - 1));
  }
  Vec2w clamp(Vec2w p) const {
    return {std::clamp(p.x, -coordLimit_, coordLimit_), std::clamp(p.y, -coordLimit_, coordLimit_)};
  }

  // A strictly convex CCW polygon around `center`. Entity-sized ones are validated by the Convex
  // constructor; wider ones (legal for sweep(), though no entity is that big) come straight from
  // the hull, which is strictly convex and counter-clockwise by construction.
  std::vector<Vec2w> polygon(Vec2w center, int64_t radius) {
    for (;;) {
      std::vector<Vec2> pts;
      if (oneIn(8) && radius >= 64 && radius <= kShapeLimit) {
        const Convex regular = Convex::regular(static_cast<int>(uni(3, 64)), static_cast<int32_t>(radius));
        pts.assign(regular.vertices().begin(), regular.vertices().end());
      } else {
        for (int64_t k = uni(3, 12); k > 0; --k) pts.push_back(narrow(randVec(radius)));
        pts = convexHull(pts);
      }
      if (pts.size() < 3) continue;
      if (radius <= kShapeLimit) (void)Convex(pts);  // throws if the physics would reject the shape
      std::vector<Vec2w> out;
      for (const Vec2 v : pts) out.push_back(center + wide(v));
      // Any vertex may come first: hulls always start at the lowest x, callers need not.
      std::rotate(out.begin(), out.begin() + uni(0, static_cast<int64_t>(out.size()) - 1), out.end());
      return out;
    }
  }

  void build(std::vector<Vec2w>& poly, Vec2w& a, Vec2w& b, Vec2w& m) {
    const bool fullRange = coordLimit_ > kShapeLimit && oneIn(8);  // edges up to 2^31 - 2
    const int64_t r = fullRange ? coordLimit_ : size(std::min<int64_t>(coordLimit_ / 2, kShapeLimit));
    const Vec2w center = fullRange  ? Vec2w{0, 0}
                         : oneIn(8) ? Vec2w{coordLimit_ - r, -(coordLimit_ - r)}
                                    : randVec(coordLimit_ - r);
    poly = polygon(center, r);
    const auto vertex = [&] { return poly[uni(0, static_cast<int64_t>(poly.size()) - 1)]; };
    const int64_t reach = oneIn(8) ? size(coordLimit_) : 2 * r + 2;
    bool mayTouch = true;
    switch (uni(0, 4)) {
      case 0:  // anywhere near the polygon
        a = clamp(center + randVec(reach)), b = clamp(center + randVec(reach));
        break;
      case 1:  // with interior lattice points, where a vertex can sit exactly
        a = clamp(center + randVec(reach)), b = a + randVec(uni(1, 4)) * uni(1, 8);
        break;
      case 2:  // sharing an endpoint with a vertex
        a = vertex(), b = clamp(center + randVec(reach));
        if (oneIn(2)) std::swap(a, b);
        break;
      case 3: {  // on the line of an edge: overlapping it, extending it, or apart from it
        const size_t i = uni(0, static_cast<int64_t>(poly.size()) - 1);
        const Vec2w w = poly[i], e = poly[(i + 1) % poly.size()] - w, s = step(e);
        const int64_t g = lattice(e);
        const int64_t picks[] = {0, g, -1, g + 1, uni(-g - 2, 2 * g + 2), uni(-g - 2, 2 * g + 2)};
        a = w + s * picks[uni(0, 5)], b = w + s * picks[uni(0, 5)];
        mayTouch = false;
        break;
      }
      default: {  // through a vertex
        const Vec2w v = vertex(), dir = randVec(size(r + 1));
        a = v - dir * uni(0, 2), b = v + dir * uni(0, 2);
        mayTouch = false;
      }
    }
    const Vec2w d = b - a, ds = step(d);
    if (mayTouch && oneIn(3)) {  // move the polygon so a vertex lies exactly on the segment
      const int64_t g = lattice(d);
      const int64_t picks[] = {0, g, uni(0, g)};
      Vec2w shift = a + ds * picks[uni(0, 2)] - vertex();
      if (oneIn(4)) shift = shift + randVec(1);  // or a near miss
      for (Vec2w& v : poly) v = v + shift;
    }
    switch (uni(0, 7)) {
      case 0:  // zero
        m = {0, 0};
        break;
      case 1:  // a single unit (or zero)
        m = randVec(1);
        break;
      case 2:  // parallel to the segment
        m = ds * uni(-3, 3);
        break;
      case 3:  // near-parallel
        m = ds * uni(1, 3) + randVec(1);
        break;
      case 4: {  // parallel to an edge
        const size_t i = uni(0, static_cast<int64_t>(poly.size()) - 1);
        m = (poly[(i + 1) % poly.size()] - poly[i]) * uni(-2, 2);
        break;
      }
      case 5:  // anything
        m = randVec(size(moveLimit_));
        break;
      default: {  // aimed at a point of the segment, often arriving exactly at t = 1 or 1/2
        const Vec2w target{a.x + d.x * uni(0, 8) / 8, a.y + d.y * uni(0, 8) / 8};
        const Vec2w from = oneIn(3) ? center : vertex();
        m = (target - from) * uni(1, 2);
        if (oneIn(2)) m = m + randVec(1);
      }
    }
  }

  std::mt19937_64 rng_;
  int64_t coordLimit_, moveLimit_;
};

uint64_t seedFor(uint64_t fallback) {
  const char* env = std::getenv("PLATON_SWEEP_SEED");
  const uint64_t seed = env ? std::strtoull(env, nullptr, 0) : fallback;
  std::cout << "[   SEED   ] " << ::testing::UnitTest::GetInstance()->current_test_info()->name() << " seed = " << seed
            << " (set PLATON_SWEEP_SEED to change)\n";
  return seed;
}

// Collects disagreements for one case; an empty result means the case passed.
struct Checker {
  std::string problems;
  void expect(bool ok, const std::string& what) {
    if (!ok) problems += "\n  " + what;
  }
};

const Rat<i128> kZero{0, 1}, kOne{1, 1};

void checkStatic(const Case& c, Checker& k) {
  const ref::RefSweep r = ref::referenceSweep(c.poly, c.motion, c.seg.a, c.seg.b);
  // Two independent reference routes (obstacle hull, direct clipping) must agree first.
  const bool openClip = ref::clipSegment(c.poly, c.motion, c.seg.a, c.seg.b, kZero, true).hit;
  const bool closedClip = ref::clipSegment(c.poly, c.motion, c.seg.a, c.seg.b, kZero, false).hit;
  k.expect(r.overlapsAtZero == openClip, "REFERENCE self-check: interior overlap at t=0 differs");
  k.expect(r.touchesAtZero == closedClip, "REFERENCE self-check: touching at t=0 differs");
  const bool over = overlapsInterior(c.poly, c.seg), touch = touchesOrOverlaps(c.poly, c.seg);
  k.expect(over == openClip, "overlapsInterior = " + std::to_string(over) + ", reference " + std::to_string(openClip));
  k.expect(touch == closedClip,
           "touchesOrOverlaps = " + std::to_string(touch) + ", reference " + std::to_string(closedClip));
}

struct Stats {
  int cases = 0, nonEmpty = 0, hits = 0, startsInside = 0, touchingAtStart = 0, vertexEntries = 0, stretches = 0;
};

void checkSweep(const Case& c, Checker& k, Stats& stats) {
  const ref::RefSweep r = ref::referenceSweep(c.poly, c.motion, c.seg.a, c.seg.b);
  const Sweep s = sweep(c.poly, c.motion, c.seg);
  const bool nonEmpty = r.overlaps && (!r.bounded || r.exit > kZero);
  const bool hits = nonEmpty && r.bounded && r.enter >= kZero && r.enter < kOne;
  const bool inside = nonEmpty && (!r.bounded || r.enter < kZero);
  k.expect(s.empty == !nonEmpty, "empty = " + std::to_string(s.empty) + ", reference interval " +
                                     (r.bounded ? "(" + str(r.enter) + ", " + str(r.exit) + ")" : "unbounded") +
                                     " overlaps=" + std::to_string(r.overlaps));
  k.expect(s.hitsWithinFrame() == hits, "hitsWithinFrame = " + std::to_string(s.hitsWithinFrame()));
  k.expect(s.startsInside() == inside, "startsInside = " + std::to_string(s.startsInside()));
  stats.cases++, stats.nonEmpty += nonEmpty, stats.hits += hits, stats.startsInside += inside;
  stats.touchingAtStart += r.touchesAtZero && !r.overlapsAtZero;

  if (nonEmpty && !s.empty) {
    k.expect(s.hasEnter == r.bounded && s.hasExit == r.bounded, "hasEnter/hasExit wrong");
    if (r.bounded && s.hasEnter && s.hasExit) {
      k.expect(same(s.enter, r.enter), "enter = " + str(s.enter) + ", reference " + str(r.enter));
      k.expect(same(s.exit, r.exit), "exit = " + str(s.exit) + ", reference " + str(r.exit));
      const Vec2w n = s.normal();
      std::string valid;
      bool ok = false;
      for (const Vec2w rn : r.enterNormals) {
        ok = ok || (ref::crossExact(n, rn) == 0 && ref::dotExact(n, rn) > 0);
        valid += " " + str(rn);
      }
      k.expect(ok, "normal = " + str(n) + ", reference allows" + valid);
      stats.vertexEntries += r.enterNormals.size() > 1;

      // Contacts at the exact entry time: the closed sets touch, the interiors do not yet.
      const ref::RefContact want = ref::referenceContact(c.poly, c.motion, c.seg.a, c.seg.b, r.enter);
      k.expect(want.count > 0 && !ref::clipSegment(c.poly, c.motion, c.seg.a, c.seg.b, r.enter, true).hit,
               "REFERENCE self-check: no clean touch at the entry time");
      const ContactPoints got = contactPoints(c.poly, c.motion, c.seg, s);
      const auto at = [&](int i) { return wide(got.points[i]); };
      bool match = got.count == want.count;
      if (match && want.count == 1) match = at(0) == want.points[0];
      if (match && want.count == 2)
        match = (at(0) == want.points[0] && at(1) == want.points[1]) ||
                (at(0) == want.points[1] && at(1) == want.points[0]);
      std::string gotS, wantS;
      for (int i = 0; i < got.count; ++i) gotS += " " + str(at(i));
      for (int i = 0; i < want.count; ++i) wantS += " " + str(want.points[i]);
      k.expect(match, "contactPoints =" + gotS + ", reference" + wantS + " (enter " + str(r.enter) + ")");
      stats.stretches += want.count == 2;
    }
  }

  // A third route that needs neither interval: clip the moved polygon directly at fixed times.
  for (int64_t q = 0; q <= 4; ++q) {
    const bool open = ref::clipSegment(c.poly, c.motion, c.seg.a, c.seg.b, {q, 4}, true).hit;
    const Fraction t{q, 4};
    const bool claimed = !s.empty && (!s.hasEnter || s.enter < t) && (!s.hasExit || t < s.exit);
    k.expect(open == claimed, "at t = " + str(t) + " interiors meet = " + std::to_string(open) +
                                  " but the sweep interval says " + std::to_string(claimed));
  }
}

// Runs `count` cases; stops after a few failing ones so a systematic bug stays readable.
template <class Check>
void runCases(uint64_t seed, int count, int64_t coordLimit, int64_t moveLimit, Check check) {
  CaseGen gen(seed, coordLimit, moveLimit);
  int failures = 0;
  for (int i = 0; i < count && failures < 10; ++i) {
    const Case c = gen.next();
    Checker k;
    try {
      check(c, k);
    } catch (const std::exception& e) {
      k.problems += std::string("\n  exception: ") + e.what();
    }
    if (!k.problems.empty()) {
      ++failures;
      ADD_FAILURE() << "case #" << i << " (seed " << seed << ")" << describe(c) << k.problems;
    }
  }
}

void printStats(const Stats& s) {
  std::cout << "[  STATS   ] cases " << s.cases << ", non-empty " << s.nonEmpty << ", hits in frame " << s.hits
            << ", starting inside " << s.startsInside << ", touching at t=0 " << s.touchingAtStart
            << ", vertex entries " << s.vertexEntries << ", shared stretches " << s.stretches << "\n";
}

}  // namespace

// The reference's own arithmetic, against plain __int128 where that is exact.
TEST(SweepPropertyReference, Int256AgreesWithInt128) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const auto draw = [&] {
      const int bits = static_cast<int>(rng() % 62);
      const int64_t v = static_cast<int64_t>(rng() >> (63 - bits)) >> 1;
      return rng() % 2 ? v : -v;
    };
    const i128 a = draw(), b = draw(), c = draw(), d = draw();
    const ref::Int256 x = ref::Int256(a) * b - ref::Int256(c) * d;
    EXPECT_EQ(x, ref::Int256(a * b - c * d));
    EXPECT_EQ(x <=> ref::Int256(0), (a * b - c * d) <=> 0);
    EXPECT_EQ(ref::Int256(a * b) <=> ref::Int256(c * d), (a * b) <=> (c * d));
  }
  const ref::Int256 big = ref::Int256(i128{1} << 100) * (i128{1} << 100);  // 2^200
  EXPECT_GT(big, ref::Int256((i128{1} << 126) - 1) * 4);
  EXPECT_LT(-big, ref::Int256(0));
  EXPECT_EQ(ref::floorDiv(big * 5 + 3, big), 5);
  EXPECT_EQ(ref::floorDiv(-(big * 5) - 3, big), -6);
  EXPECT_THROW(big * big, std::overflow_error);
}

// Hand-computed cases: the reference itself must give the textbook answers.
TEST(SweepPropertyReference, HandCheckedCases) {
  const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  {  // square moving right onto a vertical segment: flush edge contact at t = 2/5
    const ref::RefSweep r = ref::referenceSweep(square, {10, 0}, {6, -5}, {6, 5});
    ASSERT_TRUE(r.overlaps && r.bounded);
    EXPECT_EQ(r.enter, (Rat<i128>{2, 5}));
    EXPECT_EQ(r.exit, (Rat<i128>{3, 5}));
    ASSERT_EQ(r.enterNormals.size(), 1u);
    EXPECT_EQ(r.enterNormals[0], (Vec2w{-1, 0}));
    const ref::RefContact c = ref::referenceContact(square, {10, 0}, {6, -5}, {6, 5}, r.enter);
    ASSERT_EQ(c.count, 2);
    EXPECT_EQ(c.points[0], (Vec2w{6, 0}));
    EXPECT_EQ(c.points[1], (Vec2w{6, 2}));
  }
  {  // corner onto the segment's endpoint, diagonally: two valid normals
    const ref::RefSweep r = ref::referenceSweep(square, {4, 4}, {4, 4}, {4, 9});
    ASSERT_TRUE(r.overlaps && r.bounded);
    EXPECT_EQ(r.enter, (Rat<i128>{1, 2}));
    ASSERT_EQ(r.enterNormals.size(), 2u);
    const ref::RefContact c = ref::referenceContact(square, {4, 4}, {4, 4}, {4, 9}, r.enter);
    ASSERT_EQ(c.count, 1);
    EXPECT_EQ(c.points[0], (Vec2w{4, 4}));
  }
  {  // rounding: apex (1, 2) of a triangle reaches y = 5 at t = 1/2 with x = 1 + 3/2 -> 3 (half up)
    const std::vector<Vec2> tri{{0, 0}, {2, 0}, {1, 2}};
    const ref::RefSweep r = ref::referenceSweep(tri, {3, 6}, {-10, 5}, {10, 5});
    EXPECT_EQ(r.enter, (Rat<i128>{1, 2}));
    const ref::RefContact c = ref::referenceContact(tri, {3, 6}, {-10, 5}, {10, 5}, r.enter);
    ASSERT_EQ(c.count, 1);
    EXPECT_EQ(c.points[0], (Vec2w{3, 5}));
  }
  // Sliding along a segment without penetrating is no overlap; static touching is not overlap.
  EXPECT_FALSE(ref::referenceSweep(square, {5, 0}, {-5, 2}, {5, 2}).overlaps);
  const ref::RefSweep touching = ref::referenceSweep(square, {0, 0}, {2, 1}, {5, 1});
  EXPECT_TRUE(touching.touchesAtZero);
  EXPECT_FALSE(touching.overlapsAtZero);
}

// Main run: |coordinate| <= 2^20, |motion component| <= 2^22.
TEST(SweepProperty, MatchesReference) {
  Stats stats;
  runCases(seedFor(0x5eed'0001), 20000, 1 << 20, 1 << 22, [&](const Case& c, Checker& k) { checkSweep(c, k, stats); });
  printStats(stats);
}

TEST(SweepProperty, StaticPredicatesMatchReference) {
  runCases(seedFor(0x5eed'0002), 20000, 1 << 20, 1 << 22, checkStatic);
}

// The whole legal range: coordinates up to kCoordLimit, motions up to sweep()'s own limit of
// 2^31 - 2 (beyond the world's kMaxMove). The reference stays exact here (see the bounds in
// reference_geometry.h; its products are overflow-checked).
TEST(SweepProperty, LargeCoordinates) {
  Stats stats;
  runCases(seedFor(0x5eed'0003), 5000, kCoordLimit, (int64_t{1} << 31) - 2, [&](const Case& c, Checker& k) {
    checkStatic(c, k);
    checkSweep(c, k, stats);
  });
  printStats(stats);
}
