#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

#include "platon/physics/convex.h"
#include "platon/physics/fraction.h"
#include "platon/testing/rng.h"

using namespace platon::physics;

TEST(Angle, QuarterTurnsAreExact) {
  EXPECT_EQ(rotationOf(0).c, 1 << 30);
  EXPECT_EQ(rotationOf(kQuarterTurn).s, 1 << 30);
  EXPECT_EQ(rotationOf(kQuarterTurn).c, 0);
  EXPECT_EQ(rotationOf(kHalfTurn).c, -(1 << 30));
  EXPECT_EQ(rotationOf(3 * kQuarterTurn).s, -(1 << 30));
}

TEST(Angle, RotationIsUnitLengthAndMatchesTheAngle) {
  for (int64_t deg = -720; deg <= 720; deg += 7) {
    const Rotation r = rotationOf(angleFromDegrees(deg));
    const double rad = static_cast<double>(deg) * 3.14159265358979323846 / 180.0;
    EXPECT_NEAR(static_cast<double>(r.c) / (1 << 30), std::cos(rad), 1.5e-9) << deg;
    EXPECT_NEAR(static_cast<double>(r.s) / (1 << 30), std::sin(rad), 1.5e-9) << deg;
  }
}

TEST(Angle, AngleOfInvertsRotation) {
  for (int64_t deg = 0; deg < 360; deg += 5) {
    const Angle a = angleFromDegrees(deg);
    const Rotation r = rotationOf(a);
    for (const int64_t scale : {int64_t{1}, int64_t{1000}, int64_t{1} << 20}) {
      const Angle back = angleOf({r.c * scale, r.s * scale});
      const int32_t error = static_cast<int32_t>(back - a);
      EXPECT_LE(std::abs(error), 1) << deg << " degrees, scale " << scale;
    }
  }
  EXPECT_EQ(angleOf({0, 0}), 0u);
  EXPECT_EQ(angleOf({5, 0}), 0u);
  EXPECT_EQ(angleOf({-5, 0}), kHalfTurn);
}

TEST(Angle, DegreesConvertExactlyAtQuarterTurns) {
  EXPECT_EQ(angleFromDegrees(90), kQuarterTurn);
  EXPECT_EQ(angleFromDegrees(-90), 3 * kQuarterTurn);
  EXPECT_EQ(angleFromDegrees(450), kQuarterTurn);
  const int32_t pentagon = static_cast<int32_t>(angleFromDegrees(72) * 5u);  // 2^32 / 5 is not whole
  EXPECT_LE(std::abs(pentagon), 5);
}

TEST(Fraction, ComparesExactlyAtTheLimits) {
  const int64_t big = INT64_MAX;
  EXPECT_LT((Fraction{big - 1, big}), (Fraction{big, big}));
  EXPECT_LT((Fraction{-big, 1}), (Fraction{big, 1}));
  EXPECT_EQ((Fraction{2, 4}), (Fraction{1, 2}));
  EXPECT_GT((Fraction{1, big}), Fraction::zero());
  EXPECT_EQ((Fraction{3, 4}).scaledFloor(8), 192);
}

TEST(Convex, RotationRoundsAndStaysConvex) {
  const Convex box = Convex::box(100, 50);
  const Convex quarter = box.rotated(kQuarterTurn);
  int64_t maxX = 0, maxY = 0;
  for (const Vec2 v : quarter.vertices()) maxX = std::max<int64_t>(maxX, v.x), maxY = std::max<int64_t>(maxY, v.y);
  EXPECT_EQ(maxX, 50);
  EXPECT_EQ(maxY, 100);
  for (int64_t deg = 1; deg < 360; deg += 13) {
    const Convex turned = box.rotated(angleFromDegrees(deg));
    EXPECT_NO_THROW(Convex(std::vector<Vec2>(turned.vertices().begin(), turned.vertices().end()))) << deg;
  }
  EXPECT_EQ(convexHull({{0, 0}, {2, 2}, {1, 1}, {2, 0}, {0, 2}, {1, 0}}).size(), 4u);
}

// convexHull over every scale a caller can give it, up to points at both ends of int32: the hull
// is exactly the one the points have (checked in 128 bits: every point on or left of every edge,
// every corner a strict left turn, every corner an input point). Before its turns were taken in
// 128 bits, points 2^31 apart overflowed a signed 64-bit cross product (UBSan) and bent the hull.
TEST(Convex, HullsOfPointsAnywhereInInt32AreExact) {
  platon::testing::Rng rng{2026};
  auto coordinate = [&](int64_t scale) {
    const uint64_t span = static_cast<uint64_t>(2 * scale + 1);
    return static_cast<int32_t>(static_cast<int64_t>(rng.next() % span) - scale);
  };
  const int64_t scales[] = {3, 100, int64_t{1} << 20, int64_t{1} << 29, INT32_MAX};
  for (const int64_t scale : scales)
    for (int set = 0; set < 400; ++set) {
      std::vector<Vec2> points;
      const int n = rng.between(1, 40);
      for (int i = 0; i < n; ++i) {
        Vec2 p{coordinate(scale), coordinate(scale)};
        if (scale == INT32_MAX && rng.between(0, 3) == 0) p.x = rng.between(0, 1) ? INT32_MAX : INT32_MIN;
        if (scale == INT32_MAX && rng.between(0, 3) == 0) p.y = rng.between(0, 1) ? INT32_MAX : INT32_MIN;
        points.push_back(p);
        if (rng.between(0, 5) == 0) points.push_back(p);  // repeats
      }
      const std::vector<Vec2> hull = convexHull(points);
      auto turn = [](Vec2 o, Vec2 a, Vec2 b) { return cross128(wide(a) - wide(o), wide(b) - wide(o)); };
      const size_t k = hull.size();
      for (const Vec2 c : hull) ASSERT_NE(std::find(points.begin(), points.end(), c), points.end());
      if (k < 3) {  // all the points on one line
        for (const Vec2 p : points)
          ASSERT_TRUE(k == 2 ? turn(hull[0], hull[1], p) == 0 : p == hull[0]) << scale << " set " << set;
        continue;
      }
      for (size_t i = 0; i < k; ++i) {
        ASSERT_GT(turn(hull[i], hull[(i + 1) % k], hull[(i + 2) % k]), 0) << scale << " set " << set;
        for (const Vec2 p : points) ASSERT_GE(turn(hull[i], hull[(i + 1) % k], p), 0) << scale << " set " << set;
      }
    }
  // The whole square of int32, with points on its sides and inside: its four corners.
  const std::vector<Vec2> square = convexHull({{INT32_MIN, INT32_MIN},
                                               {INT32_MAX, INT32_MIN},
                                               {0, INT32_MIN},
                                               {INT32_MAX, INT32_MAX},
                                               {INT32_MIN, INT32_MAX},
                                               {0, 0},
                                               {INT32_MIN, 5}});
  EXPECT_EQ(square,
            (std::vector<Vec2>{
                {INT32_MIN, INT32_MIN}, {INT32_MAX, INT32_MIN}, {INT32_MAX, INT32_MAX}, {INT32_MIN, INT32_MAX}}));
}
