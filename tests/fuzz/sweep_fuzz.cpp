// libFuzzer target: sweep(), overlapsInterior(), touchesOrOverlaps(), contactPoints() and the stop
// rounding of roundedStep() against the independent exact reference (reference_geometry.h), over
// the whole legal coordinate range. Any disagreement prints the case as C++ and traps.
#include <algorithm>
#include <cstdio>
#include <fuzzer/FuzzedDataProvider.h>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "platon/physics/convex.h"
#include "platon/physics/sweep.h"
#include "platon/testing/reference_geometry.h"

using namespace platon::physics;
namespace ref = platon::testing::reference;
using ref::Rat;

namespace {

constexpr int64_t kLimit = kCoordLimit;
const Rat<i128> kZero{0, 1}, kOne{1, 1};

struct Case {
  std::vector<Vec2> poly;
  Vec2w motion;
  Segment seg;
};

std::string str(Vec2w v) { return "{" + std::to_string(v.x) + ", " + std::to_string(v.y) + "}"; }
std::string str(Fraction f) { return std::to_string(f.num) + "/" + std::to_string(f.den); }
std::string str(const Rat<i128>& r) { return ref::toString(r.num) + "/" + ref::toString(r.den); }

[[noreturn]] void fail(const Case& c, const std::string& what) {
  std::ostringstream o;
  o << "sweep_fuzz MISMATCH: " << what << "\n  const std::vector<Vec2> polygon{";
  for (const Vec2 v : c.poly) o << str(wide(v)) << ", ";
  o << "};\n  const Vec2w motion" << str(c.motion) << ";\n  const Segment segment{" << str(wide(c.seg.a)) << ", "
    << str(wide(c.seg.b)) << "};\n";
  std::fputs(o.str().c_str(), stderr);
  __builtin_trap();
}

void expect(const Case& c, bool ok, const std::string& what) {
  if (!ok) fail(c, what);
}

Vec2w operator*(Vec2w v, int64_t k) { return {v.x * k, v.y * k}; }
Vec2w clampToRange(Vec2w p) { return {std::clamp(p.x, -kLimit, kLimit), std::clamp(p.y, -kLimit, kLimit)}; }
Vec2 narrow(Vec2w p) { return {static_cast<int32_t>(p.x), static_cast<int32_t>(p.y)}; }
// The shortest lattice step along d (d itself when zero).
Vec2w latticeStep(Vec2w d) {
  const int64_t g = std::gcd(d.x, d.y);
  return g == 0 ? d : Vec2w{d.x / g, d.y / g};
}

// Turns fuzzer bytes into geometry. Every magnitude goes through a decoded scale, so tiny shapes
// (rich in the exact lattice coincidences an exact sweep must get right) are as easy to reach as
// ones spanning the whole range.
class Decoder {
 public:
  Decoder(const uint8_t* data, size_t size) : in_(data, size) {}

  int64_t range(int64_t lo, int64_t hi) { return in_.ConsumeIntegralInRange(lo, hi); }
  bool flag() { return in_.ConsumeBool(); }
  int shift() { return static_cast<int>(range(0, 16)); }
  // A signed offset of magnitude up to 2^31: a coarse part at scale 2^shift plus fine noise.
  int64_t scaled(int s) { return (int64_t{in_.ConsumeIntegral<int16_t>()} << s) + in_.ConsumeIntegral<int8_t>(); }
  Vec2w vec(int s) { return {scaled(s), scaled(s)}; }
  Vec2w point() { return {range(-kLimit, kLimit), range(-kLimit, kLimit)}; }

 private:
  FuzzedDataProvider in_;
};

bool decode(Decoder& in, Case& c) {
  // The polygon: the hull of 3..12 points around a centre anywhere in range.
  const Vec2w center = in.point();
  const int polyShift = in.shift();
  std::vector<Vec2> points;
  for (int64_t k = in.range(3, 12); k > 0; --k) points.push_back(narrow(clampToRange(center + in.vec(polyShift))));
  std::vector<Vec2> hull = convexHull(points);
  if (hull.size() < 3) return false;
  std::rotate(hull.begin(), hull.begin() + in.range(0, static_cast<int64_t>(hull.size()) - 1), hull.end());
  std::vector<Vec2w> poly(hull.size());
  std::transform(hull.begin(), hull.end(), poly.begin(), wide);
  const auto vertex = [&] { return poly[in.range(0, static_cast<int64_t>(poly.size()) - 1)]; };

  // The segment: anywhere, from a vertex, on an edge's line, or through a vertex.
  Vec2w a, b;
  bool mayShift = true;
  switch (in.range(0, 3)) {
    case 0: {
      const int s = in.shift();
      a = center + in.vec(s), b = center + in.vec(s);
      break;
    }
    case 1:
      a = vertex(), b = a + in.vec(in.shift());
      if (in.flag()) std::swap(a, b);
      break;
    case 2: {  // overlapping, extending or apart from an edge, on its line
      const size_t i = in.range(0, static_cast<int64_t>(poly.size()) - 1);
      const Vec2w w = poly[i], e = poly[(i + 1) % poly.size()] - w;
      const int64_t g = std::gcd(e.x, e.y);
      const auto pick = [&] {
        const int64_t picks[] = {0, g, -1, g + 1, g / 2, in.scaled(in.shift())};
        return picks[in.range(0, 5)];
      };
      a = w + latticeStep(e) * pick(), b = w + latticeStep(e) * pick();
      mayShift = false;
      break;
    }
    default: {
      const Vec2w v = vertex(), dir = in.vec(in.shift());
      a = v - dir * in.range(0, 2), b = v + dir * in.range(0, 2);
      mayShift = false;
    }
  }
  a = clampToRange(a), b = clampToRange(b);
  if (a == b) return false;
  const Vec2w d = b - a, ds = latticeStep(d);
  if (mayShift && in.flag()) {  // put a vertex exactly on a lattice point of the segment, or one unit off
    const int64_t g = std::gcd(d.x, d.y);
    const int64_t picks[] = {0, g, in.range(0, g)};
    Vec2w shift = a + ds * picks[in.range(0, 2)] - vertex();
    if (in.flag()) shift = shift + Vec2w{in.range(-1, 1), in.range(-1, 1)};
    std::vector<Vec2w> moved = poly;
    for (Vec2w& v : moved) v = v + shift;
    if (std::all_of(moved.begin(), moved.end(), [](Vec2w v) { return clampToRange(v) == v; })) poly = moved;
  }

  // The motion: zero, a unit, along the segment or an edge, anything, or aimed at the segment.
  Vec2w m;
  switch (in.range(0, 6)) {
    case 0:
      m = {0, 0};
      break;
    case 1:
      m = {in.range(-1, 1), in.range(-1, 1)};
      break;
    case 2:
      m = ds * in.range(-3, 3);
      break;
    case 3:
      m = ds * in.range(1, 3) + Vec2w{in.range(-1, 1), in.range(-1, 1)};
      break;
    case 4: {
      const size_t i = in.range(0, static_cast<int64_t>(poly.size()) - 1);
      m = (poly[(i + 1) % poly.size()] - poly[i]) * in.range(-2, 2);
      break;
    }
    case 5:
      m = in.vec(in.shift());
      break;
    default: {  // often arriving exactly at t = 1 or 1/2
      const int64_t j = in.range(0, 8);
      const Vec2w target{a.x + d.x * j / 8, a.y + d.y * j / 8};
      m = (target - (in.flag() ? center : vertex())) * in.range(1, 2);
      if (in.flag()) m = m + Vec2w{in.range(-1, 1), in.range(-1, 1)};
    }
  }
  // Largest world move per component, and every moved vertex stays in range.
  int64_t lo[2] = {-kMaxMove, -kMaxMove}, hi[2] = {kMaxMove, kMaxMove};
  for (const Vec2w v : poly) {
    lo[0] = std::max(lo[0], -kLimit - v.x), hi[0] = std::min(hi[0], kLimit - v.x);
    lo[1] = std::max(lo[1], -kLimit - v.y), hi[1] = std::min(hi[1], kLimit - v.y);
  }
  m = {std::clamp(m.x, lo[0], hi[0]), std::clamp(m.y, lo[1], hi[1])};

  c.poly.clear();
  for (const Vec2w v : poly) c.poly.push_back(narrow(v));
  c.motion = m;
  c.seg = {narrow(a), narrow(b)};
  return true;
}

void checkStatic(const Case& c) {
  const bool open = ref::clipSegment(c.poly, {0, 0}, c.seg.a, c.seg.b, kZero, true).hit;
  const bool closed = ref::clipSegment(c.poly, {0, 0}, c.seg.a, c.seg.b, kZero, false).hit;
  expect(c, overlapsInterior(c.poly, c.seg) == open,
         "overlapsInterior disagrees with the reference (" + std::to_string(open) + ")");
  expect(c, touchesOrOverlaps(c.poly, c.seg) == closed,
         "touchesOrOverlaps disagrees with the reference (" + std::to_string(closed) + ")");
}

void checkSweep(const Case& c) {
  const ref::RefSweep r = ref::referenceSweep(c.poly, c.motion, c.seg.a, c.seg.b);
  const Sweep s = sweep(c.poly, c.motion, c.seg);
  const bool nonEmpty = r.overlaps && (!r.bounded || r.exit > kZero);
  const bool hits = nonEmpty && r.bounded && r.enter >= kZero && r.enter < kOne;
  const std::string interval =
      r.bounded ? " reference (" + str(r.enter) + ", " + str(r.exit) + ")" : " reference unbounded";
  expect(c, s.empty == !nonEmpty, "empty = " + std::to_string(s.empty) + interval);
  expect(c, s.hitsWithinFrame() == hits, "hitsWithinFrame = " + std::to_string(s.hitsWithinFrame()) + interval);
  expect(c, s.startsInside() == (nonEmpty && (!r.bounded || r.enter < kZero)), "startsInside wrong," + interval);
  if (nonEmpty && r.bounded) {
    expect(c, s.hasEnter && s.hasExit, "hasEnter/hasExit wrong," + interval);
    expect(c, Rat<i128>{s.enter.num, s.enter.den} == r.enter && Rat<i128>{s.exit.num, s.exit.den} == r.exit,
           "interval (" + str(s.enter) + ", " + str(s.exit) + ")," + interval);
    const Vec2w n = s.normal();
    const bool normalOk = std::any_of(r.enterNormals.begin(), r.enterNormals.end(), [&](Vec2w rn) {
      return ref::crossExact(n, rn) == 0 && ref::dotExact(n, rn) > 0;
    });
    expect(c, normalOk, "normal " + str(n) + " is not one of the reference's entry normals");

    const ref::RefContact want = ref::referenceContact(c.poly, c.motion, c.seg.a, c.seg.b, r.enter);
    const ContactPoints got = contactPoints(c.poly, c.motion, c.seg, s);
    const auto at = [&](int i) { return wide(got.points[i]); };
    bool match = got.count == want.count;
    if (match && want.count == 1) match = at(0) == want.points[0];
    if (match && want.count == 2)
      match =
          (at(0) == want.points[0] && at(1) == want.points[1]) || (at(0) == want.points[1] && at(1) == want.points[0]);
    expect(c, match,
           "contactPoints (" + std::to_string(got.count) + ") differ from the reference (" +
               std::to_string(want.count) + ")");
  }
  if (s.hitsWithinFrame()) {
    // The world stops a move at roundedStep(): on the path's box, and never across the segment.
    const Vec2w step = roundedStep(c.motion, s.enter, &s.enterAxis);
    const auto within = [](int64_t v, int64_t m) {
      return std::min<int64_t>(0, m) <= v && v <= std::max<int64_t>(0, m);
    };
    expect(c, within(step.x, c.motion.x) && within(step.y, c.motion.y),
           "roundedStep " + str(step) + " leaves the motion's box");
    std::vector<Vec2> moved;
    for (const Vec2 v : c.poly) moved.push_back(narrow(wide(v) + step));
    expect(c, !overlapsInterior(moved, c.seg),
           "the polygon moved by roundedStep " + str(step) + " overlaps the segment");
    expect(c, !ref::clipSegment(moved, {0, 0}, c.seg.a, c.seg.b, kZero, true).hit,
           "reference: the polygon moved by roundedStep " + str(step) + " overlaps the segment");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Decoder in(data, size);
  Case c;
  if (!decode(in, c)) return -1;  // not a case: keep it out of the corpus
  try {
    checkStatic(c);
    checkSweep(c);
  } catch (const std::exception& e) {  // the reference's overflow checks: a bound in it is wrong
    fail(c, std::string("exception: ") + e.what());
  }
  return 0;
}
