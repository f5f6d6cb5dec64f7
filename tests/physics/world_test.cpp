// Behaviour of the world step: landing, resting, sliding, corners, wedges, limits.
#include "platon/physics/world.h"

#include <cmath>

#include <gtest/gtest.h>

using namespace platon::physics;

namespace {

constexpr int64_t kUnit = 65536;  // one unit per frame in Q16

struct Scene {
  World world;
  MapPart* part = nullptr;
  Scene() { part = &world.createMapPart(1); }
  EntityId drop(const Convex& shape, Vec2 at, Vec2w velocity = {}) {
    if (!part->initialized()) part->initialize();
    const EntityId id = world.createEntity(shape);
    world.insert(id, 1, at, 0);
    world.setVelocity(id, velocity);
    return id;
  }
  Vec2 pos(EntityId id) const { return world.entity(id).instance(0).position; }
  void run(int frames) {
    for (int i = 0; i < frames; ++i) {
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u) << "frame " << world.frame();
    }
  }
};

}  // namespace

TEST(World, FallsAndLandsExactlyOnFloor) {
  Scene s;
  s.part->line({-1000, 0}, {1000, 0});
  s.part->setGravity({0, -kUnit / 4});
  const EntityId box = s.drop(Convex::box(10, 10), {0, 500});
  s.run(200);
  EXPECT_EQ(s.pos(box), (Vec2{0, 10}));  // bottom edge exactly on the floor: no gap, no skin
  EXPECT_EQ(s.world.entity(box).velocity().y, 0);
}

TEST(World, RestsWithoutDriftForAMillionFrames) {
  Scene s;
  s.part->line({-1000, 0}, {1000, 0});
  s.part->line({200, 0}, {-200, 300});  // a slope nearby, not touched
  s.part->setGravity({0, -kUnit / 3});
  const EntityId box = s.drop(Convex::box(10, 10), {0, 10});
  for (int i = 0; i < 1000000; ++i) s.world.solve();
  EXPECT_EQ(s.pos(box), (Vec2{0, 10}));
  EXPECT_EQ(s.world.countOverlaps(), 0u);
}

TEST(World, SlidesAlongThousandCollinearSegmentsWithoutStopping) {
  Scene s;
  for (int i = 0; i < 1000; ++i) s.part->line({i * 16, 0}, {(i + 1) * 16, 0});
  s.part->setGravity({0, -kUnit});
  const EntityId box = s.drop(Convex::box(8, 8), {8, 8}, {3 * kUnit, 0});
  for (int frame = 1; frame <= 5000; ++frame) {
    s.world.solve();
    ASSERT_EQ(s.pos(box), (Vec2{8 + 3 * frame, 8})) << "stopped at frame " << frame;
  }
}

TEST(World, StopsInCornerAndStays) {
  Scene s;
  s.part->line({-100, 0}, {100, 0});
  s.part->line({100, 0}, {100, 200});
  s.part->setGravity({0, -kUnit / 2});
  const EntityId box = s.drop(Convex::box(10, 10), {0, 50}, {7 * kUnit, 0});
  s.run(300);
  EXPECT_EQ(s.pos(box), (Vec2{90, 10}));
}

TEST(World, SlidesDownSlopeAndNeverSinks) {
  Scene s;
  s.part->line({-2000, 1000}, {2000, -1000});  // slope 1:2
  s.part->line({-3000, -1000}, {3000, -1000});
  s.part->setGravity({0, -kUnit / 2});
  const EntityId ball = s.drop(Convex::regular(12, 20), {-1000, 600});
  Vec2 last = s.pos(ball);
  int stuck = 0;
  for (int i = 0; i < 400; ++i) {
    s.run(1);
    const Vec2 p = s.pos(ball);
    if (p == last && p.y > -900) ++stuck;
    last = p;
  }
  EXPECT_GT(last.x, -1000);  // it went down the slope
  EXPECT_LE(stuck, 2);
}

// A wedge narrowing to a very small angle: the body settles, then never moves or sinks again.
TEST(World, AcuteWedgesHoldStill) {
  for (const int spread : {400, 100, 20, 5, 1}) {
    Scene s;
    s.part->line({-spread * 20, 80000}, {0, 0});  // half-angle down to atan(1/4000), 0.014 degrees
    s.part->line({0, 0}, {spread * 20, 80000});
    s.part->setGravity({0, -kUnit});
    const EntityId ball = s.drop(Convex::regular(8, 6), {0, 60000});
    s.run(1500);
    const Vec2 rest = s.pos(ball);
    EXPECT_LT(rest.y, 60000) << "it fell into the wedge";
    for (int i = 0; i < 200; ++i) {
      s.run(1);
      ASSERT_EQ(s.pos(ball), rest) << "jitter in wedge with spread " << spread;
    }
  }
}

TEST(World, TJunctionsAndDuplicateLinesHold) {
  Scene s;
  s.part->line({-500, 0}, {500, 0});
  s.part->line({-500, 0}, {500, 0});  // duplicate
  s.part->line({-200, 0}, {300, 0});  // overlapping piece
  s.part->line({0, 0}, {0, -300});    // T-junction below the floor
  s.part->line({100, 0}, {100, 60});  // T-junction above: a post
  s.part->setGravity({0, -kUnit});
  const EntityId box = s.drop(Convex::box(10, 10), {-100, 100}, {5 * kUnit, 0});
  s.run(200);
  EXPECT_EQ(s.pos(box), (Vec2{90, 10}));
}

TEST(World, NearParallelApproachTouchesWithoutCrossing) {
  Scene s;
  s.part->line({-1000000, 0}, {1000000, 1});  // rises one unit over two million
  const EntityId box = s.drop(Convex::box(10, 10), {-900000, 20}, {1000 * kUnit, -kUnit / 64});
  s.run(1800);
  EXPECT_GT(s.pos(box).x, 0);
}

TEST(World, MaximumLengthMovesStopAtTheFarWall) {
  Scene s;
  s.part->line({kCoordLimit - 5, -100}, {kCoordLimit - 5, 100});
  const EntityId box = s.drop(Convex::box(4, 4), {-kCoordLimit + 10, 0}, {int64_t{kMaxMove} * kUnit, 0});
  s.run(3);
  EXPECT_EQ(s.pos(box), (Vec2{kCoordLimit - 9, 0}));
}

TEST(World, CoordinateRangeEdgeActsAsAWall) {
  Scene s;
  s.part->line({0, 0}, {1, 1});
  const EntityId box = s.drop(Convex::box(4, 4), {kCoordLimit - 100, kCoordLimit - 100}, {50 * kUnit, 70 * kUnit});
  s.run(10);
  EXPECT_EQ(s.pos(box), (Vec2{kCoordLimit - 4, kCoordLimit - 4}));
}

TEST(World, ExactlyTouchingStartsAreAllowed) {
  Scene s;
  s.part->line({-100, 0}, {100, 0});
  s.part->line({10, 0}, {10, 50});
  const EntityId box = s.drop(Convex::box(10, 10), {0, 10});  // touches floor and wall
  EXPECT_EQ(s.world.countOverlaps(), 0u);
  s.world.setVelocity(box, {0, 4 * kUnit});  // leaving along the wall is free
  s.run(5);
  EXPECT_EQ(s.pos(box), (Vec2{0, 30}));
}

TEST(World, OneUnitMovesAreExact) {
  Scene s;
  s.part->line({-100, 0}, {100, 0});
  const EntityId box = s.drop(Convex::box(10, 10), {0, 12}, {0, -kUnit});
  s.run(1);
  EXPECT_EQ(s.pos(box), (Vec2{0, 11}));
  s.run(1);
  EXPECT_EQ(s.pos(box), (Vec2{0, 10}));
  s.run(1);
  EXPECT_EQ(s.pos(box), (Vec2{0, 10}));
}

// The motion depends on the lines, not on how the grid happens to index them: far-away lines
// change every cell boundary, yet the entity moves exactly as before.
TEST(World, MotionDoesNotDependOnTheGrid) {
  auto run = [](int farLines) {
    Scene s;
    for (int i = 0; i < 60; ++i) s.part->line({i * 50, (i % 3) * 7}, {(i + 1) * 50, ((i + 1) % 3) * 7});
    for (int i = 0; i < 12; ++i) s.part->line({200 + i * 230, 90}, {300 + i * 230, 90 + (i % 2) * 30});
    for (int i = 0; i < farLines; ++i) {
      const int32_t x = 100000 + static_cast<int32_t>((int64_t{i} * 7919) % 50000);
      const int32_t y = 100000 + static_cast<int32_t>((int64_t{i} * 104729) % 50000);
      s.part->line({x, y}, {x + 40, y + 13});
    }
    s.part->setGravity({0, -kUnit / 2});
    const EntityId ball = s.drop(Convex::regular(8, 12), {40, 60}, {5 * kUnit, 0});
    std::vector<Vec2> path;
    for (int f = 0; f < 1500; ++f) {
      if (f % 90 == 0) s.world.setVelocity(ball, {(f / 90) % 2 ? -5 * kUnit : 5 * kUnit, 9 * kUnit});
      s.world.solve();
      path.push_back(s.pos(ball));
    }
    return path;
  };
  EXPECT_EQ(run(0), run(20000));
}

// Balls dropped exactly onto the peaks of a zigzag meet two lines at the same instant; which one
// they slide off is decided by a fixed rule, not by the grid.
TEST(World, TiesBetweenLinesAreBrokenTheSameWayOnAnyGrid) {
  auto run = [](int farLines) {
    Scene s;
    for (int i = 0; i < 40; ++i) s.part->line({i * 100, (i % 2) * 30}, {(i + 1) * 100, ((i + 1) % 2) * 30});
    for (int i = 0; i < farLines; ++i) {
      const int32_t x = -300000 + static_cast<int32_t>((int64_t{i} * 7919) % 600000);
      const int32_t y = 50000 + static_cast<int32_t>((int64_t{i} * 104729) % 50000);
      s.part->line({x, y}, {x + 40, y + 13});
    }
    s.part->setGravity({0, -kUnit});
    std::vector<EntityId> balls;
    for (int i = 1; i < 40; i += 2) balls.push_back(s.drop(Convex::regular(8, 12), {i * 100, 200}));
    for (int f = 0; f < 300; ++f) s.world.solve();
    std::vector<Vec2> out;
    for (const EntityId b : balls) out.push_back(s.pos(b));
    return out;
  };
  const std::vector<Vec2> plain = run(0);
  for (const int far : {1000, 5000, 30000}) EXPECT_EQ(plain, run(far)) << far << " far lines";
}

// Free flight is the exact parabola at every frame (the frame moves by the average of its start and
// end velocities), to within the unit rounding.
TEST(World, FreeFlightFollowsTheExactParabola) {
  Scene s;
  s.part->line({-1000000, -1000000}, {1000000, -1000000});
  const int64_t g = 11429;  // 9.81 m/s^2 at 64 units per metre and 60 Hz, in Q16
  s.part->setGravity({0, -g});
  const EntityId ball = s.drop(Convex::regular(8, 16), {0, 0}, {5 * kUnit, 3 * kUnit});
  for (int n = 1; n <= 600; ++n) {
    s.world.solve();
    // y(n) = vy n - g n^2 / 2, in Q16, floored by the whole-unit position.
    const int64_t exactQ16 = 3 * kUnit * n - g * n * n / 2;
    const int64_t y = s.pos(ball).y;
    ASSERT_LE(std::abs(y * kUnit - exactQ16), kUnit) << "frame " << n;
    ASSERT_EQ(s.pos(ball).x, 5 * n);
  }
}

// Sliding down a frictionless slope: the distance travelled matches s = g sin(a) t^2 / 2 to within
// a unit or two, with no drift from the per-frame rounding along the line.
TEST(World, SlidesDownASlopeAsFarAsTheAnalyticAnswer) {
  Scene s;
  s.part->line({-1008, 178}, {2017, -356});  // 10 degrees
  s.part->setGravity({0, -11429});
  const EntityId box = s.drop(Convex::box(16, 16), {16, 17});
  s.run(120);
  const double dx = s.pos(box).x - 16, dy = s.pos(box).y - 17;
  const double travelled = std::hypot(dx, dy);
  const double g = 11429.0 / 65536.0;  // units per frame^2
  const double exact = 0.5 * g * std::sin(10.0 * 3.14159265358979 / 180.0) * 120 * 120;
  EXPECT_NEAR(travelled, exact, 2.0);
}

// Sliding along a sloped line turns a velocity so one component could exceed the largest move;
// the world keeps every velocity one that setVelocity accepts.
TEST(World, VelocitiesStayWithinTheLargestMoveAfterSlides) {
  Scene s;
  s.part->line({-1066800000, -616000000}, {1066800000, 616000000});  // 30 degrees
  const int64_t limit = int64_t{kMaxMove} << 16;
  const EntityId box = s.drop(Convex::box(100, 100), {1000000000, 577428000}, {-limit, -limit});
  s.world.setGravityEnabled(box, false);
  s.run(1);
  const Vec2w v = s.world.entity(box).velocity();
  EXPECT_LE(std::max(std::abs(v.x), std::abs(v.y)), limit);
  EXPECT_NO_THROW(s.world.setVelocity(box, v));
}
