// The fixed-step clock: whole steps at any display rate, no drift over hours, bounded catch-up.
#include "platon/core/fixed_step.h"

#include <random>

#include <gtest/gtest.h>

using platon::core::FixedStep;

TEST(FixedStep, AnyDisplayRateGivesTheSameStepsPerSecond) {
  for (const int display : {30, 59, 60, 75, 144, 240, 1000}) {
    FixedStep clock(60);
    long steps = 0;
    const int64_t frame = 1'000'000'000 / display, rest = 1'000'000'000 % display;
    for (int f = 0; f < display * 3600; ++f) steps += clock.advance(frame);
    // One hour of frames of exactly 1/display s (the remainder nanoseconds fed once an hour).
    for (int s = 0; s < 3600; ++s) steps += clock.advance(rest);
    EXPECT_EQ(steps, 60 * 3600) << display << " Hz display";
    EXPECT_GE(clock.alpha(), 0.0);
    EXPECT_LT(clock.alpha(), 1.0);
  }
}

TEST(FixedStep, JitteryFramesNeverLoseOrGainTime) {
  std::mt19937_64 rng(7);
  FixedStep clock(120, 1000);
  int64_t total = 0;
  long steps = 0;
  for (int f = 0; f < 100000; ++f) {
    const int64_t dt = 1'000'000 + static_cast<int64_t>(rng() % 30'000'000);
    total += dt;
    steps += clock.advance(dt);
  }
  EXPECT_EQ(steps, total * 120 / 1'000'000'000);
  EXPECT_NEAR(clock.alpha(), static_cast<double>(total * 120 % 1'000'000'000) / 1e9, 1e-12);
}

TEST(FixedStep, ASlowFrameIsCappedAndCounted) {
  FixedStep clock(60, 4);
  EXPECT_EQ(clock.advance(1'000'000'000), 4);  // 60 steps due, 4 run
  EXPECT_EQ(clock.droppedSteps(), 56u);
  EXPECT_EQ(clock.advance(-5), 0);  // a clock that went backwards adds nothing
  EXPECT_THROW(FixedStep(0), std::invalid_argument);
  EXPECT_THROW(FixedStep(60, 0), std::invalid_argument);
}
