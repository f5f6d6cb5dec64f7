// Crossing warp edges: instances on both sides, exact quarter turns, rotated frames, blocked edges.
#include <gtest/gtest.h>

#include "platon/physics/world.h"

using namespace platon::physics;

namespace {
constexpr int64_t kUnit = 65536;

// Two faces of a cube, 1000 units a side. Face 1's right edge is face 2's bottom edge, so moving
// right on face 1 turns into moving up on face 2 (a quarter turn).
struct CubeEdge {
  World world;
  CubeEdge(bool wallBehindEdge = false) {
    MapPart& a = world.createMapPart(1);
    MapPart& b = world.createMapPart(2);
    a.line({0, 0}, {1000, 0});
    a.warp({1000, 0}, {1000, 1000}, 2, {1000, 0}, {0, 0});
    b.warp({0, 0}, {1000, 0}, 1, {1000, 1000}, {1000, 0});
    if (wallBehindEdge) b.line({0, 5}, {1000, 5});
    a.initialize();
    b.initialize();
  }
};

Vec2 mapFace1ToFace2(Vec2 p) { return {1000 - p.y, p.x - 1000}; }
}  // namespace

TEST(Warp, CrossesACubeEdgeWithAnExactQuarterTurn) {
  CubeEdge cube;
  const EntityId ball = cube.world.createEntity(Convex::regular(8, 20));
  cube.world.insert(ball, 1, {900, 500}, 0);
  cube.world.setVelocity(ball, {5 * kUnit, 0});
  bool sawBoth = false;
  for (int frame = 0; frame < 60; ++frame) {
    cube.world.solve();
    ASSERT_EQ(cube.world.countOverlaps(), 0u);
    const Entity& e = cube.world.entity(ball);
    if (e.instances.size() == 2) {
      sawBoth = true;
      const Instance& a = *e.instanceIn(1);
      const Instance& b = *e.instanceIn(2);
      EXPECT_EQ(b.position, mapFace1ToFace2(a.position)) << "instances drifted apart";
    }
  }
  EXPECT_TRUE(sawBoth);
  const Entity& e = cube.world.entity(ball);
  ASSERT_EQ(e.instances.size(), 1u);
  EXPECT_EQ(e.instances[0].part, 2u);
  EXPECT_EQ(e.instances[0].position, mapFace1ToFace2({900 + 5 * 60, 500}));
  EXPECT_EQ(e.velocityQ16, (Vec2w{0, 5 * kUnit})) << "velocity turns with the frame";
  EXPECT_EQ(e.instances[0].frame, 0u);
}

TEST(Warp, GoingBackErasesTheCopyOnTheFarSide) {
  CubeEdge cube;
  const EntityId ball = cube.world.createEntity(Convex::regular(8, 20));
  cube.world.insert(ball, 1, {970, 500}, 0);
  cube.world.setVelocity(ball, {5 * kUnit, 0});
  for (int i = 0; i < 6; ++i) cube.world.solve();
  ASSERT_EQ(cube.world.entity(ball).instances.size(), 2u);
  cube.world.setVelocity(ball, {-5 * kUnit, 0});
  for (int i = 0; i < 20; ++i) cube.world.solve();
  const Entity& e = cube.world.entity(ball);
  ASSERT_EQ(e.instances.size(), 1u);
  EXPECT_EQ(e.instances[0].part, 1u);
  EXPECT_EQ(e.instances[0].position, (Vec2{900, 500}));  // 970 + 6 * 5 - 20 * 5
}

TEST(Warp, AWallJustBehindTheEdgeHoldsTheEntity) {
  CubeEdge cube(true);
  const EntityId ball = cube.world.createEntity(Convex::regular(8, 20));
  cube.world.insert(ball, 1, {900, 500}, 0);
  cube.world.setVelocity(ball, {5 * kUnit, 0});
  for (int i = 0; i < 60; ++i) {
    cube.world.solve();
    ASSERT_EQ(cube.world.countOverlaps(), 0u);
  }
  const Entity& e = cube.world.entity(ball);
  // The copy on face 2 would meet the wall at y = 5 once 5 units are across: the entity stops there.
  ASSERT_EQ(e.instances.size(), 2u);
  EXPECT_EQ(e.instanceIn(1)->position, (Vec2{1000 - 20 + 5, 500}));
}

// Two triangles of a tetrahedron net: the shared edge is turned by 120 degrees, so positions on the
// far side are rounded; the instances must still never overlap a line, and stay within a unit.
TEST(Warp, CrossesATriangleEdgeWithRoundedRotation) {
  World world;
  MapPart& a = world.createMapPart(10);
  MapPart& b = world.createMapPart(20);
  // Face A: triangle (0,0) (10000,0) (5000,8660). Edge (10000,0)->(5000,8660) is shared.
  a.line({0, 0}, {10000, 0});
  a.line({5000, 8660}, {0, 0});
  a.warp({10000, 0}, {5000, 8660}, 20, {0, 0}, {10000, 0});
  // Face B: same triangle shape in its own frame; its bottom edge is the shared one.
  b.warp({0, 0}, {10000, 0}, 10, {5000, 8660}, {10000, 0});
  b.line({10000, 0}, {5000, 8660});
  b.line({5000, 8660}, {0, 0});
  b.line({6000, 1000}, {6000, 3000});  // something to land against on face B
  a.initialize();
  b.initialize();
  const EntityId ball = world.createEntity(Convex::regular(10, 100));
  world.insert(ball, 10, {5000, 2000}, 0);
  world.setVelocity(ball, {40 * kUnit, 20 * kUnit});
  int straddling = 0;
  for (int frame = 0; frame < 400; ++frame) {
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u) << "frame " << frame;
    straddling += world.entity(ball).instances.size() > 1;
  }
  EXPECT_GT(straddling, 0);
  const Entity& e = world.entity(ball);
  ASSERT_EQ(e.instances.size(), 1u);
  EXPECT_EQ(e.instances[0].part, 20u);
}
