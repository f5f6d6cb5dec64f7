// Fixed simulation steps from a variable wall clock. The game advances in whole frames of 1/hz
// seconds whatever the display does, so it plays the same at 30 and 240 Hz and matches headless
// runs bit for bit; the renderer draws between the last two states at alpha().
//
// Time is kept exactly, in nanoseconds times hz, so no rounding accumulates over hours of play.
#pragma once
#include <cstdint>

namespace platon::core {

class FixedStep {
 public:
  // hz: simulation frames per second (1..10000). maxSteps: the most steps one advance() returns;
  // time beyond that is dropped (a slow machine slows the game down rather than spiralling).
  explicit FixedStep(int hz, int maxSteps = 8);

  // Adds `nanoseconds` of wall time; returns how many simulation steps are due now.
  int advance(int64_t nanoseconds);
  // How far the clock is into the next step, in [0, 1): where to draw between the last two states.
  double alpha() const;
  int hz() const { return hz_; }
  uint64_t droppedSteps() const { return dropped_; }

 private:
  int hz_;
  int maxSteps_;
  int64_t owed_ = 0;  // nanoseconds * hz not yet turned into steps; a step costs 10^9
  uint64_t dropped_ = 0;
};

}  // namespace platon::core
