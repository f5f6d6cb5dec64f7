// Lines that change at run time (refreshPierce) and one-way lines, for level logic: doors and
// bridges that switches open and close, platforms you jump up through and stand on.
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;

namespace {

using platon::testing::between;
using platon::testing::randomConvex;
using platon::testing::Turn;

constexpr int64_t kUnit = 65536;
constexpr uint32_t kDoor = 7;

// Lines tagged kDoor pierce while the door is open; begin and end events are counted per line.
struct DoorRules : Rules {
  bool open = false;
  int begins = 0, ends = 0;
  bool pierce(EntityId e, const LineRef& line) override {
    return (line.tag == kDoor && open) || Rules::pierce(e, line);
  }
  void beginContact(const Contact& c) override { begins += c.line.tag == kDoor; }
  void endContact(const Contact& c) override { ends += c.line.tag == kDoor; }
};

}  // namespace

// A door across a corridor: shut, it stops the body; opened, the body walks through; the door is
// shut again while the body is half way through: it stays passable for that body until the body is
// clear of it, begin and end stay paired, and from then on it holds again.
TEST(Toggles, ADoorShutOnABodyHalfThroughWaitsUntilItIsClear) {
  World world;
  DoorRules rules;
  world.setRules(&rules);
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 0}, {1000, 0});
  part.line({0, 0}, {0, 200}, kDoor);
  part.setGravity({0, -kUnit / 2});
  part.initialize();
  const EntityId box = world.createEntity(Convex::box(20, 20));
  world.insert(box, 1, {-100, 20}, 0);
  for (int f = 0; f < 60; ++f) {
    world.setVelocity(box, {2 * kUnit, world.entity(box).velocity().y});
    world.solve();
  }
  EXPECT_EQ(world.entity(box).position(), (Vec2{-20, 20})) << "the shut door holds";
  rules.open = true;
  world.refreshPierce(kDoor);
  for (int f = 0; f < 10; ++f) {
    world.setVelocity(box, {2 * kUnit, world.entity(box).velocity().y});
    world.solve();
  }
  EXPECT_EQ(world.entity(box).position(), (Vec2{0, 20})) << "half through the open door";
  EXPECT_EQ(rules.begins, 1);
  rules.open = false;  // shut it on the body
  world.refreshPierce(kDoor);
  for (int f = 0; f < 40; ++f) {
    world.setVelocity(box, {2 * kUnit, world.entity(box).velocity().y});
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
  EXPECT_EQ(world.entity(box).position(), (Vec2{80, 20})) << "it finished going through";
  EXPECT_EQ(rules.ends, 1) << "begin and end paired";
  // Back the other way: the door holds again.
  for (int f = 0; f < 80; ++f) {
    world.setVelocity(box, {-2 * kUnit, world.entity(box).velocity().y});
    world.solve();
  }
  EXPECT_EQ(world.entity(box).position(), (Vec2{20, 20}));
  EXPECT_EQ(rules.begins, 1);
}

// A bridge that vanishes under a body standing on it lets it fall; one that appears under a falling
// body catches it only where it is clear of it.
TEST(Toggles, BridgesAppearAndVanishUnderBodies) {
  World world;
  DoorRules rules;  // tagged lines pierce while "open": here, while the bridge is gone
  world.setRules(&rules);
  MapPart& part = world.createMapPart(1);
  part.line({-1000, -500}, {1000, -500});
  part.line({-200, 0}, {200, 0}, kDoor);
  part.setGravity({0, -kUnit / 2});
  part.initialize();
  const EntityId box = world.createEntity(Convex::box(20, 20));
  world.insert(box, 1, {0, 20}, 0);
  for (int f = 0; f < 30; ++f) world.solve();
  EXPECT_EQ(world.entity(box).position(), (Vec2{0, 20}));
  rules.open = true;  // the bridge vanishes
  world.refreshPierce(kDoor);
  for (int f = 0; f < 30; ++f) world.solve();
  EXPECT_LT(world.entity(box).position().y, 0);
  rules.open = false;  // it comes back while the box is inside it or below it
  world.refreshPierce(kDoor);
  for (int f = 0; f < 200; ++f) {
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
  EXPECT_EQ(world.entity(box).position(), (Vec2{0, -480})) << "landed on the floor below";
  EXPECT_EQ(rules.begins, rules.ends);
}

// Random doors switched at random frames under random bodies: never an overlap with a line that is
// solid for the body, and every begin has its end by the time the body is clear.
TEST(Toggles, RandomSwitchingNeverTrapsABodyInALine) {
  std::mt19937_64 rng(51);
  for (int trial = 0; trial < 40; ++trial) {
    World world;
    DoorRules rules;
    world.setRules(&rules);
    MapPart& part = world.createMapPart(1);
    part.line({-3000, -3000}, {3000, -3000});
    part.line({-3000, -3000}, {-3000, 3000});
    part.line({3000, -3000}, {3000, 3000});
    for (int i = 0; i < 30; ++i) {
      const Vec2 a{between(rng, -2800, 2800), between(rng, -2800, 2800)};
      const Vec2 b{a.x + between(rng, -600, 600), a.y + between(rng, -300, 300)};
      if (a != b) part.line(a, b, i % 2 ? kDoor : 0);
    }
    part.setGravity({between(rng, -8000, 8000), -between(rng, 2000, 40000)});
    part.initialize();
    std::vector<EntityId> ids;
    for (int i = 0; i < 8; ++i) {
      const EntityId id = world.createEntity(randomConvex(rng, between(rng, 5, 40), Turn::Upright));
      for (int tries = 0; tries < 50; ++tries) {
        try {
          world.insert(id, 1, {between(rng, -2700, 2700), between(rng, -2700, 2700)}, 0);
          world.setVelocity(id, {between(rng, -10, 10) * kUnit, between(rng, -10, 10) * kUnit});
          ids.push_back(id);
          break;
        } catch (const Error&) {}
      }
    }
    for (int f = 0; f < 1500; ++f) {
      if (rng() % 25 == 0) {
        rules.open = !rules.open;
        world.refreshPierce(kDoor);
      }
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u) << "trial " << trial << ", frame " << f;
    }
    // Open everything, let them fall through to the floor: every begin then has its end.
    rules.open = true;
    world.refreshPierce(kDoor);
    for (int f = 0; f < 3000; ++f) world.solve();
    int overlapping = 0;
    for (const EntityId id : ids)
      for (const InstanceView inst : world.entity(id).instances())
        for (const Segment& s : world.mapPart(1).segments()) {
          std::vector<Vec2> verts;
          for (const Vec2 v : inst.shape) verts.push_back({inst.position.x + v.x, inst.position.y + v.y});
          overlapping += overlapsInterior(verts, s);
        }
    EXPECT_EQ(rules.begins - rules.ends, overlapping) << "trial " << trial << ": an unpaired begin";
  }
}

// One-way platforms: jumped at from below, at any angle and speed, a body of any shape goes up
// through and lands on top without ever sinking through (on a tilted platform it then slides off
// the lower end, frictionless); on a flat one it stands still, and walking off the end it falls.
TEST(OneWay, JumpUpThroughAndLandOnTopForAnyShapeAndAngle) {
  std::mt19937_64 rng(53);
  int stood = 0, cases = 0;
  for (int trial = 0; trial < 200; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-5000, 0}, {5000, 0});
    const int32_t height = between(rng, 100, 400), half = between(rng, 150, 600);
    const int32_t tilt = trial % 2 ? 0 : between(rng, -half / 3, half / 3);  // up to about 18 degrees
    const Vec2 a{-half, height - tilt}, b{half, height + tilt};
    part.oneWay(a, b);
    const int64_t g = between(rng, 4000, kUnit);
    part.setGravity({0, -g});
    part.initialize();
    const EntityId body = world.createEntity(randomConvex(rng, between(rng, 4, 30), Turn::Upright));
    try {
      world.insert(body, 1, {between(rng, -half / 2, half / 2), 40}, 0);
    } catch (const Error&) {
      continue;
    }
    for (int f = 0; f < 100; ++f) world.solve();  // settle on the floor
    ++cases;
    // Jump hard enough to clear the platform: v^2 >= 2 g (height + size).
    const double need = std::sqrt(2.0 * static_cast<double>(g) / kUnit * (height + std::abs(tilt) + 80));
    // Sideways too on a tilted one; straight up onto a flat one, where a frictionless body that
    // lands moving sideways slides on and off the end.
    const int64_t sideways = between(rng, -2, 2) * kUnit / 4;
    world.setVelocity(body,
                      {tilt == 0 ? 0 : sideways, static_cast<int64_t>((need * between(rng, 11, 20) / 10) * kUnit)});
    bool above = false;
    int f = 0;
    for (; f < 3000; ++f) {
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u);
      const Vec2 p = world.entity(body).position();
      const bool nowAbove = cross(b - a, p - a) > 0 && p.x > a.x && p.x < b.x;
      // Once wholly above, it may come down again only past an end (it is at most 30 units wide).
      if (above && cross(b - a, p - a) < 0) {
        ASSERT_TRUE(p.x < a.x + 30 || p.x > b.x - 30) << "trial " << trial << ": fell through at frame " << f;
      }
      if (nowAbove && p.y > height + std::abs(tilt) + 30) above = true;
      if (tilt == 0 && above && world.entity(body).velocity() == Vec2w{} && f > 300) break;
    }
    ASSERT_TRUE(above) << "trial " << trial << ": never got up through";
    if (tilt != 0) continue;
    ++stood;
    const Vec2 rest = world.entity(body).position();
    EXPECT_GT(rest.y, height) << "trial " << trial;
    for (int still = 0; still < 20000; ++still) world.solve();
    EXPECT_EQ(world.entity(body).position(), rest) << "trial " << trial;
    for (int walk = 0; walk < 1000; ++walk) {  // walk off the end: it falls to the floor
      world.setVelocity(body, {4 * kUnit, world.entity(body).velocity().y});
      world.solve();
    }
    EXPECT_LT(world.entity(body).position().y, height / 2) << "trial " << trial << ": did not fall off the end";
  }
  EXPECT_GT(cases, 150);
  EXPECT_GT(stood, 70);
}

// Dropped from above at any speed onto the middle of a long one-way line (slightly tilted, no
// sideways push, so it cannot reach an end), a body never sinks into it or passes through it.
TEST(OneWay, NothingFallsThroughFromAbove) {
  std::mt19937_64 rng(57);
  for (int trial = 0; trial < 300; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    const Vec2 a{-20000, between(rng, -200, 200)}, b{20000, between(rng, -200, 200)};
    part.oneWay(a, b);
    part.setGravity({0, -between(rng, 4000, 3 * kUnit)});
    part.initialize();
    const EntityId body = world.createEntity(randomConvex(rng, between(rng, 3, 40), Turn::Upright));
    world.insert(body, 1, {between(rng, -500, 500), between(rng, 300, 3000)}, 0);
    world.setVelocity(body, {between(rng, -2, 2) * kUnit, -between(rng, 0, 300) * kUnit});
    for (int f = 0; f < 600; ++f) {
      world.solve();
      const InstanceView inst = world.entity(body).instance(0);
      std::vector<Vec2> verts;
      for (const Vec2 v : inst.shape) verts.push_back({inst.position.x + v.x, inst.position.y + v.y});
      ASSERT_FALSE(overlapsInterior(verts, {a, b})) << "trial " << trial << ", frame " << f << ": sank into it";
      ASSERT_GT(cross(b - a, inst.position - a), 0) << "trial " << trial << ", frame " << f << ": fell through";
    }
  }
}
