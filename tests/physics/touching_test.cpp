// The rest test's answer for a line a body touches is the slide's answer for a contact where the
// body stands: nearNormals saying Touching gives exactly the normals (the same, in the same order)
// that touchingNormals gives at t = 0, whatever the motion. The slide reads the rest test's
// normals instead of asking again (WorldImpl::Scratch::TouchMemo), so this is what keeps it exact.
// Families: random convex polygons against segments along their edges (a side on a floor), from
// their vertices (a corner on a line, a line's end on a side), and random segments near them,
// half of them shifted by -2..2 units so that touching, overlapping, near and apart all come up.
#include <random>

#include <gtest/gtest.h>

#include "contact_normal.h"  // internal: linked through platon_physics_internals
#include "platon/physics/convex.h"

using namespace platon::physics;

namespace {

int64_t uni(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
}

std::vector<Vec2> polygon(std::mt19937_64& rng) {
  const int64_t radius = uni(rng, 2, 3000);
  for (;;) {
    std::vector<Vec2> pts;
    for (int64_t k = uni(rng, 3, 9); k > 0; --k)
      pts.push_back({static_cast<int32_t>(uni(rng, -radius, radius)), static_cast<int32_t>(uni(rng, -radius, radius))});
    pts = convexHull(pts);
    if (pts.size() >= 3) return pts;
  }
}

Vec2 plus(Vec2 p, Vec2w d) { return {static_cast<int32_t>(p.x + d.x), static_cast<int32_t>(p.y + d.y)}; }

// A segment the polygon touches or nearly touches.
Segment segmentBy(std::mt19937_64& rng, const std::vector<Vec2>& poly) {
  const size_t n = poly.size(), i = static_cast<size_t>(uni(rng, 0, static_cast<int64_t>(n) - 1));
  const Vec2 v = poly[i], next = poly[(i + 1) % n];
  const Vec2w e = next - v;
  const Vec2w shift = uni(rng, 0, 1) ? Vec2w{} : Vec2w{uni(rng, -2, 2), uni(rng, -2, 2)};  // half of them exact
  switch (uni(rng, 0, 2)) {
    case 0: {  // along an edge, past either end or inside it
      const int64_t s = uni(rng, -3, 1), t = uni(rng, 0, 4);
      return {plus(v, {e.x * s / 2 + shift.x, e.y * s / 2 + shift.y}),
              plus(v, {e.x * t / 2 + shift.x, e.y * t / 2 + shift.y})};
    }
    case 1: {  // from a vertex, outward
      const Vec2w out{e.y + uni(rng, -e.x, e.x) / 2, -e.x + uni(rng, -e.y, e.y) / 2};
      return {plus(v, shift), plus(v, {out.x + shift.x, out.y + shift.y})};
    }
    default: {  // any segment near it
      const Vec2 a = plus(v, {uni(rng, -50, 50), uni(rng, -50, 50)});
      return {a, plus(a, {uni(rng, -4000, 4000), uni(rng, -4000, 4000)})};
    }
  }
}

}  // namespace

TEST(Touching, TheRestTestsTouchingNormalsAreTheSlidesWhereItStands) {
  std::mt19937_64 rng(2026);
  int touching = 0, others = 0;
  for (int k = 0; k < 400000; ++k) {
    const std::vector<Vec2> poly = polygon(rng);
    const Segment seg = segmentBy(rng, poly);
    if (seg.a == seg.b) continue;
    std::vector<Vec2w> near, atStart;
    const Nearness nearness = nearNormals(poly, seg, near);
    const Vec2w motion{uni(rng, -600, 600), uni(rng, -600, 600)};
    const bool touches = touchingNormals(poly, motion, Fraction::zero(), seg, atStart);
    if (nearness != Nearness::Touching) {
      ++others;
      continue;
    }
    ++touching;
    ASSERT_TRUE(touches) << "case " << k;
    ASSERT_EQ(near, atStart) << "case " << k;
  }
  // Both kinds came up often.
  EXPECT_GT(touching, 50000);
  EXPECT_GT(others, 50000);
}
