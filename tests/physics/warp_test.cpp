// Crossing warp edges: instances on both sides, exact quarter turns, rotated frames, blocked edges.
#include <cmath>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/si_units.h"

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
    const EntityView e = cube.world.entity(ball);
    if (e.instanceCount() == 2) {
      sawBoth = true;
      const InstanceView a = *e.instanceIn(1);
      const InstanceView b = *e.instanceIn(2);
      EXPECT_EQ(b.position, mapFace1ToFace2(a.position)) << "instances drifted apart";
    }
  }
  EXPECT_TRUE(sawBoth);
  const EntityView e = cube.world.entity(ball);
  ASSERT_EQ(e.instanceCount(), 1u);
  EXPECT_EQ(e.instance(0).part, 2u);
  EXPECT_EQ(e.instance(0).position, mapFace1ToFace2({900 + 5 * 60, 500}));
  EXPECT_EQ(e.velocity(), (Vec2w{0, 5 * kUnit})) << "velocity turns with the frame";
  EXPECT_EQ(e.instance(0).frame, 0u);
}

TEST(Warp, GoingBackErasesTheCopyOnTheFarSide) {
  CubeEdge cube;
  const EntityId ball = cube.world.createEntity(Convex::regular(8, 20));
  cube.world.insert(ball, 1, {970, 500}, 0);
  cube.world.setVelocity(ball, {5 * kUnit, 0});
  for (int i = 0; i < 6; ++i) cube.world.solve();
  ASSERT_EQ(cube.world.entity(ball).instanceCount(), 2u);
  cube.world.setVelocity(ball, {-5 * kUnit, 0});
  for (int i = 0; i < 20; ++i) cube.world.solve();
  const EntityView e = cube.world.entity(ball);
  ASSERT_EQ(e.instanceCount(), 1u);
  EXPECT_EQ(e.instance(0).part, 1u);
  EXPECT_EQ(e.instance(0).position, (Vec2{900, 500}));  // 970 + 6 * 5 - 20 * 5
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
  const EntityView e = cube.world.entity(ball);
  // The copy on face 2 would meet the wall at y = 5 once 5 units are across: the entity stops there.
  ASSERT_EQ(e.instanceCount(), 2u);
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
    straddling += world.entity(ball).instanceCount() > 1;
  }
  EXPECT_GT(straddling, 0);
  const EntityView e = world.entity(ball);
  ASSERT_EQ(e.instanceCount(), 1u);
  EXPECT_EQ(e.instance(0).part, 20u);
}

// Edges at any angle, including the dodecahedron's 72 (+180) degrees: random walls on both faces,
// entities thrown across; no overlap on any frame, and the copies stay within two units of the
// exactly mapped position (apart from the few held back by a wall).
TEST(Warp, EdgesAtAnyAngleKeepTheInvariant) {
  int crossings = 0, copyFrames = 0, lagging = 0;
  for (const int64_t degrees : {72 + 180, 120, 144, 90, 37, 250}) {
    for (uint64_t seed = 0; seed < 6; ++seed) {
      std::mt19937_64 rng(seed * 1000 + static_cast<uint64_t>(degrees));
      World world;
      MapPart& a = world.createMapPart(1);
      MapPart& b = world.createMapPart(2);
      // Face A: the square [0,6000]^2, right edge shared. Face B: the same edge turned by `degrees`
      // about the origin; B's face lies right of t0 -> t1.
      const Rotation r = rotationOf(angleFromDegrees(degrees));
      auto turn = [&](Vec2 p) {
        const Vec2w q = rotateWide(r, wide(p));
        return Vec2{static_cast<int32_t>(q.x), static_cast<int32_t>(q.y)};
      };
      const Vec2 t0 = turn({6000, 0}), t1 = turn({6000, 6000});
      a.line({0, 0}, {6000, 0});
      a.line({6000, 6000}, {0, 6000});
      a.line({0, 6000}, {0, 0});
      a.warp({6000, 0}, {6000, 6000}, 2, t0, t1);
      b.warp(t1, t0, 1, {6000, 6000}, {6000, 0});
      // Face B: the mirror image of A across the shared edge, in B's turned frame.
      const Vec2 far0 = turn({12000, 0}), far1 = turn({12000, 6000});
      b.line(t0, far0);
      b.line(far0, far1);
      b.line(far1, t1);
      for (int i = 0; i < 12; ++i) {
        const Vec2 p{6300 + static_cast<int32_t>(rng() % 5000), 300 + static_cast<int32_t>(rng() % 5400)};
        const Vec2 q{p.x + static_cast<int32_t>(rng() % 801) - 400, p.y + static_cast<int32_t>(rng() % 801) - 400};
        if (p != q) b.line(turn(p), turn(q));
        const Vec2 u{300 + static_cast<int32_t>(rng() % 5000), 300 + static_cast<int32_t>(rng() % 5400)};
        const Vec2 w{u.x + static_cast<int32_t>(rng() % 801) - 400, u.y + static_cast<int32_t>(rng() % 801) - 400};
        if (u != w) a.line(u, w);
      }
      a.setGravity({20000, 0});  // towards the shared edge
      b.setGravity(rotateWide(r, {-20000, 0}));
      a.initialize();
      b.initialize();
      std::vector<EntityId> ids;
      for (int i = 0; i < 5; ++i) {
        const EntityId id = world.createEntity(Convex::regular(3 + i, 40 + 20 * i));
        for (int tries = 0; tries < 50; ++tries) {
          try {
            world.insert(id, 1, {300 + static_cast<int32_t>(rng() % 5400), 300 + static_cast<int32_t>(rng() % 5400)},
                         static_cast<Angle>(rng()));
            world.setVelocity(id, {static_cast<int64_t>(rng() % (int64_t{80} * 65536)) - int64_t{20} * 65536,
                                   static_cast<int64_t>(rng() % (int64_t{60} * 65536)) - int64_t{30} * 65536});
            ids.push_back(id);
            break;
          } catch (const Error&) {}
        }
      }
      for (int f = 0; f < 400; ++f) {
        crossings += static_cast<int>(world.solve().warpsCreated);
        ASSERT_EQ(world.countOverlaps(), 0u) << degrees << " degrees, seed " << seed << ", frame " << f;
        for (const EntityId id : ids) {
          const EntityView e = world.entity(id);
          ASSERT_TRUE(e.inserted());
          for (size_t i = 1; i < e.instanceCount(); ++i) {
            // Where the copy belongs: the anchor's position turned exactly into the copy's face
            // (B's frame is A's turned by `degrees` about the origin). Rounding the edge's
            // endpoints allows about a unit; a copy held back by a wall on its side may lag more.
            const InstanceView anchor = e.instance(0), copy = e.instance(i);
            const Vec2w exact =
                anchor.part == 1 ? rotateWide(r, wide(anchor.position)) : rotateWideInverse(r, wide(anchor.position));
            const int64_t dx = copy.position.x - exact.x, dy = copy.position.y - exact.y;
            ++copyFrames;
            if (std::abs(dx) > 3 || std::abs(dy) > 3) ++lagging;
          }
        }
      }
    }
  }
  EXPECT_GT(crossings, 50);
  EXPECT_GT(copyFrames, 500);
  EXPECT_LE(lagging * 100, copyFrames) << lagging << " of " << copyFrames << " copy-frames off their ideal";
}

// Several worlds stepped on separate threads at once: no shared state, identical results.
TEST(Warp, WorldsRunInParallelThreads) {
  auto run = [](uint64_t* hash) {
    World world;
    MapPart& a = world.createMapPart(1);
    MapPart& b = world.createMapPart(2);
    a.line({0, 0}, {1000, 0});
    a.warp({1000, 0}, {1000, 1000}, 2, {1000, 0}, {0, 0});
    b.warp({0, 0}, {1000, 0}, 1, {1000, 1000}, {1000, 0});
    a.setGravity({0, -30000});
    b.setGravity({0, -30000});
    a.initialize();
    b.initialize();
    for (int i = 0; i < 8; ++i) {
      const EntityId id = world.createEntity(Convex::regular(6, 15));
      world.insert(id, 1, {100 + i * 100, 300}, 0);
      world.setVelocity(id, {int64_t{3 + i} * 65536, 0});
    }
    for (int f = 0; f < 5000; ++f) world.solve();
    *hash = world.stateHash();
  };
  uint64_t h[4];
  std::vector<std::thread> threads;
  for (uint64_t& slot : h) threads.emplace_back(run, &slot);
  for (std::thread& t : threads) t.join();
  uint64_t serial;
  run(&serial);
  for (const uint64_t x : h) EXPECT_EQ(x, serial);
}

// Walking along a floor that continues across a 120-degree or 252-degree edge (a box 0.5 m wide at
// 4 m/s, several resolutions and frame rates): the rounded copy on the far side must never snag on
// the first point of the continued floor.
TEST(Warp, WalkingAcrossTurnedEdgesOntoAContinuingFloor) {
  for (const int degrees : {120, 252, 90})
    for (const int upm : {64, 256, 1024, 4096})
      for (const double hz : {30.0, 60.0, 120.0, 240.0}) {
        const long double a = degrees * 3.14159265358979323846L / 180, c = std::cos(a), s = std::sin(a);
        auto units = [&](long double x, long double y) { return platon::testing::pointFromMetres(x, y, upm); };
        auto turned = [&](long double x, long double y) { return units(c * x - s * y, s * x + c * y); };
        World world;
        MapPart& faceA = world.createMapPart(1);
        MapPart& faceB = world.createMapPart(2);
        const Vec2 t0 = turned(8, 0), t1 = turned(8, 8);
        faceA.warp(units(8, 0), units(8, 8), 2, t0, t1);
        faceB.warp(t1, t0, 1, units(8, 8), units(8, 0));
        faceA.line(units(0, 0), units(8, 0));
        faceB.line(t0, turned(16, 0));  // the floor, continued on the far side
        const long double g = -9.81L * upm / (hz * hz) * 65536;
        faceA.setGravity({0, std::llround(g)});
        faceB.setGravity({std::llround(-s * g), std::llround(c * g)});
        faceA.initialize();
        faceB.initialize();
        const int32_t half = upm / 4;
        const EntityId box = world.createEntity(Convex::box(half, half));
        world.insert(box, 1, units(5, 0.25), 0);
        world.setVelocity(box, {platon::testing::q16FromSpeed(4.0, upm, hz), 0});  // no friction: it keeps going
        const int frames = static_cast<int>(2.5 * hz);
        for (int f = 0; f < frames; ++f) {
          world.solve();
          ASSERT_EQ(world.countOverlaps(), 0u)
              << degrees << " degrees, " << upm << " u/m, " << hz << " Hz, frame " << f;
        }
        const EntityView e = world.entity(box);
        EXPECT_EQ(e.instanceCount(), 1u) << degrees << " degrees, " << upm << " u/m, " << hz << " Hz";
        EXPECT_EQ(e.instance(0).part, 2u)
            << degrees << " degrees, " << upm << " u/m, " << hz << " Hz: stopped at the edge";
      }
}

// A warp edge that no whole-unit step can reach: a body driven along a tight sloped tunnel that
// crosses the edge (its clearance across the slope below 0.3 units), so every whole-unit step
// around the exact one at the moment its path meets the edge touches the floor or the ceiling. Such
// a warp is held like a wall for the frame (SolveReport::warpsHeld): the next sub-move meets it
// where the body stands and slides on, and a later frame crosses. Without that, the same sub-move
// came again from the same place until the frame's sub-moves ran out: the frame ended with the body
// where it was, no contact, its velocity saying it moves, and so did the next. Random families:
// slopes, shapes, tunnels, upright and leaning edges, speeds, across and back; no frame of a moving
// body ends where it began with no contact.
TEST(Warp, AnEdgeNoWholeStepReachesNeverFreezesTheBody) {
  std::mt19937_64 r(2026);
  auto between = [&](int lo, int hi) { return lo + static_cast<int>(r() % static_cast<uint64_t>(hi - lo + 1)); };
  int held = 0, crossings = 0, scenes = 0;
  for (int trial = 0; trial < 4000 && scenes < 400; ++trial) {
    World world;
    MapPart& a = world.createMapPart(1);
    MapPart& b = world.createMapPart(2);
    const int32_t dx = between(4, 24), dy = between(-12, 12);
    const double len = std::hypot(dx, dy);
    const Convex shape =
        r() % 2 ? Convex::box(between(6, 30), between(6, 30)) : Convex::regular(between(3, 9), between(8, 30));
    double lo = 1e18, hi = -1e18;  // the shape's extent across the slope
    for (const Vec2 v : shape.vertices()) {
      const double across = (double(dx) * v.y - double(dy) * v.x) / len;
      lo = std::min(lo, across), hi = std::max(hi, across);
    }
    const int32_t rise = static_cast<int32_t>(std::ceil((hi - lo) * len / dx));  // the tunnel's height, upright
    const double clearance = rise * dx / len - (hi - lo);                        // across the slope
    if (clearance > 0.3) continue;  // tight tunnels only: a unit's rounding touches a side
    const Vec2 edge{1000, 300};
    const int32_t k = 40;
    a.line({edge.x - k * dx, edge.y - k * dy}, edge);
    a.line({edge.x, edge.y + rise}, {edge.x - k * dx, edge.y - k * dy + rise});
    b.line(edge, {edge.x + k * dx, edge.y + k * dy});
    b.line({edge.x + k * dx, edge.y + k * dy + rise}, {edge.x, edge.y + rise});
    // The edge through `edge`, upright or leaning either way.
    const int32_t lean = between(-3, 3);
    const Vec2 e0{edge.x - lean * 700, edge.y - 2100}, e1{edge.x + lean * 700, edge.y + 2100};
    a.warp(e0, e1, 2, e0, e1);
    b.warp(e1, e0, 1, e1, e0);
    const int64_t g = between(2000, 30000);
    for (MapPart* p : {&a, &b}) {
      p->setGravity({std::llround(double(g) * dy / len), -std::llround(double(g) * dx / len)});
      p->initialize();
    }
    const EntityId body = world.createEntity(shape);
    bool placed = false;
    const int32_t back = between(40, 200);
    for (int32_t y = -40; y <= 80 && !placed; ++y) {
      const Vec2 at{edge.x - back, edge.y - static_cast<int32_t>(std::lround(double(back) * dy / dx)) + y};
      try {
        world.insert(body, 1, at, 0);
        placed = true;
      } catch (const Error&) {}
    }
    if (!placed) continue;
    ++scenes;
    const double speed = between(1, 8) + between(0, 1000) / 1000.0;
    MapPartId lastPart = 1;
    Vec2 last = world.entity(body).position();
    for (int frame = 0; frame < 240; ++frame) {
      const double way = frame < 120 ? 1 : -1;  // across, then back
      world.setVelocity(body,
                        {std::llround(way * speed * dx / len * kUnit), std::llround(way * speed * dy / len * kUnit)});
      const SolveReport report = world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u) << "trial " << trial << ", frame " << frame;
      held += static_cast<int>(report.warpsHeld);
      const EntityView e = world.entity(body);
      const bool moving = std::hypot(double(e.velocity().x), double(e.velocity().y)) >= 2.0 * kUnit;
      ASSERT_FALSE(moving && e.part() == lastPart && e.position() == last && e.contacts().empty())
          << "trial " << trial << ", frame " << frame
          << ": a moving body ended the frame where it was, with no contact";
      crossings += e.part() != lastPart;
      lastPart = e.part();
      last = e.position();
    }
  }
  EXPECT_GE(scenes, 300);
  EXPECT_GT(crossings, 100);
  EXPECT_GT(held, 20) << "the family rarely reached an edge no whole step could reach";
  RecordProperty("held", held);
  std::printf("%d tunnels, %d crossings, %d warps held\n", scenes, crossings, held);
}
