// Rules: pierceable lines and their events, solid contacts and their responses, errors thrown from
// callbacks, structural changes refused during solve.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;

namespace {
constexpr int64_t kUnit = 65536;
constexpr uint32_t kTriggerTag = 7;

struct Recorder : Rules {
  std::vector<std::string> log;
  bool pierce(EntityId, const LineRef& line) override { return line.kind == LineKind::Warp || line.tag == kTriggerTag; }
  void beginContact(const Contact& c) override { log.push_back("begin " + std::to_string(c.line.index)); }
  void overContact(const Contact& c) override { log.push_back("over " + std::to_string(c.line.index)); }
  void endContact(const Contact& c) override { log.push_back("end " + std::to_string(c.line.index)); }
  void contact(const Contact& c, ContactResponse&) override {
    log.push_back("contact " + std::to_string(c.line.index));
  }
  void touchContact(const Contact& c) override { log.push_back("touch " + std::to_string(c.line.index)); }
};
}  // namespace

TEST(Rules, FastCrossingOfATriggerStillBeginsAndEnds) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({500, -100}, {500, 100}, kTriggerTag);  // a thin trigger line
  part.initialize();
  Recorder rules;
  world.setRules(&rules);
  const EntityId box = world.createEntity(Convex::box(5, 5));
  world.insert(box, 1, {0, 0}, 0);
  world.setVelocity(box, {2000 * kUnit, 0});  // crosses the line inside one frame
  world.solve();
  EXPECT_EQ(world.entity(box).instance(0).position, (Vec2{2000, 0}));
  EXPECT_EQ(rules.log, (std::vector<std::string>{"begin 0", "end 0"}));
}

TEST(Rules, OverContactEveryFrameWhileInside) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({10, -100}, {10, 100}, kTriggerTag);
  part.initialize();
  Recorder rules;
  world.setRules(&rules);
  const EntityId box = world.createEntity(Convex::box(5, 5));
  world.insert(box, 1, {0, 0}, 0);
  world.setVelocity(box, {2 * kUnit, 0});
  for (int i = 0; i < 12; ++i) world.solve();
  // The right edge passes x = 10 on frame 3, the left edge on frame 8: overlapping after frames 3-7.
  const std::vector<std::string> expected = {"begin 0", "over 0", "over 0", "over 0", "over 0", "over 0", "end 0"};
  EXPECT_EQ(rules.log, expected);
}

TEST(Rules, EventsOnOneFrameComeInTheOrderTheyHappen) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({300, -100}, {300, 100}, kTriggerTag);
  part.line({100, -100}, {100, 100}, kTriggerTag);
  part.line({200, -100}, {200, 100}, kTriggerTag);
  part.initialize();
  Recorder rules;
  world.setRules(&rules);
  const EntityId box = world.createEntity(Convex::box(5, 5));
  world.insert(box, 1, {0, 0}, 0);
  world.setVelocity(box, {400 * kUnit, 0});
  world.solve();
  EXPECT_EQ(rules.log, (std::vector<std::string>{"begin 1", "end 1", "begin 2", "end 2", "begin 0", "end 0"}));
}

TEST(Rules, SolidContactReportsLineNormalPointAndFraction) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-100, 0}, {100, 0}, 3);
  part.initialize();
  struct Probe : Rules {
    std::vector<Contact> contacts;
    void contact(const Contact& c, ContactResponse&) override { contacts.push_back(c); }
  } probe;
  world.setRules(&probe);
  const EntityId box = world.createEntity(Convex::box(10, 10));
  world.insert(box, 1, {0, 30}, 0);
  world.setVelocity(box, {0, -40 * kUnit});
  world.solve();
  ASSERT_EQ(probe.contacts.size(), 1u);
  const Contact& c = probe.contacts[0];
  EXPECT_EQ(c.line.index, 0u);
  EXPECT_EQ(c.line.tag, 3u);
  EXPECT_EQ(c.fraction, (Fraction{1, 2}));
  EXPECT_EQ(c.normal.x, 0);
  EXPECT_GT(c.normal.y, 0);
  ASSERT_EQ(c.points.count, 2);  // the bottom edge lies along the floor
  EXPECT_EQ(c.points.points[0], (Vec2{-10, 0}));
  EXPECT_EQ(c.points.points[1], (Vec2{10, 0}));
}

TEST(Rules, ContactResponseCanStopTheSlideAndKeepVelocity) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 0}, {1000, 0});
  part.initialize();
  struct Sticky : Rules {
    void contact(const Contact&, ContactResponse& r) override {
      r.slide = false;
      r.removeNormalVelocity = false;
    }
  } sticky;
  world.setRules(&sticky);
  const EntityId box = world.createEntity(Convex::box(10, 10));
  world.insert(box, 1, {0, 20}, 0);
  world.setVelocity(box, {20 * kUnit, -20 * kUnit});
  world.solve();
  EXPECT_EQ(world.entity(box).instance(0).position, (Vec2{10, 10}));  // no slide after the hit
  EXPECT_EQ(world.entity(box).velocity(), (Vec2w{20 * kUnit, -20 * kUnit}));
}

// The world never changes a moving body's velocity without telling the rules: whether the slide
// met a line inside the frame or a rounded step ended touching it and the rest test stopped the
// body at the next frame's start, contact() is called. Random shapes, upright and turned, dropped
// and thrown onto floors and slopes at random gravities. (A body already at rest hears nothing.)
TEST(Rules, EveryStopIsAContact) {
  std::mt19937_64 rng(0x1a2d);
  using platon::testing::between;
  struct Counter : Rules {
    int contacts = 0;
    void contact(const Contact&, ContactResponse&) override { ++contacts; }
  };
  int stops = 0, changes = 0;
  for (int trial = 0; trial < 300; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    const int32_t rise = between(rng, -600, 600);
    part.line({-4000, -rise}, {4000, rise});
    part.line({-4000, -rise}, {-4000, 4000});
    part.line({4000, rise}, {4000, 4000});
    const Vec2w gravity{between(rng, -2000, 2000), -between(rng, 2000, 200000)};
    part.setGravity(gravity);
    part.initialize();
    Counter counter;
    world.setRules(&counter);
    const EntityId body =
        world.createEntity(platon::testing::randomConvex(rng, between(rng, 3, 60), platon::testing::Turn::MaybeTurned));
    world.insert(body, 1, {between(rng, -500, 500), 700 + between(rng, 0, 2000)}, 0);
    world.setVelocity(body, {between(rng, -20, 20) * kUnit, between(rng, -20, 20) * kUnit + between(rng, 0, 65535)});
    for (int frame = 0; frame < 400; ++frame) {
      const Vec2w before = world.entity(body).velocity();
      const int heard = counter.contacts;
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u);
      const Vec2w after = world.entity(body).velocity();
      if (before == Vec2w{} || after == before + gravity) continue;
      ++changes;
      stops += after == Vec2w{};
      ASSERT_GT(counter.contacts, heard) << "trial " << trial << " frame " << frame
                                         << ": the velocity changed and no contact was heard";
    }
  }
  EXPECT_GT(stops, 100);
  EXPECT_GT(changes, 1000);
}

// A rule that keeps the velocity mirrored across the line bounces a body for ever: no landing,
// however the rounding falls, ends in rest.
TEST(Rules, AnElasticBounceNeverComesToRest) {
  std::mt19937_64 rng(0xb0b);
  using platon::testing::between;
  struct Mirror : Rules {
    World* world = nullptr;
    void contact(const Contact& c, ContactResponse& r) override {
      const Vec2w v = world->entity(c.entity).velocity(), n = c.normal;
      const i128 vn = dot128(v, n), nn = dot128(n, n);
      if (vn < 0)
        world->setVelocity(
            c.entity, {static_cast<int64_t>(v.x - 2 * vn * n.x / nn), static_cast<int64_t>(v.y - 2 * vn * n.y / nn)});
      r.removeNormalVelocity = false;
    }
  };
  for (int trial = 0; trial < 60; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-100000, 0}, {100000, 0});
    part.setGravity({0, -between(rng, 3000, 100000)});
    part.initialize();
    Mirror mirror;
    mirror.world = &world;
    world.setRules(&mirror);
    const EntityId body = world.createEntity(Convex::box(between(rng, 2, 40), between(rng, 2, 40)));
    world.insert(body, 1, {0, 200 + between(rng, 0, 3000)}, 0);
    int stillFrames = 0;
    for (int frame = 0; frame < 3000; ++frame) {
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u);
      stillFrames = world.entity(body).velocity() == Vec2w{} ? stillFrames + 1 : 0;
      ASSERT_LT(stillFrames, 2) << "trial " << trial << " came to rest at frame " << frame;
    }
  }
}

TEST(Rules, AnErrorInACallbackLeavesTheWorldWholeAndIsRethrown) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 0}, {1000, 0});
  part.initialize();
  struct Throwing : Rules {
    void contact(const Contact&, ContactResponse&) override {
      throw std::runtime_error("script error at level.lua:12");
    }
  } throwing;
  world.setRules(&throwing);
  const EntityId box = world.createEntity(Convex::box(10, 10));
  const EntityId other = world.createEntity(Convex::box(10, 10));
  world.insert(box, 1, {0, 20}, 0);
  world.insert(other, 1, {100, 20}, 0);
  world.setVelocity(box, {0, -30 * kUnit});
  world.setVelocity(other, {0, 5 * kUnit});
  EXPECT_THROW(
      {
        try {
          world.solve();
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "script error at level.lua:12");
          throw;
        }
      },
      std::runtime_error);
  // The frame completed for everyone with default responses.
  EXPECT_EQ(world.entity(box).instance(0).position, (Vec2{0, 10}));
  EXPECT_EQ(world.entity(other).instance(0).position, (Vec2{100, 25}));
  EXPECT_EQ(world.countOverlaps(), 0u);
  world.setRules(nullptr);
  EXPECT_NO_THROW(world.solve());
}

TEST(Rules, StructuralChangesInsideCallbacksAreRefusedClearly) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 0}, {1000, 0});
  part.initialize();
  struct Meddler : Rules {
    World* world = nullptr;
    void contact(const Contact& c, ContactResponse&) override {
      world->setVelocity(c.entity, {0, 0});  // allowed
      world->destroyEntity(c.entity);        // not allowed
    }
  } meddler;
  meddler.world = &world;
  world.setRules(&meddler);
  const EntityId box = world.createEntity(Convex::box(10, 10));
  world.insert(box, 1, {0, 20}, 0);
  world.setVelocity(box, {0, -30 * kUnit});
  try {
    world.solve();
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("destroyEntity is not allowed inside a contact callback"), std::string::npos);
  }
  EXPECT_TRUE(world.valid(box));
}

TEST(Rotation, TurnsFreelyInOpenSpace) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, -500}, {1000, -500});
  part.initialize();
  const EntityId stick = world.createEntity(Convex::box(100, 5));
  world.insert(stick, 1, {0, 0}, 0);
  EXPECT_TRUE(world.rotate(stick, kQuarterTurn));
  const EntityView e = world.entity(stick);
  EXPECT_EQ(e.angle(), kQuarterTurn);
  const auto shape = e.instance(0).shape;
  int64_t maxY = 0;
  for (const Vec2 v : shape) maxY = std::max<int64_t>(maxY, v.y);
  EXPECT_EQ(maxY, 100);
}

TEST(Rotation, ATightCorridorStopsTheTurnAndReportsTouch) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 10}, {1000, 10});
  part.line({1000, -10}, {-1000, -10});
  part.initialize();
  Recorder rules;
  world.setRules(&rules);
  const EntityId stick = world.createEntity(Convex::box(100, 5));
  world.insert(stick, 1, {0, 0}, 0);
  EXPECT_FALSE(world.rotate(stick, kQuarterTurn));
  EXPECT_EQ(world.countOverlaps(), 0u);
  const EntityView e = world.entity(stick);
  EXPECT_LT(e.angle(), kQuarterTurn / 8);  // it got only a few degrees
  ASSERT_FALSE(rules.log.empty());
  EXPECT_EQ(rules.log.back().rfind("touch", 0), 0u);
}

TEST(Rotation, AngularVelocityInsideACorridorNeverOverlaps) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({-1000, 12}, {1000, 12});
  part.line({1000, -12}, {-1000, -12});
  part.initialize();
  const EntityId stick = world.createEntity(Convex::box(60, 6));
  world.insert(stick, 1, {0, 0}, 0);
  world.setAngularVelocity(stick, static_cast<int32_t>(kQuarterTurn / 30));
  world.setVelocity(stick, {3 * kUnit, 2 * kUnit});
  for (int i = 0; i < 300; ++i) {
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
}

// A body far larger than any level's (its far end 4 * 10^8 units from its origin) turning a quarter
// turn: a short line between the chord and the arc of two sub-steps that a cap of 4,096 sub-steps
// would have left 7 units apart still stops the turn, with a touchContact, for lines placed all
// along the arc.
TEST(Rotation, LargeBodiesMeetShortLinesAnywhereAlongTheirArc) {
  const int32_t reach = 400'000'000;
  const double kPi = 3.14159265358979323846;
  for (int k = 0; k < 12; ++k) {
    World world;
    MapPart& part = world.createMapPart(1);
    // A two-unit line across the arc at radius reach - 3 .. reach - 1, at an angle half-way between
    // two of the 4,096 sub-steps (where the old chords passed 7 units inside the arc).
    const double at = (97.5 + 330.0 * k) * (kPi / 2) / 4096;
    const auto point = [&](double r) {
      return Vec2{static_cast<int32_t>(std::lround(r * std::cos(at))),
                  static_cast<int32_t>(std::lround(r * std::sin(at)))};
    };
    part.line(point(reach - 3.0), point(reach - 1.0), 9);
    part.initialize();
    struct Touches : Rules {
      int count = 0;
      uint32_t tag = 0;
      void touchContact(const Contact& c) override { ++count, tag = c.line.tag; }
    } rules;
    world.setRules(&rules);
    const EntityId rod = world.createEntity(Convex::box(reach, 4));
    world.insert(rod, 1, {0, 0}, 0);
    EXPECT_FALSE(world.rotate(rod, kQuarterTurn)) << "line " << k << " at " << at << " rad";
    EXPECT_EQ(rules.count, 1);
    EXPECT_EQ(rules.tag, 9u);
    EXPECT_LT(world.entity(rod).angle() * (2 * kPi / 4294967296.0), at);
    EXPECT_EQ(world.countOverlaps(), 0u);
  }
}
