// A body that slides fast down a leaning wall into the floor at its foot (an obtuse crease, the
// wall leaning away) and then walks off along the floor. Found in a level: after such a slide the
// body could stop a fraction of a unit from both lines, where every rounded step toward the floor
// met the wall; the sub-move went again from the same place forever and the body froze, with no
// contact and its velocity growing. Over a family of lean angles, speeds, shapes and positions,
// the body must leave the crease when it walks away.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;
using platon::testing::between;

TEST(ObtuseCrease, ABodyThatSlidDownALeaningWallWalksAwayAlongTheFloor) {
  std::mt19937_64 rng(0x0b7c);
  int frozen = 0, trials = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    // The floor ends at the wall's foot; the wall leans away by 5 to 70 degrees from upright.
    const double lean = between(rng, 5, 70) * M_PI / 180;
    const Vec2 foot{between(rng, 2000, 6000), between(rng, 100, 900)};
    const Vec2 top{foot.x + static_cast<int32_t>(4000 * std::sin(lean)),
                   foot.y + static_cast<int32_t>(4000 * std::cos(lean))};
    part.line({foot.x - 5000, foot.y}, foot);
    part.line(foot, top);
    part.setGravity({0, -between(rng, 15000, 40000)});
    part.initialize();
    const Convex shape =
        trial % 2 ? Convex::regular(between(rng, 8, 24), between(rng, 40, 160))
                  : platon::testing::randomConvex(rng, between(rng, 40, 160), platon::testing::Turn::MaybeTurned);
    const EntityId body = world.createEntity(shape);
    // High on the wall's side, moving into it and down.
    const int32_t height = between(rng, 1500, 3000);
    const Vec2 start{foot.x + static_cast<int32_t>(height * std::tan(lean)) - 400, foot.y + height};
    try {
      world.insert(body, 1, start, 0);
    } catch (const Error&) {
      continue;  // the random shape does not fit there
    }
    ++trials;
    world.setVelocity(body, {int64_t{between(rng, 2, 20)} * 65536, -int64_t{between(rng, 10, 60)} * 65536});
    for (int f = 0; f < 400; ++f) {
      const Vec2w v = world.entity(body).velocity();
      world.setVelocity(body, {v.x + 65536 / 2, v.y});  // pressed toward the wall while it slides
      world.solve();
    }
    // At the foot now. Walk away along the floor.
    const Vec2 before = world.entity(body).position();
    for (int f = 0; f < 60; ++f) {
      world.setVelocity(body, {int64_t{-9} * 65536, world.entity(body).velocity().y});
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u);
    }
    const Vec2 after = world.entity(body).position();
    if (before.x - after.x < 300) {
      ++frozen;
      ADD_FAILURE() << "trial " << trial << ": lean " << lean * 180 / M_PI << " deg, from (" << before.x << ", "
                    << before.y << ") only to (" << after.x << ", " << after.y << ")";
    }
  }
  EXPECT_GT(trials, 800);
  EXPECT_EQ(frozen, 0);
}
