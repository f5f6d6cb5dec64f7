#include <gtest/gtest.h>

#include <cmath>

#include "platon/physics/angle.h"

using namespace platon::physics;

TEST(Angle, QuarterTurnsAreExact) {
  EXPECT_EQ(rotationOf(0).c, 1 << 30);
  EXPECT_EQ(rotationOf(kQuarterTurn).s, 1 << 30);
  EXPECT_EQ(rotationOf(kQuarterTurn).c, 0);
  EXPECT_EQ(rotationOf(kHalfTurn).c, -(1 << 30));
  EXPECT_EQ(rotationOf(3 * kQuarterTurn).s, -(1 << 30));
}
