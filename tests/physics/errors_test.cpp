// Every misuse gets a clear error that names the bad value, and leaves the world unchanged.
#include <string>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/cube_faces.h"

using namespace platon::physics;

namespace {
// Runs f, expects Error whose message contains `needle`.
template <class F>
void expectError(F&& f, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one mentioning '" << needle << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << "message was: " << e.what();
  }
}
}  // namespace

TEST(Errors, ConvexShapesAreValidated) {
  expectError([] { Convex({{0, 0}, {1, 0}}); }, "at least 3 vertices");
  expectError([] { Convex({{0, 0}, {0, 10}, {10, 0}}); }, "turns clockwise");
  expectError([] { Convex({{0, 0}, {10, 0}, {20, 0}, {10, 10}}); }, "vertex 1");  // collinear
  expectError([] { Convex({{0, 0}, {10, 0}, {10, 0}, {0, 10}}); }, "vertex 2 repeats vertex 1 (10, 0)");
  expectError([] { Convex({{0, 0}, {10, 0}, {5, 2}, {10, 10}, {0, 10}}); }, "vertex 2");  // reflex
  expectError([] { Convex({{0, 0}, {kShapeLimit + 1, 0}, {0, 10}}); }, "vertex 1");
  // A pentagram winds twice with only left turns: caught as non-convex.
  expectError([] { Convex({{0, 100}, {-59, -81}, {95, 31}, {-95, 31}, {59, -81}}); }, "not convex");
  std::vector<Vec2> many;
  for (int i = 0; i < 65; ++i) many.push_back({i, i * i});
  expectError([&] { Convex{many}; }, "limit is 64");
}

TEST(Errors, MapPartsCheckTheirLines) {
  World world;
  MapPart& part = world.createMapPart(3);
  expectError([&] { world.createMapPart(3); }, "map part 3 already exists");
  expectError([&] { part.line({5, 5}, {5, 5}); }, "zero length at (5, 5)");
  expectError([&] { part.line({0, 0}, {kCoordLimit + 1, 0}); }, "outside the coordinate range");
  expectError([&] { part.warp({0, 0}, {100, 0}, 9, {0, 0}, {50, 0}); }, "edge lengths differ");
  part.warp({0, 0}, {100, 0}, 9, {0, 0}, {100, 0});
  // Targets may be created after the part; the world checks them when it is next used.
  part.initialize();
  expectError([&] { world.solve(); }, "map part 3 warp 0: target map part 9 does not exist");
  const EntityId box = world.createEntity(Convex::box(5, 5));
  expectError([&] { world.insert(box, 3, {50, 50}, 0); }, "target map part 9 does not exist");
  MapPart& late = world.createMapPart(9);
  late.initialize();
  world.solve();  // the target exists now
  world.insert(box, 3, {50, 50}, 0);
  World other;
  MapPart& self = other.createMapPart(1);
  expectError([&] { self.warp({0, 0}, {100, 0}, 1, {0, 0}, {100, 0}); }, "cannot target its own part");
  EXPECT_TRUE(self.lines().empty());  // refused: nothing added
  MapPart& done = other.createMapPart(2);
  done.line({0, 0}, {10, 0});
  done.initialize();
  expectError([&] { done.line({0, 1}, {10, 1}); }, "after initialize()");
  expectError([&] { done.initialize(); }, "called twice");
  expectError([&] { other.mapPart(77); }, "map part 77 does not exist");
  expectError([&] { done.setGravity({0, int64_t{1} << 47}); }, "gravity");
}

TEST(Errors, InsertChecksPlacement) {
  World world;
  MapPart& open = world.createMapPart(1);
  open.line({-100, 0}, {100, 0});
  MapPart& later = world.createMapPart(2);
  open.initialize();
  const EntityId box = world.createEntity(Convex::box(10, 10));
  expectError([&] { world.insert(box, 2, {0, 0}, 0); }, "not initialized");
  expectError([&] { world.insert(box, 1, {0, 5}, 0); }, "would overlap solid line 0");
  EXPECT_FALSE(world.entity(box).inserted());
  expectError([&] { world.insert(box, 1, {kCoordLimit - 3, 50}, 0); }, "outside the coordinate range");
  world.insert(box, 1, {0, 10}, 0);
  expectError([&] { world.insert(box, 1, {0, 50}, 0); }, "already has an instance in map part 1");
  expectError([&] { world.erase(box, 2); }, "no instance in map part 2");
  later.initialize();
  expectError([&] { world.setVelocity(box, {int64_t{1} << 47, 0}); }, "exceeds the largest move");
}

// A cube's six faces joined edge to edge (2000 units a side), as the golden cube.
void buildCube(World& world) {
  platon::testing::addCubeFaces(world, 2000);
  for (int f = 0; f < 6; ++f) world.mapPart(static_cast<MapPartId>(f)).initialize();
}

// On a face, a body's middle is on it, or over an edge by at most the body's size (as while it
// crosses): farther out the first step would put it back by a corner, hundreds of units away
// (a body 55 units out was moved 368). The family: each face, each edge, bodies of several sizes,
// just inside the allowance and just past it; past it is refused and the world is unchanged.
TEST(Errors, InsertRefusesABodyOffItsFace) {
  World world;
  buildCube(world);
  const int32_t s = 2000;
  for (const int32_t half : {5, 20, 60}) {  // a box's half size: its reach is about 1.42 times it
    const int32_t reach = half * 1414 / 1000 + 1;
    for (MapPartId face = 0; face < 6; ++face)
      for (int edge = 0; edge < 4; ++edge) {
        // Out from the edge's middle by `out` units (the box's middle is its origin).
        auto at = [&](int32_t out) -> Vec2 {
          switch (edge) {
            case 0:
              return {s / 2, -out};
            case 1:
              return {s + out, s / 2};
            case 2:
              return {s / 2, s + out};
            default:
              return {-out, s / 2};
          }
        };
        const EntityId inside = world.createEntity(Convex::box(half, half));
        EXPECT_NO_THROW(world.insert(inside, face, at(reach), 0))
            << "face " << face << " edge " << edge << " half " << half;
        world.destroyEntity(inside);
        const EntityId far = world.createEntity(Convex::box(half, half));
        const uint64_t before = world.stateHash();
        expectError([&] { world.insert(far, face, at(reach + 10), 0); }, "units off the face");
        EXPECT_FALSE(world.entity(far).inserted());
        EXPECT_EQ(world.stateHash(), before) << "a refused insert changed the world";
        world.destroyEntity(far);
      }
  }
  // The case: a small body 55 units out.
  const EntityId small = world.createEntity(Convex::box(4, 4));
  expectError([&] { world.insert(small, 0, {1000, -55}, 0); }, "insert: the entity at (1000, -55) in map part 0");
  // A part that is no face (its warps close no loop) takes any point.
  MapPart& open = world.createMapPart(9);
  open.line({0, 0}, {100, 0});
  open.initialize();
  world.insert(small, 9, {50000, 50000}, 0);
  EXPECT_TRUE(world.entity(small).inserted());
}

TEST(Errors, StaleHandlesAreDetected) {
  World world;
  const EntityId a = world.createEntity(Convex::box(3, 3));
  world.destroyEntity(a);
  EXPECT_FALSE(world.valid(a));
  expectError([&] { world.entity(a); }, "does not exist");
  expectError([&] { world.destroyEntity(a); }, "does not exist");
  const EntityId b = world.createEntity(Convex::box(3, 3));  // reuses the slot
  EXPECT_EQ(b.index, a.index);
  EXPECT_NE(b.generation, a.generation);
  EXPECT_FALSE(world.valid(a));
  EXPECT_TRUE(world.valid(b));
}

TEST(Errors, ShapesTooSmallToRotateAreRefused) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-100, -50}, {100, -50});
  part.initialize();
  const EntityId sliver = world.createEntity(Convex({{0, 0}, {1, 1}, {0, 1}}));
  world.insert(sliver, 1, {0, 0}, 0);
  expectError([&] { world.rotate(sliver, angleFromDegrees(25)); }, "too small to rotate");
  EXPECT_EQ(world.entity(sliver).angle(), 0u);
}

// The shape constructors check their arguments before any arithmetic on them (negating INT32_MIN
// or rotating a radius past the shape range was undefined behaviour).
TEST(Errors, ShapeConstructorsCheckBeforeArithmetic) {
  expectError([] { Convex::box(INT32_MIN, 5); }, "box half-size (-2147483648, 5) is outside 1..2^29");
  expectError([] { Convex::box(5, INT32_MIN); }, "outside 1..2^29");
  expectError([] { Convex::box(0, 5); }, "outside 1..2^29");
  expectError([] { Convex::box(kShapeLimit + 1, 5); }, "outside 1..2^29");
  expectError([] { Convex::regular(8, INT32_MIN); }, "radius -2147483648 is outside 1..2^29");
  expectError([] { Convex::regular(8, INT32_MAX); }, "outside 1..2^29");
  expectError([] { Convex::regular(2, 10); }, "3..64 vertices, got 2");
  expectError([] { Convex::regular(65, 10); }, "3..64 vertices, got 65");
  EXPECT_EQ(Convex::box(kShapeLimit, kShapeLimit).size(), 4);
  EXPECT_EQ(Convex::regular(64, kShapeLimit).size(), 64);
}

// A rule that leaves a restitution that is no fraction gets an Error from solve() at the end of
// the frame (the contact slides as by default), whether the slide met the line or the rest test did.
TEST(Errors, ABadRestitutionIsReportedAndTheFrameFinishes) {
  struct BadBounce : Rules {
    Fraction restitution;
    void contact(const Contact&, ContactResponse& r) override { r.restitution = restitution; }
  };
  for (const Fraction bad : {Fraction{1, 0}, Fraction{-1, 2}, Fraction{3, -4}}) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-1000, 0}, {1000, 0});
    part.setGravity({0, -65536});
    part.initialize();
    BadBounce rules;
    rules.restitution = bad;
    world.setRules(&rules);
    const EntityId box = world.createEntity(Convex::box(10, 10));
    world.insert(box, 1, {0, 40}, 0);
    world.setVelocity(box, {0, int64_t{-50} * 65536});
    expectError([&] { world.solve(); }, "restitution");
    EXPECT_EQ(world.entity(box).instance(0).position, (Vec2{0, 10}));  // landed, slid: nothing bounced
    EXPECT_EQ(world.countOverlaps(), 0u);
  }
}

// Lines in bulk are all checked before any is added: one bad segment adds none, and the error
// names the index that line would have had.
TEST(Errors, BulkLinesAreCheckedBeforeAnyIsAdded) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({0, 0}, {10, 0});
  const std::vector<Segment> bad{{{0, 10}, {10, 10}}, {{5, 5}, {5, 5}}, {{0, 20}, {10, 20}}};
  expectError([&] { part.lines(bad); }, "line 2: zero length at (5, 5)");
  EXPECT_EQ(part.lines().size(), 1u);
  const std::vector<Segment> far{{{0, 10}, {int32_t{1} << 30, 10}}};
  expectError([&] { part.lines(far); }, "outside the coordinate range");
  EXPECT_EQ(part.lines().size(), 1u);
  EXPECT_EQ(part.lines(std::vector<Segment>{{{0, 10}, {10, 10}}, {{0, 20}, {10, 20}}}, 4), 1u);
  EXPECT_EQ(part.lines().size(), 3u);
  EXPECT_EQ(part.lines()[2].tag, 4u);
  part.initialize();
  expectError([&] { part.lines(std::vector<Segment>{{{0, 30}, {10, 30}}}); }, "after initialize");
}
