// Rules: pierceable lines and their events, solid contacts and their responses, errors thrown from
// callbacks, structural changes refused during solve.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "platon/physics/world.h"

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
