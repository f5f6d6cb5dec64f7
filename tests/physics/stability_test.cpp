// The stiff and extreme scenes (tests/scenes): Platon's outcome must be perfect on each, at the
// origin and pressed against both ends of the coordinate range.
#include <cmath>

#include <gtest/gtest.h>

#include "platon/physics/vec2.h"
#include "platon/testing/stability_scenes.h"

using namespace platon::testing::scenes;

namespace {
constexpr double kUnitsPerMetre = 1024;

void expectClean(const Scene& s, const Outcome& o, const std::string& where) {
  SCOPED_TRACE(s.name + " " + where);
  EXPECT_EQ(o.overlapFrames, 0) << "penetration";
  EXPECT_EQ(o.tunnelFrames, 0) << "tunnel";
  EXPECT_EQ(o.missedEvents, 0) << "missed trigger events";
  EXPECT_EQ(o.triggerBegins, s.expectedCrossings);
  EXPECT_EQ(o.triggerEnds, s.expectedCrossings);
  if (s.settleFrames >= 0) {
    EXPECT_EQ(o.drift, 0.0) << "drift at rest";
  }
  EXPECT_EQ(o.stuckFrames, 0) << "stuck";
  EXPECT_FALSE(o.missedTarget) << "ended at x = " << o.final.x << ", not " << s.targetX;
}
}  // namespace

class Stability : public ::testing::TestWithParam<std::string> {};

TEST_P(Stability, PlatonIsExactAtTheOriginAndAtBothRangeLimits) {
  for (const Scene& s : stabilityScenes()) {
    if (s.name != GetParam()) continue;
    expectClean(s, runPlaton(s, kUnitsPerMetre), "at the origin");
    if (s.platonOnly || s.frames > 100000) return;  // the long rest runs once
    const int64_t limit = platon::physics::kCoordLimit - extentUnits(s, kUnitsPerMetre);
    expectClean(s, runPlaton(s, kUnitsPerMetre, limit), "near +2^30");
    expectClean(s, runPlaton(s, kUnitsPerMetre, -limit), "near -2^30");
    return;
  }
  FAIL() << "no scene named " << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Scenes, Stability,
                         ::testing::Values("high-gravity", "max-speed", "thin-stick", "tiny-body", "slide-chain",
                                           "wedge-10.0deg", "wedge-1.0deg", "wedge-0.1deg", "star-hub",
                                           "dense-parallel", "spin-corridor", "fast-trigger", "warp-corner",
                                           "rest-1e6"),
                         [](const auto& param) {
                           std::string n = param.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(StabilityScenes, EverySceneIsCovered) { EXPECT_EQ(stabilityScenes().size(), 14u); }
