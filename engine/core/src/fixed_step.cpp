#include "platon/core/fixed_step.h"

#include <stdexcept>
#include <string>

namespace platon::core {
namespace {
constexpr int64_t kSecond = 1'000'000'000;
}

FixedStep::FixedStep(int hz, int maxSteps) : hz_(hz), maxSteps_(maxSteps) {
  if (hz < 1 || hz > 10000) throw std::invalid_argument("FixedStep: hz must be 1..10000, got " + std::to_string(hz));
  if (maxSteps < 1) throw std::invalid_argument("FixedStep: maxSteps must be at least 1");
}

int FixedStep::advance(int64_t nanoseconds) {
  if (nanoseconds < 0) nanoseconds = 0;                        // a clock that went back: no time passed
  if (nanoseconds > 10 * kSecond) nanoseconds = 10 * kSecond;  // a suspended process: cap the catch-up
  owed_ += nanoseconds * hz_;
  int64_t steps = owed_ / kSecond;
  owed_ -= steps * kSecond;
  if (steps > maxSteps_) {
    dropped_ += static_cast<uint64_t>(steps - maxSteps_);
    steps = maxSteps_;
  }
  return static_cast<int>(steps);
}

double FixedStep::alpha() const { return static_cast<double>(owed_) / static_cast<double>(kSecond); }

}  // namespace platon::core
