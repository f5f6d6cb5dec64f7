// The rest test's answer for a line a body touches is the slide's answer for a contact where the
// body stands: nearNormals saying Touching gives exactly the normals (the same, in the same order)
// that touchingNormals gives at t = 0, whatever the motion. The slide reads the rest test's
// normals instead of asking again (WorldImpl::Scratch::TouchMemo), so this is what keeps it exact.
// Families: random convex polygons against segments along their edges (a side on a floor), from
// their vertices (a corner on a line, a line's end on a side), and random segments near them,
// half of them shifted by -2..2 units so that touching, overlapping, near and apart all come up.
#include <cstdlib>
#include <random>

#include <gtest/gtest.h>

#include "contact_normal.h"  // internal: linked through platon_physics_internals
#include "platon/physics/convex.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;

namespace {

using platon::testing::between;

// A random convex polygon (testing/random_shapes.h) of any size from a few units to thousands.
std::vector<Vec2> polygon(std::mt19937_64& rng) {
  const Convex c = platon::testing::randomConvex(rng, between(rng, 2, 3000), platon::testing::Turn::MaybeTurned);
  return {c.vertices().begin(), c.vertices().end()};
}

Vec2 plus(Vec2 p, Vec2w d) { return {static_cast<int32_t>(p.x + d.x), static_cast<int32_t>(p.y + d.y)}; }

// A segment the polygon touches or nearly touches.
Segment segmentBy(std::mt19937_64& rng, const std::vector<Vec2>& poly) {
  const size_t n = poly.size(), i = static_cast<size_t>(between(rng, 0, static_cast<int32_t>(n) - 1));
  const Vec2 v = poly[i], next = poly[(i + 1) % n];
  const Vec2w e = next - v;
  const Vec2w shift =
      between(rng, 0, 1) ? Vec2w{} : Vec2w{between(rng, -2, 2), between(rng, -2, 2)};  // half of them exact
  switch (between(rng, 0, 2)) {
    case 0: {  // along an edge, past either end or inside it
      const int64_t s = between(rng, -3, 1), t = between(rng, 0, 4);
      return {plus(v, {e.x * s / 2 + shift.x, e.y * s / 2 + shift.y}),
              plus(v, {e.x * t / 2 + shift.x, e.y * t / 2 + shift.y})};
    }
    case 1: {  // from a vertex, outward
      // Outward from the edge's normal by up to half its length either way.
      const int32_t ax = static_cast<int32_t>(std::abs(e.x)), ay = static_cast<int32_t>(std::abs(e.y));
      const Vec2w out{e.y + between(rng, -ax, ax) / 2, -e.x + between(rng, -ay, ay) / 2};
      return {plus(v, shift), plus(v, {out.x + shift.x, out.y + shift.y})};
    }
    default: {  // any segment near it
      const Vec2 a = plus(v, {between(rng, -50, 50), between(rng, -50, 50)});
      return {a, plus(a, {between(rng, -4000, 4000), between(rng, -4000, 4000)})};
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
    const Vec2w motion{between(rng, -600, 600), between(rng, -600, 600)};
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
