// A deliberately forbidden arrow: code built with the stage module's allowed dependencies
// (physics) that calls into core. The architecture test builds this target and expects the link
// to fail with an undefined reference; it is never part of a normal build.
#include "platon/stage/stage.h"

namespace platon::core {
class FixedStep {
 public:
  explicit FixedStep(int hz, int maxSteps);
};
}  // namespace platon::core

int main() {
  platon::core::FixedStep clock(60, 8);  // stage -> core: not an allowed arrow
  return 0;
}
